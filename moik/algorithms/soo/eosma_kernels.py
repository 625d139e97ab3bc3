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
from numba.np.random.random_methods import random_bounded_uint64_fill

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


@jit(inline=True)
def difference_rows(P, R, SF, out):
    """Eq. 16 on every agent from its drawn indices ``R`` (3, n) and factors ``SF`` (n,)."""
    n, d = out.shape
    for i in range(n):
        for j in range(d):
            out[i, j] = difference_coordinate(P[R[0, i], j], P[R[1, i], j], P[R[2, i], j], SF[i])
    return out


# One generation's random numbers (GenerationDraws): three scratch arrays whose slots are
# named here; the kernels index them by these constants (numba folds module-level ints).
# cells (5, n, d): per agent and coordinate
WEIGHT_R = 0  # r of Eq. 4, per rank
LAMBDA = 1  # lambda of Eq. 8
DECAY = 2  # -lambda t1, then numpy's exp(-lambda t1) (Eq. 8)
EO_R = 3  # r of Eq. 8's sign
VB = 4  # SMA's vb of Eq. 1 in U(-a, a)
N_CELLS = 5
# rows (5, n): per agent
LOG_WEIGHT = 0  # the Eq. 4 log10 argument per rank, then numpy's log10
GCP_R1 = 1  # r1 of Eq. 9
GCP_R2 = 2  # r2 of Eq. 9
OPERATOR_U = 3  # Eq. 15's operator test (EO where < z)
SF = 4  # Eq. 16's scale factor in U(0.3, 0.6)
N_ROWS = 5
# picks (7, n): per agent, integers
ORDER = 0  # the ranking of Eq. 5 (best first)
POOL_INDEX = 1  # the pool member of Eq. 6
A_INDEX = 2  # X_A of Eq. 1
B_INDEX = 3  # X_B of Eq. 1
MUTANT_R = 4  # R1, R2, R3 of Eq. 16 (three slots: 4, 5, 6)
N_PICKS = 7


class GenerationDraws:
    """Every random number of one EOSMA/MOEOSMA generation, in named slots.

    The kernels take the three arrays (``cells`` (5, n, d), ``rows`` (5, n), ``picks``
    (7, n) int) and index them by the module's slot constants; this class owns them and
    names each slot (a view) for readers and tests.

    Args:
        n: Number of agents. d: Number of variables.
    """

    def __init__(self, n: int, d: int) -> None:
        self.cells = np.empty((N_CELLS, n, d))
        self.rows = np.empty((N_ROWS, n))
        self.picks = np.empty((N_PICKS, n), dtype=np.int64)

    weight_r = property(lambda self: self.cells[WEIGHT_R], doc="r of Eq. 4 (n, d), per rank")
    lam = property(lambda self: self.cells[LAMBDA], doc="lambda of Eq. 8 (n, d)")
    decay = property(lambda self: self.cells[DECAY], doc="exp(-lambda t1) of Eq. 8 (n, d)")
    eo_r = property(lambda self: self.cells[EO_R], doc="r of Eq. 8's sign (n, d)")
    vb = property(lambda self: self.cells[VB], doc="vb of Eq. 1 (n, d)")
    log_weight = property(lambda self: self.rows[LOG_WEIGHT], doc="Eq. 4's log10 term (n,)")
    gcp_r1 = property(lambda self: self.rows[GCP_R1], doc="r1 of Eq. 9 (n,)")
    gcp_r2 = property(lambda self: self.rows[GCP_R2], doc="r2 of Eq. 9 (n,)")
    operator_u = property(lambda self: self.rows[OPERATOR_U], doc="Eq. 15's test (n,)")
    sf = property(lambda self: self.rows[SF], doc="SF of Eq. 16 (n,)")
    order = property(lambda self: self.picks[ORDER], doc="Eq. 5's ranking (n,)")
    pool_index = property(lambda self: self.picks[POOL_INDEX], doc="Eq. 6's pool member (n,)")
    a_index = property(lambda self: self.picks[A_INDEX], doc="X_A of Eq. 1 (n,)")
    b_index = property(lambda self: self.picks[B_INDEX], doc="X_B of Eq. 1 (n,)")
    mutant_r = property(lambda self: self.picks[MUTANT_R:MUTANT_R + 3],
                        doc="R1..R3 of Eq. 16 (3, n)")

    def apply_numpy_maths(self) -> None:
        """numpy's log10 (Eq. 4) and exp (Eq. 8) in place, between the draws and the
        candidates (numpy's and the C library's differ in the last bit: module doc)."""
        np.log10(self.rows[LOG_WEIGHT], out=self.rows[LOG_WEIGHT])
        np.exp(self.cells[DECAY], out=self.cells[DECAY])


