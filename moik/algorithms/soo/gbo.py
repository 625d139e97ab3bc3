"""Gradient-based optimizer (GBO).

Ahmadianfar, Bozorg-Haddad & Chu, "Gradient-based optimizer: A new
metaheuristic optimization algorithm", Information Sciences 540, 131-159
(2020), DOI 10.1016/j.ins.2020.06.037. Equation numbers as in the paper (and
in the comments of the authors' reference code):

- Eq. 14: ``beta = 0.2 + (1.2 - 0.2) (1 - (m/M)^3)^2``,
  ``alpha = |beta sin(3 pi/2 + sin(3 pi/2 beta))|``; ``rho = alpha (2 rand - 1)``;
- Eq. 16: ``dx = rand(1:D) |step|``, ``step = ((x_best - x_r1) + delta)/2``,
  ``delta = 2 rand |x_m - x_n|`` with ``x_m`` the mean of four random members;
- Eqs. 15, 21-23: the gradient search rule GSR, first with
  ``x_best - x_worst + eps`` in the denominator, then with ``yp - yq + eps``;
- Eq. 18: the direction of movement ``DM = rand rho2 (x_best - x_n)``;
- Eq. 25: ``X1 = x_n - GSR + DM``; Eq. 26: ``X2 = x_best - GSR + rand rho2 (x_r1 - x_r2)``;
- Eq. 27: ``x_new = ra (rb X1 + (1 - rb) X2) + (1 - ra) X3``,
  ``X3 = x_n - rho1 (X2 - X1)`` per coordinate;
- Eq. 28: the local escaping operator (LEO), applied with probability pr:
  ``x_LEO = {x_new or x_best} + f1 (u1 x_best - u2 x_k)
  + f2 rho1 (u3 (X2 - X1) + u2 (x_r1 - x_r2))/2``,
  ``x_k`` a random member or a random point in the box (50/50).

Defaults (EOSMA paper, Table 3): pr=0.5; beta_min=0.2, beta_max=1.2 and
``eps = 0.005 rand`` as in the paper. Evaluations: N per iteration (one
trial per agent; a trial replaces its agent only if better).

Deviations and readings:
- All agents are updated at once from the same population; the authors' code
  updates them in turn (with ``x_best`` refreshed after each).
- ``r1..r4`` are mutually different and different from ``n`` (the paper);
  the authors' code draws them with replacement. This needs N >= 5.
- Eq. 25 uses ``x_best - x_n`` in DM (the paper); the authors' code uses
  ``x_best - x_r1``. The intermediate point inside the GSR follows the code.
- LEO chooses between ``x_new`` and ``x_best`` with a fresh ``rand < 0.5``
  (the paper); the code reuses ``u1 < 0.5``.
- ``x_worst`` is the worst member of the current population (the paper); the
  code keeps the initial worst.
- Coordinates outside the box are clipped to the bounds (authors' code).
- Constrained problems: feasibility-first comparisons (see base.py).
"""

from __future__ import annotations

import math

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    best_index,
    clip_to_bounds,
    greedy_memory,
    ranking_fitness,
    uniform_population,
)
from moik.algorithms.soo.de import distinct_partners


def gbo_alpha(t: int, T: int) -> float:
    """Eq. 14: the schedule ``alpha`` (t/T capped at 1)."""
    s = min(t / T, 1.0)
    beta = 0.2 + (1.2 - 0.2) * (1.0 - s**3) ** 2
    return abs(beta * math.sin(3.0 * math.pi / 2.0 + math.sin(3.0 * math.pi / 2.0 * beta)))


def gradient_search_rule(X, Xr1, Xm, best, worst, base, DM, rho1, eps, *,
                         rng: np.random.Generator) -> np.ndarray:
    """Eqs. 15-16, 21-23: the GSR term of every agent (per-agent scalars as (n, 1))."""
    n, d = X.shape
    delta = 2.0 * rng.random((n, 1)) * np.abs(Xm - X)  # Eq. 16
    dx = rng.random((n, d)) * np.abs(((best - Xr1) + delta) / 2.0)
    gsr = rng.standard_normal((n, 1)) * rho1 * (2.0 * dx * X) / (best - worst + eps)  # Eq. 15
    xs = base - gsr + DM  # Eq. 21
    mid = 0.5 * (xs + X)
    yp = rng.random((n, 1)) * (mid + rng.random((n, 1)) * dx)  # Eq. 22
    yq = rng.random((n, 1)) * (mid - rng.random((n, 1)) * dx)
    return rng.standard_normal((n, 1)) * rho1 * (2.0 * dx * X) / (yp - yq + eps)  # Eq. 23


