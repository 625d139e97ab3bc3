"""MOEOSMA's compiled generation: the random draws, Eqs. 4, 15, 16, 17 and the memory.

Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3; the equations,
readings and deviations are in :mod:`moik.algorithms.moo.moeosma`. The numpy operators
of EOSMA (:func:`moik.algorithms.soo.eosma.eosma_update`, ``sma_weights``,
``random_difference_mutation``, ``midpoint_repair``) cost about 150 us per MOEOSMA
generation at N = 100, d = 7, mostly numpy's per-call overhead; these kernels do the
same arithmetic in a few microseconds.

Random numbers: :func:`generation_draws` draws every number of a generation on the
algorithm's numpy ``Generator`` inside the kernel (numba's Generator methods give numpy's
stream), in the order of the numpy operators: the leader of each agent, the Eq. 4
weights, EO's lambda, r, pool index, r1, r2 (Eqs. 8-9), SMA's vb, A, B, the operator
test, then the mutation test and Eq. 16's R1..R3 and SF. Algorithm 2 draws the
mutation numbers after the first evaluation; nothing between consumes the Generator
(the evaluation and the memory draw nothing, the archive merge comes at the end of the
iteration), so drawing them in the same call gives the same stream, with one Generator
conversion per generation (numba types a Generator argument in about 10 us).

Bit identity with the numpy operators: every value is computed with the same IEEE
operations in the same order; the Eq. 4 ``log10`` and the Eq. 8 ``exp`` are numpy's,
applied by the caller between the draws and :func:`candidates` (numpy's vectorised
``log10``/``exp`` and the C library's, which numba calls, differ in the last bit for
some inputs). So a seed gives the same run as the numpy operators did.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit

EPS = np.finfo(float).eps


@jit(inline=True)
def midpoint(x: float, x_old: float, lo: float, hi: float) -> float:
    """Eq. 17 for one coordinate: beyond a bound, halfway from the old value to it."""
    if x > hi:
        return (x_old + hi) / 2.0
    if x < lo:
        return (x_old + lo) / 2.0
    return x


@jit
def candidates(P, pool, picks, cells, rows, log10_val, exp_val, a1: float, z: float,
               GP: float, V: float, xl, xu):
    """Eqs. 4, 15 and 17: the repaired candidates of the first batch of a generation.

    Args:
        P: Personal bests (n, d). pool: Equilibrium pool (m, d).
        picks, cells, rows: From :func:`leader_draws`.
        log10_val: numpy's ``log10`` of the Eq. 4 argument (n,), per rank.
        exp_val: numpy's ``exp(-lambda t1)`` (n, d) of Eq. 8.
        a1, z, GP, V: Hyperparameters (EO exploration factor, operator probability,
            generation probability, volume).
        xl, xu: Bounds (d,).

    Returns:
        Candidates (n, d) inside the bounds.
    """
    n, d = P.shape
    W = np.empty((n, d))
    for k in range(n):
        sign = 1.0 if k + 1 <= n / 2 else -1.0
        w = sign * log10_val[k]
        for j in range(d):
            W[picks[1, k], j] = 1.0 + w * cells[0, k, j]  # Eq. 4
    X = np.empty((n, d))
    for i in range(n):
        g, q = picks[0, i], picks[2, i]
        gcp = 0.5 * rows[0, i] if rows[1, i] >= GP else 0.0  # Eq. 9
        eo = rows[2, i] < z
        for j in range(d):
            if eo:  # Eqs. 6, 8, 9 on the personal best (Eq. 15, first case)
                lam, c, ceq = cells[1, i, j], P[i, j], pool[q, j]
                F = a1 * np.sign(cells[2, i, j] - 0.5) * (exp_val[i, j] - 1.0)
                G = gcp * (ceq - lam * c) * F
                x = ceq + (c - ceq) * F + G / (lam * V) * (1.0 - F)
            else:  # Eq. 15, second case
                x = pool[g, j] + cells[3, i, j] * (W[i, j] * P[picks[3, i], j] - P[picks[4, i], j])
            X[i, j] = midpoint(x, P[i, j], xl[j], xu[j])
    return X


@jit(inline=True)
def mutation_draws(rng, n: int, q: float):
    """The mutation test (Algorithm 2, line 26) and, when it passes, Eq. 16's R1..R3 and SF.

    Returns:
        ``(mutate, R, SF)`` with R (3, n) and SF (n,) (empty when not mutating).
    """
    if not rng.random() < q:
        return False, np.empty((3, 0), dtype=np.int64), np.empty(0)
    R = rng.integers(0, n, size=(3, n))
    SF = np.empty(n)
    for i in range(n):
        SF[i] = rng.uniform(0.3, 0.6)
    return True, R, SF


@jit
def generation_draws(rng, n: int, d: int, n_pool: int, a: float, q: float, S):
    """Every random number of a generation for ``n`` agents, in the numpy operators' order.

    Args:
        rng: The algorithm's numpy Generator.
        n: Number of agents. d: Number of variables. n_pool: Size of the equilibrium pool.
        a: The SMA range of Eq. 3 (vb ~ U(-a, a)). q: The mutation probability.
        S: The personal bests' fitness on the Eq. 21 objective (n,), ranked for Eq. 5.

    Returns:
        ``(picks, cells, rows, log_arg, mutate, R, SF)``: picks (5, n) int: leader, order
        of S (Eq. 5), pool index, A, B; cells (4, n, d): Eq. 4's r, lambda, Eq. 8's r,
        vb; rows (3, n): r1, r2, the operator test; log_arg (n,): the Eq. 4 log10
        argument per rank; whether the mutation runs (Algorithm 2, line 26) and its
        R (3, n) and SF (n,) of Eq. 16 (no columns when it does not).
    """
    picks = np.empty((5, n), dtype=np.int64)
    cells = np.empty((4, n, d))
    rows = np.empty((3, n))
    picks[0] = rng.integers(0, n_pool, size=n)
    order = np.argsort(S, kind="mergesort")
    picks[1] = order
    bF, wF = S[order[0]], S[order[n - 1]]
    log_arg = np.empty(n)
    for k in range(n):
        log_arg[k] = (bF - S[order[k]]) / (bF - wF - EPS) + 1.0
    for c in range(3):
        for i in range(n):
            for j in range(d):
                cells[c, i, j] = rng.random()
        if c == 2:
            picks[2] = rng.integers(0, n_pool, size=n)
    for r in range(2):
        for i in range(n):
            rows[r, i] = rng.random()
    for i in range(n):
        for j in range(d):
            cells[3, i, j] = rng.uniform(-a, a)
    picks[3] = rng.integers(0, n, size=n)
    picks[4] = rng.integers(0, n, size=n)
    for i in range(n):
        rows[2, i] = rng.random()
    mutate, R, SF = mutation_draws(rng, n, q)
    return picks, cells, rows, log_arg, mutate, R, SF


@jit
def mutants(P, R, SF, xl, xu):
    """Eq. 16 and Eq. 17: ``pBest_R1 + SF (pBest_R2 - pBest_R3)``, repaired against ``P``."""
    n, d = P.shape
    X = np.empty((n, d))
    for i in range(n):
        for j in range(d):
            x = P[R[0, i], j] + SF[i] * (P[R[1, i], j] - P[R[2, i], j])
            X[i, j] = midpoint(x, P[i, j], xl[j], xu[j])
    return X
