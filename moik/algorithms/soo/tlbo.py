"""Teaching-learning-based optimization (TLBO).

Rao, Savsani & Vakharia, "Teaching-learning-based optimization: A novel method
for constrained mechanical design optimization problems", Computer-Aided
Design 43, 303-315 (2011), DOI 10.1016/j.cad.2010.12.015. The two phases are
cited by the paper's names and symbols (labels T1-T3, L1-L2 below are ours: the
paper's text was not at hand to check its equation numbers):

- T1 (teacher phase): ``Difference_Mean_i = r_i (M_new - T_F M_i)``, with
  ``M_new`` the best learner (the teacher), ``M_i`` the mean of the class;
- T2: the teaching factor ``T_F = round(1 + rand(0, 1))`` in {1, 2};
- T3: ``X_new = X_old + Difference_Mean_i``, accepted if it gives a better
  function value;
- L1-L2 (learner phase): for a random partner ``X_j != X_i``,
  ``X_new = X_i + r (X_i - X_j)`` if ``f(X_i) < f(X_j)``, else
  ``X_new = X_i + r (X_j - X_i)``; accepted if better.

Defaults (EOSMA paper, Table 3): T_F drawn from {1, 2}. TLBO has no other
parameter. Evaluations: **2N per iteration** (N in the teacher phase, N in the
learner phase), so at an equal evaluation budget it runs half as many
iterations as an N-per-iteration algorithm; ``max_iter`` inferred from an
``n_eval`` termination accounts for it.

Deviations and readings:
- ``r`` is drawn per coordinate and ``T_F`` per learner (the paper writes
  ``r_i`` and ``T_F`` per iteration ``i`` without fixing their shape).
- Each phase updates all learners at once from the same class (the learner
  phase uses the class after the teacher phase, as in the paper).
- Coordinates outside the box are clipped to the bounds (the paper's
  unconstrained problems have none; its constrained ones use penalties).
- Constrained problems: feasibility-first comparisons (see base.py) both for
  acceptance and for the learner-phase "which of the two is better".
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    best_index,
    clip_to_bounds,
    greedy_memory,
    is_better,
)


def teacher_phase(X, teacher, *, rng: np.random.Generator) -> np.ndarray:
    """T1-T3: every learner moves by ``r (teacher - T_F mean)``, ``T_F`` in {1, 2}."""
    n, d = X.shape
    TF = rng.integers(1, 3, size=n)[:, None]  # T2: round(1 + rand)
    r = rng.random((n, d))
    return X + r * (teacher - TF * X.mean(axis=0))


def learner_phase(X, better_than_partner: np.ndarray, partner: np.ndarray, *,
                  rng: np.random.Generator) -> np.ndarray:
    """L1-L2: move away from a worse partner, toward a better (or equal) one.

    Args:
        X: Class after the teacher phase (n, d).
        better_than_partner: Boolean (n,), ``f(X_i) < f(X_j)``.
        partner: Index ``j`` of each learner's partner (n,).
        rng: Random generator.
    """
    r = rng.random(X.shape)
    step = np.where(better_than_partner[:, None], X - X[partner], X[partner] - X)
    return X + r * step


def random_partners(n: int, *, rng: np.random.Generator) -> np.ndarray:
    """A uniformly random index ``j != i`` for every ``i`` in ``range(n)``."""
    return (np.arange(n) + rng.integers(1, n, size=n)) % n


class TLBO(ArrayAlgorithm):
    """Teaching-learning-based optimization (Rao et al. 2011) with array state.

    ``X``/``F`` is the class (each learner keeps its best, greedy acceptance).
    Two evaluated batches of N per iteration.

    Args:
        pop_size: Class size N >= 2.
        X0: Optional initial points.
        max_iter: Schedule length (TLBO has no schedule; kept for a uniform API).
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, X0: np.ndarray | None = None,
                 max_iter: int | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)

    def _evals_per_iteration(self) -> float:
        return 2.0 * self.pop_size

    def _generation(self) -> Step:
        rng = self.random_state
        teacher = self.X[best_index(self.F, self.CV)]
        X = clip_to_bounds(teacher_phase(self.X, teacher, rng=rng), self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
        j = random_partners(len(self.X), rng=rng)
        cv_j = None if self.CV is None else self.CV[j]
        better = is_better(self.F, self.CV, self.F[j], cv_j)
        X = clip_to_bounds(learner_phase(self.X, better, j, rng=rng), self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