def gbo_update(X, best, worst, alpha: float, *, pr: float, xl: np.ndarray, xu: np.ndarray,
               rng: np.random.Generator) -> np.ndarray:
    """Eqs. 14-28: GBO's trial for every agent (row of ``X``), not yet bounded."""
    n, d = X.shape
    R = distinct_partners(n, 4, rng=rng)
    Xr1, Xr2 = X[R[:, 0]], X[R[:, 1]]
    Xm = X[R].mean(axis=1)
    rho = alpha * (2.0 * rng.random((n, 1)) - 1.0)
    rho1 = alpha * (2.0 * rng.random((n, 1)) - 1.0)
    eps = 5e-3 * rng.random((n, 1))
    gsr = gradient_search_rule(X, Xr1, Xm, best, worst, X, rng.random((n, 1)) * rho * (best - Xr1),
                               rho1, eps, rng=rng)
    X1 = X - gsr + rng.random((n, 1)) * rho * (best - X)  # Eqs. 18, 25
    DM2 = rng.random((n, 1)) * rho * (Xr1 - Xr2)
    gsr = gradient_search_rule(X, Xr1, Xm, best, worst, best, DM2, rho1, eps, rng=rng)
    X2 = best - gsr + rng.random((n, 1)) * rho * (Xr1 - Xr2)  # Eq. 26
    X3 = X - alpha * (2.0 * rng.random((n, d)) - 1.0) * (X2 - X1)
    ra, rb = rng.random((n, d)), rng.random((n, d))
    X_new = ra * (rb * X1 + (1.0 - rb) * X2) + (1.0 - ra) * X3  # Eq. 27
    # Eq. 28: local escaping operator
    leo = (rng.random(n) < pr)[:, None]
    f1, f2 = rng.uniform(-1.0, 1.0, (n, 1)), rng.uniform(-1.0, 1.0, (n, 1))
    rho_l = alpha * (2.0 * rng.random((n, 1)) - 1.0)
    L1 = rng.random((n, 1)) < 0.5
    u1 = np.where(L1, 2.0 * rng.random((n, 1)), 1.0)
    u2 = np.where(L1, rng.random((n, 1)), 1.0)
    u3 = np.where(L1, rng.random((n, 1)), 1.0)
    L2 = rng.random((n, 1)) < 0.5
    Xk = np.where(L2, X[rng.integers(n, size=n)], uniform_population(n, xl, xu, rng=rng))
    start = np.where(rng.random((n, 1)) < 0.5, X_new, best)
    X_leo = start + f1 * (u1 * best - u2 * Xk) + f2 * rho_l * (u3 * (X2 - X1)
                                                                 + u2 * (Xr1 - Xr2)) / 2.0
    return np.where(leo, X_leo, X_new)


class GBO(ArrayAlgorithm):
    """Gradient-based optimizer (Ahmadianfar et al. 2020) with array state.

    ``X``/``F`` is the population (each agent keeps its best, greedy).

    Args:
        pop_size: Population size N >= 5.
        pr: Probability of the local escaping operator in [0, 1] (Table 3: 0.5).
        max_iter: Schedule length M (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 5

    def __init__(self, *, pop_size: int = 100, pr: float = 0.5, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.pr = interval("pr", pr, 0.0, 1.0)

    def _generation(self) -> Step:
        best = self.X[best_index(self.F, self.CV)]
        worst = self.X[np.argmax(ranking_fitness(self.F, self.CV))]
        X = gbo_update(self.X, best, worst, gbo_alpha(self.t, self.max_iter), pr=self.pr,
                       xl=self.xl, xu=self.xu, rng=self.random_state)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
