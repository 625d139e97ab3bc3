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
- Eqs. 4-5: ``W = 1 +/- r log10((bF - S_i)/(bF - wF - eps) + 1)``, "+" for the
  better half of the sorted population (``eps`` keeps the denominator off zero;
  see the deviations for its sign).

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
- The authors' code divides by ``bestFitness - worstFitness + eps``. For
  minimisation ``bF - wF <= 0``, so ``+ eps`` shrinks the denominator's magnitude:
  it is 0 when ``wF - bF = eps`` (``log10`` of ``-inf``) and positive below (the
  argument drops under 0, ``log10`` gives NaN). Here ``eps`` is subtracted, so
  ``|bF - wF - eps| >= eps`` and the argument stays in ``[1, 2]``; when
  ``bF == wF`` both give ``W = 1``.
- Eq. 3's ``T``: the paper's pseudo-code and the authors' code evaluate at the top
  of ``while t <= Max_iter`` (``t = 1`` evaluates the initial population), so the
  update made with ``t = Max_iter`` is never evaluated and their ``Max_iter``
  counts the initial evaluation. Here T counts update iterations, so Eq. 3 uses
  ``t / (T + 1)``: the last evaluated update has ``b = 1/(T + 1) > 0``, as in the
  code (``t / T = 1`` would give ``vb = vc = 0`` and send every ``vc X``
  coordinate to exactly 0, an artificial optimum on origin-centred problems).
- Constrained problems: the fitness S is the feasibility-first ranking value of
  base.ranking_fitness (Deb's rules).

Compiled: the weights (:func:`weight_arguments`, :func:`weights_into`, shared with
EOSMA) and the Eq. 1 position update (per coordinate :func:`sma_coordinate`, which
EOSMA's update inlines too). The random numbers are drawn with numpy's Generator
before the kernels, and ``log10`` and ``tanh`` are numpy's: numpy's vectorised
versions and the C library's (which numba calls) differ in the last bit for some
inputs, and numpy's are the ones the recorded results were computed with.
"""

from __future__ import annotations

import math

import numpy as np

from moik._jit import jit, kernel_array
from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    ieee_divide,
    ranking_fitness,
    stable_order,
    uniform_population,
)

EPS = np.finfo(float).eps


@jit(inline=True)
def weight_arguments(S, order, arg):
    """Eq. 5 and the argument of Eq. 4's log10, per rank, into ``order`` and ``arg``.

    ``order`` is numpy's stable ranking of ``S``; ``arg[i] = (bF - S_(i)) / (bF - wF -
    eps) + 1`` for the i-th best fitness ``S_(i)``, in ``[1, 2]`` (``- eps``: the
    denominator is at most ``-eps``, module doc).
    """
    stable_order(S, order)
    bF, wF = S[order[0]], S[order[-1]]
    den = bF - wF - EPS
    for i in range(S.size):
        arg[i] = ieee_divide(bF - S[order[i]], den) + 1.0


@jit(inline=True)
def weight_sign(rank: int, n: int) -> float:
    """Eq. 4's sign: "+" for the better half of the sorted population."""
    return 1.0 if rank + 1 <= n / 2 else -1.0


@jit(inline=True)
def weights_into(order, log, R, W):
    """Eq. 4: ``W[order[i]] = 1 +/- log[i] R[i]`` (``R`` drawn per rank), into ``W``."""
    n, d = R.shape
    for i in range(n):
        sl = weight_sign(i, n) * log[i]
        for j in range(d):
            W[order[i], j] = 1.0 + sl * R[i, j]
    return W


def sma_weights(S: np.ndarray, d: int, *, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 4-5: the fitness weight W (n, d) of each agent from its fitness S (n,).

    Draws ``r`` (n, d) with ``rng`` after ranking.
    """
    S = kernel_array(S)
    n = S.size
    order, arg = np.empty(n, np.int64), np.empty(n)
    weight_arguments(S, order, arg)
    return weights_into(order, np.log10(arg), kernel_array(rng.random((n, d))),
                        np.empty((n, d)))


def sma_schedule(t: int, T: int) -> tuple[float, float]:
    """Eq. 3: ``a = atanh(1 - t/T)`` and ``b = 1 - t/T`` (t/T capped at 1)."""
    s = min(t / T, 1.0)
    return math.atanh(1.0 - s), 1.0 - s


@jit(inline=True)
def sma_coordinate(x_b: float, vb: float, w: float, x_a: float, x_bb: float) -> float:
    """Eq. 1's approach move for one coordinate: ``X_b + vb (W X_A - X_B)``."""
    return x_b + vb * (w * x_a - x_bb)


@jit
def sma_rows(X, W, x_best, p, vb, vc, r, IA, IB, out):
    """Eq. 1 (without the restarts) on every row from its drawn numbers, into ``out``.
    ``x_best`` is (1, d), or (n, d) with one food source per agent (MOSMA)."""
    n, d = X.shape
    for i in range(n):
        g = i if x_best.shape[0] == n else 0
        for j in range(d):
            if r[i, j] < p[i]:
                out[i, j] = sma_coordinate(x_best[g, j], vb[i, j], W[i, j], X[IA[i, j], j],
                                           X[IB[i, j], j])
            else:
                out[i, j] = vc[i, j] * X[i, j]
    return out


def sma_update(X, W, x_best, S, f_best: float, a: float, b: float, *, z: float,
               xl: np.ndarray, xu: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 1-3: SMA's position update of every row of ``X`` (not yet bounded).

    Draws ``vb``, ``vc``, ``r``, the indices of ``X_A`` and ``X_B`` (all (n, d)), the
    restart test (n,) and the restarted points, in that order.
    """
    X = kernel_array(X)
    n, d = X.shape
    p = np.tanh(np.abs(S - f_best))  # Eq. 2
    vb = kernel_array(rng.uniform(-a, a, (n, d)))  # Eq. 3
    vc = kernel_array(rng.uniform(-b, b, (n, d)))
    r = kernel_array(rng.random((n, d)))
    IA = np.asarray(rng.integers(n, size=(n, d)), dtype=np.int64)
    IB = np.asarray(rng.integers(n, size=(n, d)), dtype=np.int64)
    x_best = kernel_array(x_best).reshape(-1, d)
    X_new = sma_rows(X, kernel_array(W), x_best, kernel_array(p), vb, vc, r, IA, IB,
                     np.empty((n, d)))  # Eq. 1
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
        a, b = sma_schedule(self.t, self.max_iter + 1)  # the code's Max_iter: T + 1 (module doc)
        W = sma_weights(S, self.problem.n_var, rng=rng)
        X = sma_update(self.X, W, self.best_x, S, DF, a, b, z=self.z, xl=self.xl, xu=self.xu,
                       rng=rng)
        X = clip_to_bounds(X, self.xl, self.xu)
        self.X = X
        self.F, self.CV = yield X
