"""EOSMA's compiled kernels: the Eq. 15 and Eq. 16 operators and one generation.

Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3 (see
:mod:`moik.algorithms.soo.eosma` for the equations and the readings). The operators take
their random numbers as arrays (:func:`eosma_rows`, :func:`difference_rows`); the
generation kernels used by the ``EOSMA`` class draw them on the algorithm's numpy
``Generator`` inside the kernel (:func:`generation_draws`, through a
:class:`~moik.algorithms.generator_handle.GeneratorHandle`; numba's Generator methods
give the same stream as numpy's), rank, build the candidates (:func:`generation_candidates`) and
remember an evaluated batch (:func:`remember`). The per-coordinate rules are EO's, SMA's
and the shared mechanics', inlined (one implementation each).

Bit identity with the numpy operators: every value is computed with the same IEEE
operations in the same order; the Eq. 4 ``log10`` and the Eq. 8 ``exp`` are numpy's,
applied by the caller between :func:`generation_draws` and :func:`generation_candidates`
(numpy's vectorised ``log10``/``exp`` and the C library's, which numba calls, differ in
the last bit for some inputs).
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit
from moik.algorithms.mechanics import greedy_step, midpoint_coordinate, ranking_into
from moik.algorithms.soo.eo import (
    eo_coordinate,
    generation_control,
    pool_update,
    pool_with_mean,
)
from moik.algorithms.soo.sma import sma_coordinate, weight_arguments, weights_into

POOL_SIZE = 4  # Eq. 7


@jit
def eosma_rows(P, g_best, pool, W, lam, E, r, idx, r1, r2, vb, A, B, u, z, a1, GP, V, out):
    """Eq. 15 on every agent from its drawn numbers, into ``out``: the EO operator on
    ``pBest`` (Eqs. 6, 8, 9, ``E = exp(-lam t1)``) where ``u < z``, else the SMA operator.
    ``g_best`` is (1, d), or (n, d) with one leader per agent (MOEOSMA)."""
    n, d = P.shape
    for i in range(n):
        g = i if g_best.shape[0] == n else 0
        if u[i] < z:
            gcp = generation_control(r1[i], r2[i], GP)
            for j in range(d):
                out[i, j] = eo_coordinate(P[i, j], pool[idx[i], j], lam[i, j], E[i, j],
                                          r[i, j], gcp, a1, V)
        else:
            for j in range(d):
                out[i, j] = sma_coordinate(g_best[g, j], vb[i, j], W[i, j], P[A[i], j],
                                           P[B[i], j])
    return out


@jit(inline=True)
def difference_coordinate(p1: float, p2: float, p3: float, sf: float) -> float:
    """Eq. 16 for one coordinate: ``pBest_R1 + SF (pBest_R2 - pBest_R3)``."""
    return p1 + sf * (p2 - p3)


@jit
def difference_rows(P, R, SF, out):
    """Eq. 16 on every agent from its drawn indices ``R`` (3, n) and factors ``SF`` (n,)."""
    n, d = out.shape
    for i in range(n):
        for j in range(d):
            out[i, j] = difference_coordinate(P[R[0, i], j], P[R[1, i], j], P[R[2, i], j], SF[i])
    return out


# One generation of the EOSMA class. Its scratch: cells (5, n, d) holds r of Eq. 4 (per
# rank), lam, exp(-lam t1), r of Eq. 8 and vb; rows (5, n) the Eq. 4 log10 (per rank), r1,
# r2, the operator test and SF; picks (7, n) the ranking, the pool index, A, B, R1..R3.

@jit(inline=True)
def fill_random(rng, A):
    """``A`` (2-D) filled with ``rng.random()`` in C order, as ``rng.random(A.shape)``."""
    for i in range(A.shape[0]):
        for j in range(A.shape[1]):
            A[i, j] = rng.random()


@jit(inline=True)
def fill_integers(rng, high, A):
    """``A`` (2-D) filled as ``rng.integers(high, size=A.shape)``."""
    values = rng.integers(0, high, size=A.size)
    for i in range(A.shape[0]):
        for j in range(A.shape[1]):
            A[i, j] = values[i * A.shape[1] + j]


@jit
def generation_draws(handle, PM, n_pool, t1, a, q, cells, rows, picks):
    """Every random number of one generation, in Algorithm 1's order; the mutation test.

    Ranks the personal bests by ``PM = (F, CV)`` (Eq. 5) and fills the Eq. 4 log10
    argument into ``rows[0]`` and ``-lam t1`` into ``cells[2]`` (the caller applies numpy's
    log10 and exp). Draws: r (n, d) of Eq. 4; lam, r (n, d), the pool index, r1, r2 (n,)
    of Eqs. 8-9; vb (n, d); A, B; the operator test (n,); the mutation test of line 22
    and, when it passes, R1..R3 and SF of Eq. 16, all on ``handle.rng`` (a
    :class:`~moik.algorithms.generator_handle.GeneratorHandle`). Returns whether the
    mutation runs.
    """
    rng = handle.rng
    n, d = cells.shape[1], cells.shape[2]
    weight_arguments(ranking_into(PM[0], PM[1], np.empty(n)), picks[0], rows[0])
    fill_random(rng, cells[0])
    fill_random(rng, cells[1])
    for i in range(n):
        for j in range(d):
            cells[2, i, j] = -cells[1, i, j] * t1  # numpy's exp follows in the caller
    fill_random(rng, cells[3])
    fill_integers(rng, n_pool, picks[1:2])
    fill_random(rng, rows[1:3])
    for i in range(n):
        for j in range(d):
            cells[4, i, j] = rng.uniform(-a, a)
    fill_integers(rng, n, picks[2:4])
    for i in range(n):
        rows[3, i] = rng.random()
    mutate = rng.random() < q
    if mutate:
        fill_integers(rng, n, picks[4:7])
        for i in range(n):
            rows[4, i] = rng.uniform(0.3, 0.6)
    return mutate


@jit
def repaired(X, P, bounds):
    """Eq. 17 in place against the personal bests ``P``; ``bounds`` is ``(xl, xu)`` (2, d)."""
    n, d = X.shape
    for i in range(n):
        for j in range(d):
            X[i, j] = midpoint_coordinate(X[i, j], P[i, j], bounds[0, j], bounds[1, j])
    return X


@jit
def generation_candidates(P, g_best, pool, cells, rows, picks, z, a1, GP, V, bounds):
    """Eqs. 4, 15 and 17: the repaired candidates of a generation from its drawn numbers."""
    n, d = P.shape
    W = weights_into(picks[0], rows[0], cells[0], np.empty((n, d)))
    X = eosma_rows(P, g_best, pool, W, cells[1], cells[2], cells[3], picks[1], rows[1],
                   rows[2], cells[4], picks[2], picks[3], rows[3], z, a1, GP, V,
                   np.empty((n, d)))
    return repaired(X, P, bounds)


@jit
def first_pool(X, F, CV):
    """Eq. 7 on the initial population: the pool with its mean as a last row, its F and CV
    (2, k). (Called with the same constant arguments as :func:`remember`, so that
    ``pool_update`` compiles once.)"""
    QX, QF, QCV = pool_update(np.empty((0, X.shape[1])), np.empty(0), np.empty(0), X, F, CV,
                              POOL_SIZE, True)
    return pool_with_mean(QX), pack(QF, QCV)


@jit
def remember(X, F, CV, PX, PM, pool, QM, mutate, rows, picks, bounds):
    """Eqs. 18 and 7 after an evaluation, and the Eq. 16 candidates when ``mutate``.

    The memory: personal bests ``PX`` (n, d) and their ``PM = (F, CV)`` (2, n); the pool
    with its mean as a last row, ``pool`` (k + 1, d), and its ``QM = (F, CV)`` (2, k).
    Returns the new ``(PX, PM, pool, QM)`` and the repaired mutation candidates (no rows
    unless ``mutate``).
    """
    PX, PF, PCV = greedy_step(X, F, CV, PX, PM[0], PM[1])
    QX, QF, QCV = pool_update(pool, QM[0], QM[1], X, F, CV, POOL_SIZE, True)  # not its mean
    X_mut = np.empty((PX.shape[0] if mutate else 0, PX.shape[1]))
    if mutate:
        repaired(difference_rows(PX, picks[4:7], rows[4], X_mut), PX, bounds)
    return PX, pack(PF, PCV), pool_with_mean(QX), pack(QF, QCV), X_mut


@jit(inline=True)
def pack(F, CV):
    """``(F, CV)`` as one (2, n) array."""
    out = np.empty((2, F.size))
    for i in range(F.size):
        out[0, i], out[1, i] = F[i], CV[i]
    return out