@jit
def fill_random(rng, A):
    """``A`` (2-D) filled with ``rng.random()`` in C order, as ``rng.random(A.shape)``."""
    for i in range(A.shape[0]):
        for j in range(A.shape[1]):
            A[i, j] = rng.random()


@jit
def fill_integers(rng, high, A):
    """``A`` (2-D) filled as ``rng.integers(high, size=A.shape)`` (``high >= 1``).

    Calls numba's implementation of that method below its argument checks and dtype
    dispatch (``random_bounded_uint64_fill``, numpy's ``_rand_int64`` for the values
    ``0 .. high - 1``): the same draws, and about a second less to compile on a cold
    start (tests/algorithms/soo/test_eosma.py compares the stream with numpy's).
    """
    values = random_bounded_uint64_fill(rng.bit_generator, np.int64(0), np.int64(high - 1),
                                        A.size, np.int64)
    for i in range(A.shape[0]):
        for j in range(A.shape[1]):
            A[i, j] = values[i * A.shape[1] + j]


@jit
def generation_draws(handle, pbest_fcv, n_pool, t1, a, q, cells, rows, picks):
    """Every random number of one generation, in Algorithm 1's order; the mutation test.

    Ranks the personal bests by ``pbest_fcv = (F, CV)`` (Eq. 5) and fills the Eq. 4 log10
    argument into ``rows[LOG_WEIGHT]`` and ``-lam t1`` into ``cells[DECAY]`` (the caller
    applies numpy's log10 and exp). Draws: r (n, d) of Eq. 4; lam, r (n, d), the pool
    index, r1, r2 (n,) of Eqs. 8-9; vb (n, d); A, B; the operator test (n,); the mutation
    test of line 22 and, when it passes, R1..R3 and SF of Eq. 16, all on ``handle.rng`` (a
    :class:`~moik.algorithms.generator_handle.GeneratorHandle`), into the named slots of
    :class:`GenerationDraws`. Returns whether the mutation runs.
    """
    rng = handle.rng
    n = cells.shape[1]
    weight_arguments(ranking_into(pbest_fcv[0], pbest_fcv[1], np.empty(n)), picks[ORDER],
                     rows[LOG_WEIGHT])
    fill_random(rng, cells[WEIGHT_R])
    fill_random(rng, cells[LAMBDA])
    decay_into(cells, t1)
    fill_random(rng, cells[EO_R])
    fill_integers(rng, n_pool, picks[POOL_INDEX:POOL_INDEX + 1])
    fill_random(rng, rows[GCP_R1:GCP_R2 + 1])
    uniform_into(rng, -a, a, cells[VB])
    fill_integers(rng, n, picks[A_INDEX:B_INDEX + 1])
    for i in range(n):
        rows[OPERATOR_U, i] = rng.random()
    return mutation_draws(rng, q, rows, picks)


@jit(inline=True)
def decay_into(cells, t1):
    """``cells[DECAY] = -lam t1`` (numpy's exp follows in the caller, Eq. 8)."""
    for i in range(cells.shape[1]):
        for j in range(cells.shape[2]):
            cells[DECAY, i, j] = -cells[LAMBDA, i, j] * t1


