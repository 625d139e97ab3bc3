"""Salp swarm algorithm (SSA).

Mirjalili, Gandomi, Mirjalili, Saremi, Faris & Mirjalili, "Salp Swarm
Algorithm: A bio-inspired optimizer for engineering design problems", Advances
in Engineering Software 114, 163-191 (2017), DOI 10.1016/j.advengsoft.2017.07.002:

- Eq. 3.1 (leader): ``x = F + c1 ((ub - lb) c2 + lb)`` if ``c3 >= 0.5`` else
  ``F - c1 ((ub - lb) c2 + lb)``, F the food source (best so far), c2, c3
  uniform in [0, 1] per coordinate (the paper prints ``c3 >= 0``; its code
  tests 0.5);
- Eq. 3.2: ``c1 = 2 exp(-(4 l / L)^2)``, l the iteration, L the maximum;
- Eq. 3.4: follower ``x_i = (x_i + x_{i-1}) / 2``, using the predecessor's new
  position (the chain is updated in order).

Defaults: no parameters besides N and L; ``n_leaders = 1`` (the paper's
single leader; the authors' code makes the first half of the swarm leaders,
``n_leaders = pop_size // 2``). Evaluations: N per iteration. Coordinates are
clipped to the bounds (code). No greedy memory; the food source is the best so
far. Constrained problems: the food source is the feasibility-first best
(Deb's rules, see base.py).
"""

from __future__ import annotations

import math

import numpy as np

from moik._validate import integer
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds


def ssa_c1(t: int, T: int) -> float:
    """Eq. 3.2 as the authors' code counts: l = t + 1 of L = T + 1.

    SSA.m counts the initial evaluation as iteration 1 (its first update uses
    l = 2, its last l = L); here T counts the update iterations, so L = T + 1.
    """
    return 2.0 * math.exp(-((4.0 * (t + 1) / (T + 1)) ** 2))


def salp_update(X, food, c1: float, n_leaders: int, xl, xu, *,
                rng: np.random.Generator) -> np.ndarray:
    """Eqs. 3.1 and 3.4: leaders around the food, each follower halfway to its predecessor."""
    new = X.copy()
    k = n_leaders
    c2 = rng.random((k, X.shape[1]))
    c3 = rng.random((k, X.shape[1]))
    step = c1 * ((xu - xl) * c2 + xl)
    new[:k] = np.where(c3 >= 0.5, food + step, food - step)  # Eq. 3.1
    for i in range(k, len(X)):
        new[i] = (X[i] + new[i - 1]) / 2.0  # Eq. 3.4
    return new


class SSA(ArrayAlgorithm):
    """Salp swarm algorithm with array state (``X``/``F`` is the current chain).

    Args:
        pop_size: Number of salps N.
        n_leaders: Leading salps, 1 <= n_leaders < N (paper: 1; code: N // 2).
        max_iter: Schedule length L (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, n_leaders: int = 1,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.n_leaders = integer("n_leaders", n_leaders, minimum=1, maximum=self.pop_size - 1)

    def _generation(self) -> Step:
        X = salp_update(self.X, self.best_x, ssa_c1(self.t, self.max_iter), self.n_leaders,
                        self.xl, self.xu, rng=self.random_state)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
