"""Improved grey wolf optimizer (I-GWO) with dimension learning-based hunting.

Nadimi-Shahraki, Taghian & Mirjalili, "An improved grey wolf optimizer for
solving engineering problems", Expert Systems with Applications 166, 113917
(2021), DOI 10.1016/j.eswa.2020.113917. Each iteration builds two candidates
per wolf:

- the GWO move (the paper restates GWO before Eq. 10):
  ``a = 2 - 2 t/T``, ``A = 2 a r1 - a``, ``C = 2 r2`` per coordinate,
  ``X_k = X_leader_k - A_k |C_k X_leader_k - X|`` for the leaders alpha, beta,
  delta (the three best wolves), ``X_GWO = (X_1 + X_2 + X_3) / 3``;
- Eq. 10: radius ``R_i = ||X_i - X_GWO_i||``;
- Eq. 11: neighbourhood ``N_i = {X_j : ||X_i - X_j|| <= R_i}`` (X_i included);
- Eq. 12: dimension learning ``X_DLH_i,d = X_i,d + rand (X_n,d - X_r,d)`` with a
  neighbour ``X_n`` drawn per dimension and one random wolf ``X_r`` per wolf;
- Eq. 13: the better of X_GWO and X_DLH replaces X_i only if it is strictly
  better (greedy selection), so the pack is its own memory.

Defaults: a from 2 to 0 (EOSMA paper, Table 3: the "convergence factor a
[2, 0]" row printed under PSO-GSA belongs to I-GWO, whose heading the table
extraction lost; PSOGSA has no such parameter). Out-of-range coordinates move
halfway between the wolf's position and the violated bound, as in the authors'
``boundConstraint``.

Evaluations per iteration: 2N (X_GWO and X_DLH of every wolf).

Deviations:
- alpha, beta and delta are the three best wolves of the current pack (the
  paper's wording). The authors' code keeps them in a cascade of ``if`` tests
  that does not shift alpha down to beta when a new alpha arrives.
- The random wolf ``X_r`` is drawn with replacement per wolf (the code uses
  one random permutation, which also makes the draws distinct across wolves).
- Constrained problems: comparisons are feasibility-first (see base.py).
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    greedy_memory,
    is_better,
    midpoint_repair,
    ranking_fitness,
)


def gwo_move(X, leaders, a: float, *, rng: np.random.Generator) -> np.ndarray:
    """GWO hunting (Mirjalili et al. 2014, Eqs. 3.1-3.7): mean of the
    leader-guided positions of every wolf; leaders each (n, d) or (d,); ``A``
    then ``C`` drawn per leader, each (n, d). Shared with MOGWO."""
    out = np.zeros_like(X)
    for leader in leaders:
        A = 2.0 * a * rng.random(X.shape) - a  # Eq. 3.3
        C = 2.0 * rng.random(X.shape)  # Eq. 3.4
        out += leader - A * np.abs(C * leader - X)  # Eqs. 3.1, 3.5-3.6
    return out / len(leaders)  # Eq. 3.7


def dimension_learning(X, X_gwo, *, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 10-12: dimension learning-based hunting candidates of every wolf."""
    n, d = X.shape
    radius = np.linalg.norm(X - X_gwo, axis=1)  # Eq. 10
    dist = np.linalg.norm(X[:, None, :] - X[None, :, :], axis=2)
    neighbour = dist <= radius[:, None]  # Eq. 11 (the wolf itself always qualifies)
    counts = neighbour.sum(axis=1)
    order = np.argsort(~neighbour, axis=1, kind="stable")  # neighbours first
    pick = (rng.random((n, d)) * counts[:, None]).astype(int)
    Xn = X[order[np.arange(n)[:, None], pick], np.arange(d)]
    Xr = X[rng.integers(n, size=n)]
    return X + rng.random((n, d)) * (Xn - Xr)  # Eq. 12


class IGWO(ArrayAlgorithm):
    """Improved grey wolf optimizer (Nadimi-Shahraki et al. 2021) with array state.

    ``X``/``F`` is the pack (its own greedy memory).

    Args:
        pop_size: Number of wolves N (at least 3 leaders are needed).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 3

    def __init__(self, *, pop_size: int = 50, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)

    def _evals_per_iteration(self) -> float:
        return 2.0 * self.pop_size

    def _generation(self) -> Step:
        rng = self.random_state
        a = 2.0 - 2.0 * min(self.t / self.max_iter, 1.0)
        leaders = self.X[np.argsort(ranking_fitness(self.F, self.CV), kind="stable")[:3]]
        X_gwo = midpoint_repair(gwo_move(self.X, leaders, a, rng=rng), self.X, self.xl, self.xu)
        X_dlh = midpoint_repair(dimension_learning(self.X, X_gwo, rng=rng), self.X,
                                self.xl, self.xu)
        n = len(self.X)
        F2, CV2 = yield np.concatenate([X_gwo, X_dlh])
        F_gwo, F_dlh = F2[:n], F2[n:]
        CV_gwo, CV_dlh = (None, None) if CV2 is None else (CV2[:n], CV2[n:])
        gwo = is_better(F_gwo, CV_gwo, F_dlh, CV_dlh)  # Eq. 13, candidate choice
        X = np.where(gwo[:, None], X_gwo, X_dlh)
        F = np.where(gwo, F_gwo, F_dlh)
        CV = None if CV_gwo is None else np.where(gwo, CV_gwo, CV_dlh)
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