@jit(inline=True)
def uniform_into(rng, lo, hi, A):
    """``A`` (2-D) filled as ``rng.uniform(lo, hi, A.shape)``."""
    for i in range(A.shape[0]):
        for j in range(A.shape[1]):
            A[i, j] = rng.uniform(lo, hi)


@jit(inline=True)
def mutation_draws(rng, q, rows, picks):
    """The mutation test (EOSMA line 22, MOEOSMA line 26) and, when it passes, R1..R3
    (one ``integers`` call of 3n) and SF of Eq. 16. Returns whether the mutation runs."""
    n = rows.shape[1]
    mutate = rng.random() < q
    if mutate:
        fill_integers(rng, n, picks[MUTANT_R:MUTANT_R + 3])
        for i in range(n):
            rows[SF, i] = rng.uniform(0.3, 0.6)
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
    """Eqs. 4, 15 and 17: the repaired candidates of a generation from its drawn numbers.
    ``g_best`` is (1, d), or (n, d) with one leader per agent (MOEOSMA)."""
    n, d = P.shape
    W = weights_into(picks[ORDER], rows[LOG_WEIGHT], cells[WEIGHT_R], np.empty((n, d)))
    X = eosma_rows(P, g_best, pool, W, cells[LAMBDA], cells[DECAY], cells[EO_R],
                   picks[POOL_INDEX], rows[GCP_R1], rows[GCP_R2], cells[VB], picks[A_INDEX],
                   picks[B_INDEX], rows[OPERATOR_U], z, a1, GP, V, np.empty((n, d)))
    return repaired(X, P, bounds)


@jit
def mutation_candidates(P, rows, picks, bounds):
    """Eqs. 16 and 17: the repaired mutants of the personal bests ``P`` from the drawn
    R1..R3 and SF."""
    X = np.empty(P.shape)
    return repaired(difference_rows(P, picks[MUTANT_R:MUTANT_R + 3], rows[SF], X), P, bounds)


@jit
def first_pool(X, F, CV):
    """Eq. 7 on the initial population: the pool with its mean as a last row, its F and CV
    (2, k). (Called with the same constant arguments as :func:`remember`, so that
    ``pool_update`` compiles once.)"""
    QX, QF, QCV = pool_update(np.empty((0, X.shape[1])), np.empty(0), np.empty(0), X, F, CV,
                              POOL_SIZE, True)
    return pool_with_mean(QX), pack(QF, QCV)


@jit
def remember(X, F, CV, PX, pbest_fcv, pool, pool_fcv, mutate, rows, picks, bounds):
    """Eqs. 18 and 7 after an evaluation, and the Eq. 16 candidates when ``mutate``.

    The memory: personal bests ``PX`` (n, d) and their ``pbest_fcv = (F, CV)`` (2, n);
    the pool with its mean as a last row, ``pool`` (k + 1, d), and its
    ``pool_fcv = (F, CV)`` (2, k). Returns the new ``(PX, pbest_fcv, pool, pool_fcv)``
    and the repaired mutation candidates (no rows unless ``mutate``).
    """
    PX, PF, PCV = greedy_step(X, F, CV, PX, pbest_fcv[0], pbest_fcv[1])
    QX, QF, QCV = pool_update(pool, pool_fcv[0], pool_fcv[1], X, F, CV, POOL_SIZE, True)
    X_mut = mutation_candidates(PX, rows, picks, bounds) if mutate else \
        np.empty((0, PX.shape[1]))
    return PX, pack(PF, PCV), pool_with_mean(QX), pack(QF, QCV), X_mut


@jit
def pack(F, CV):
    """``(F, CV)`` as one (2, n) array."""
    out = np.empty((2, F.size))
    for i in range(F.size):
        out[0, i], out[1, i] = F[i], CV[i]
    return out
