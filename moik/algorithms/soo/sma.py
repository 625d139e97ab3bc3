"""Slime mould algorithm (SMA).

Li, Chen, Wang, Heidari & Mirjalili, "Slime mould algorithm: A new method for
stochastic optimization", Future Generation Computer Systems 111, 300-323
(2020), DOI 10.1016/j.future.2020.03.055. Equation numbers below are those of
the EOSMA paper (Yin et al., Sci. Rep. 12, 9421 (2022),
DOI 10.1038/s41598-022-13516-3), which restates SMA as Eqs. 1-5:

- Eq. 1: with probability z a random restart ``rand (UB - LB) + LB``; else per
  coordinate, if ``r < p``: ``X_b + vb (W X_A - X_B)``, otherwise ``vc X``;
- Eq. 2: ``p = tanh|S_i - DF|`` (DF: best fitness so far);
- Eq. 3: ``vb ~ U(-a, a)``, ``a = atanh(1 - t/T)``; ``vc ~ U(-b, b)``,
  ``b = 1 - t/T``;
- Eqs. 4-5: ``W = 1 +/- r log10((bF - S_i)/(bF - wF) + 1)``, "+" for the better
  half of the sorted population (``eps`` added to the denominator, as in the
  authors' code).

Defaults (EOSMA paper, Table 3): z=0.03. Evaluations: N per iteration; no
greedy selection (the original has none). Coordinates are clipped to the bounds,
as in the authors' code.

Deviations:
- The authors' code updates agents one after another, so ``X_A``/``X_B`` may
  already hold this iteration's positions; here all agents are updated from
  the same population at once (vectorized, as most ports do).
- ``X_b`` is the best position so far, as in the authors' code (the paper's
  text says "best of the current iteration").
- The code draws one scalar ``rand`` for the restart of a whole row; here the
  restart is uniform per coordinate (Eq. 1 read as a vector).
- Eq. 4 prints ``log``; the authors' code and this port use ``log10``.
- Constrained problems: the fitness S is the feasibility-first ranking value of
  base.ranking_fitness (Deb's rules).
"""

from __future__ import annotations

import math

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    ranking_fitness,
    uniform_population,
)

EPS = np.finfo(float).eps


def sma_weights(S: np.ndarray, d: int, *, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 4-5: the fitness weight W (n, d) of each agent from its fitness S (n,)."""
    n = len(S)
    order = np.argsort(S, kind="stable")  # Eq. 5
    S_sorted = S[order]
    bF, wF = S_sorted[0], S_sorted[-1]
    log = np.log10((bF - S_sorted) / (bF - wF - EPS) + 1.0)
    sign = np.where(np.arange(1, n + 1) <= n / 2, 1.0, -1.0)
    W = np.empty((n, d))
    W[order] = 1.0 + (sign * log)[:, None] * rng.random((n, d))  # Eq. 4
    return W


def sma_schedule(t: int, T: int) -> tuple[float, float]:
    """Eq. 3: ``a = atanh(1 - t/T)`` and ``b = 1 - t/T`` (t/T capped at 1)."""
    s = min(t / T, 1.0)
    return math.atanh(1.0 - s), 1.0 - s


def sma_update(X, W, x_best, S, f_best: float, a: float, b: float, *, z: float,
               xl: np.ndarray, xu: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 1-3: SMA's position update of every row of ``X`` (not yet bounded)."""
    n, d = X.shape
    p = np.tanh(np.abs(S - f_best))  # Eq. 2
    vb = rng.uniform(-a, a, (n, d))  # Eq. 3
    vc = rng.uniform(-b, b, (n, d))
    r = rng.random((n, d))
    cols = np.arange(d)
    XA = X[rng.integers(n, size=(n, d)), cols]
    XB = X[rng.integers(n, size=(n, d)), cols]
    X_new = np.where(r < p[:, None], x_best + vb * (W * XA - XB), vc * X)  # Eq. 1
    restart = rng.random(n) < z
    k = int(restart.sum())
    if k:
        X_new[restart] = uniform_population(k, xl, xu, rng=rng)
    return X_new


class SMA(ArrayAlgorithm):
    """Slime mould algorithm (Li et al. 2020) with array state.

    ``X``/``F`` is the current population (no memory in the original).

    Args:
        pop_size: Number of agents N.
        z: Random-restart probability in [0, 1] (paper: 0.03).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, z: float = 0.03, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.z = interval("z", z, 0.0, 1.0)

    def _generation(self) -> Step:
        rng = self.random_state
        S = ranking_fitness(self.F, self.CV)
        feasible_best = self.best_cv is None or self.best_cv <= 0.0
        DF = self.best_f if feasible_best else float(S.min())
        a, b = sma_schedule(self.t, self.max_iter)
        W = sma_weights(S, self.problem.n_var, rng=rng)
        X = sma_update(self.X, W, self.best_x, S, DF, a, b, z=self.z, xl=self.xl, xu=self.xu,
                       rng=rng)
        X = clip_to_bounds(X, self.xl, self.xu)
        self.X = X
        self.F, self.CV = yield X
