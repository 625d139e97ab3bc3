"""Equilibrium optimizer (EO).

Faramarzi, Heidarinejad, Stephens & Mirjalili, "Equilibrium optimizer: A novel
optimization algorithm", Knowledge-Based Systems 191, 105190 (2020),
DOI 10.1016/j.knosys.2019.105190. Equation numbers below are those of the EOSMA
paper (Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3),
which restates EO as Eqs. 6-9:

- Eq. 6: ``C = Ceq + F (C - Ceq) + (1 - F) G / (lambda V)``;
- Eq. 7: the equilibrium pool, the 4 best solutions found so far and their mean;
- Eq. 8: ``F = a1 sign(r - 0.5) (exp(-lambda t1) - 1)``,
  ``t1 = (1 - t/T)^(a2 t/T)``;
- Eq. 9: ``G = GCP (Ceq - lambda C) F`` with ``GCP = 0.5 r1`` if ``r2 >= GP``
  else 0;
- memory saving: an agent keeps its previous position if that was better.

Defaults (EOSMA paper, Table 3; the EO paper's own): a1=2, a2=1, GP=0.5, V=1.
Evaluations: N per iteration. Out-of-range coordinates are clipped to the bounds,
as in the authors' code.

Deviations:
- The authors' code keeps the pool as a cascade of ``if/elseif`` tests, which
  does not shift old members down when a new best arrives; here the pool is
  the true 4 best solutions evaluated so far (the paper's wording).
- The authors' code divides ``G ./ lambda * V``; the paper divides by
  ``lambda V``. Identical for the default V=1; the paper's form is used.
- Constrained problems: comparisons are feasibility-first (see base.py).

Compiled: the update (:func:`concentration_rows`, per coordinate
:func:`eo_coordinate`, which EOSMA's update inlines too), the pool selection
(:func:`best_rows`, shared with EOSMA's distinct pool) and the pool mean. The random
numbers are drawn with numpy's Generator before the kernel, and ``exp`` is numpy's:
numpy's vectorised ``exp`` and the C library's (which numba calls) differ in the last
bit for some inputs, and numpy's is the one the recorded results were computed with.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit, kernel_array
from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    greedy_memory,
    ieee_divide,
    ranking_into,
    ranks_before,
)


@jit
def best_rows(X, S, k, distinct):
    """Indices of the ``k`` best rows by ``S`` in numpy's stable order (nan last).

    With ``distinct``, a row equal (in ``X`` and in ``S``) to a better-ranked row is
    skipped: the result is the first ``k`` rows of the stably sorted order with each
    such duplicate dropped. Rows are streamed in index order into a sorted buffer of
    ``k``; a duplicate of a row pushed out of the buffer ranks after every buffered row
    (same S, later index), so it could not enter anyway.
    """
    top = np.empty(k, np.int64)
    m = 0
    for e in range(S.size):
        if distinct:
            duplicate = False
            for b in range(m):
                t = top[b]
                if S[t] == S[e]:
                    same = True
                    for j in range(X.shape[1]):
                        if X[t, j] != X[e, j]:
                            same = False
                            break
                    if same:
                        duplicate = True
                        break
            if duplicate:
                continue
        p = m
        while p > 0 and ranks_before(S[e], S[top[p - 1]]):
            p -= 1
        if p >= k:
            continue
        for b in range(min(m, k - 1), p, -1):
            top[b] = top[b - 1]
        top[p] = e
        m = min(m + 1, k)
    return top[:m]


@jit
def pool_update(PX, PF, PCV, X, F, CV, k, distinct):
    """Eq. 7: the ``k`` best rows of the pool and a batch, feasibility-first (zeros CV
    when unconstrained), as new arrays ``(PX, PF, PCV)``. The pool is the first ``PF.size``
    rows of ``PX`` (a row after them, such as the pool mean, is ignored)."""
    m0, m, d = PF.size, PF.size + F.size, X.shape[1]
    X_all, F_all, CV_all = np.empty((m, d)), np.empty(m), np.empty(m)
    for i in range(m0):
        for j in range(d):
            X_all[i, j] = PX[i, j]
        F_all[i], CV_all[i] = PF[i], PCV[i]
    for i in range(F.size):
        for j in range(d):
            X_all[m0 + i, j] = X[i, j]
        F_all[m0 + i], CV_all[m0 + i] = F[i], CV[i]
    top = best_rows(X_all, ranking_into(F_all, CV_all, np.empty(m)), k, distinct)
    QX, QF, QCV = np.empty((top.size, d)), np.empty(top.size), np.empty(top.size)
    for b in range(top.size):
        for j in range(d):
            QX[b, j] = X_all[top[b], j]
        QF[b], QCV[b] = F_all[top[b]], CV_all[top[b]]
    return QX, QF, QCV


def select_pool(PX, PF, PCV, X, F, CV, k: int, distinct: bool):
    """:func:`pool_update` for numpy callers (``CV`` None when unconstrained)."""
    zeros = CV is None
    cv, pcv = (np.zeros(len(F)), np.zeros(len(PF))) if zeros else (kernel_array(CV),
                                                                   kernel_array(PCV))
    QX, QF, QCV = pool_update(kernel_array(PX), kernel_array(PF), pcv, kernel_array(X),
                              kernel_array(F), cv, k, distinct)
    return QX, QF, (None if zeros else QCV)


def update_pool(PX, PF, PCV, X, F, CV, k: int = 4):
    """Eq. 7 (first part): the ``k`` best of the old pool and a new evaluated batch.

    Returns:
        ``(PX, PF, PCV)`` with at most ``k`` rows, best first.
    """
    return select_pool(PX, PF, PCV, X, F, CV, k, False)


@jit
def pool_with_mean(PX):
    """Eq. 7: the pool rows and their mean (Ceq_ave) as a last row, summed row by row."""
    k, d = PX.shape
    out = np.empty((k + 1, d))
    for j in range(d):
        acc = PX[0, j]
        out[0, j] = acc
        for i in range(1, k):
            out[i, j] = PX[i, j]
            acc += PX[i, j]
        out[k, j] = acc / k
    return out


def with_mean(PX: np.ndarray) -> np.ndarray:
    """Eq. 7: append the mean of the pool members (Ceq_ave) as a last row."""
    return pool_with_mean(kernel_array(PX))


def eo_schedule(t: int, T: int, a2: float) -> float:
    """Eq. 8: ``t1 = (1 - t/T)^(a2 t/T)``, with t/T capped at 1."""
    s = min(t / T, 1.0)
    return (1.0 - s) ** (a2 * s)


@jit(inline=True)
def generation_control(r1: float, r2: float, GP: float) -> float:
    """Eq. 9: ``GCP = 0.5 r1`` if ``r2 >= GP`` else 0."""
    return 0.5 * r1 if r2 >= GP else 0.0


@jit(inline=True)
def eo_coordinate(c, ceq, lam, e, r, gcp, a1, V):
    """Eqs. 6, 8, 9 for one coordinate, with ``e = exp(-lam t1)`` computed by numpy."""
    s = r - 0.5
    sign = 1.0 if s > 0.0 else (-1.0 if s < 0.0 else (0.0 if s == 0.0 else s))  # np.sign
    F = a1 * sign * (e - 1.0)  # Eq. 8
    G = gcp * (ceq - lam * c) * F  # Eq. 9
    return ceq + (c - ceq) * F + ieee_divide(G, lam * V) * (1.0 - F)  # Eq. 6


@jit
def concentration_rows(C, pool, lam, E, r, idx, r1, r2, a1, GP, V, out):
    """Eqs. 6, 8, 9 on every row of ``C`` from its drawn numbers, into ``out``."""
    n, d = C.shape
    for i in range(n):
        gcp = generation_control(r1[i], r2[i], GP)
        for j in range(d):
            out[i, j] = eo_coordinate(C[i, j], pool[idx[i], j], lam[i, j], E[i, j], r[i, j],
                                      gcp, a1, V)
    return out


def concentration_update(C, pool, t1: float, *, a1: float, GP: float, V: float,
                         rng: np.random.Generator) -> np.ndarray:
    """Eqs. 6, 8, 9: EO's concentration update of every row of ``C``.

    Args:
        C: Current concentrations (n, d).
        pool: Equilibrium pool (m, d), one member drawn per agent.
        t1: Time factor of Eq. 8.
        a1: Exploration factor. GP: generation probability. V: control volume.
        rng: Random generator: ``lam``, ``r`` (n, d), the pool index (n,), ``r1``, ``r2``
            (n,), in that order.
    """
    C = kernel_array(C)
    n, d = C.shape
    lam = kernel_array(rng.random((n, d)))
    r = kernel_array(rng.random((n, d)))
    idx = np.asarray(rng.integers(len(pool), size=n), dtype=np.int64)
    r1, r2 = kernel_array(rng.random(n)), kernel_array(rng.random(n))
    E = np.exp(-lam * t1)
    return concentration_rows(C, kernel_array(pool), lam, E, r, idx, r1, r2, float(a1),
                              float(GP), float(V), np.empty((n, d)))


class EO(ArrayAlgorithm):
    """Equilibrium optimizer (Faramarzi et al. 2020) with array state.

    Extra public arrays: ``pool_X``/``pool_F`` (the 4 best so far). ``X``/``F`` is
    the memory (EO's memory saving makes the population its own memory).

    Args:
        pop_size: Number of particles N.
        a1: Exploration factor, > 0 (paper: 2).
        a2: Exploitation factor, > 0 (paper: 1).
        GP: Generation probability in [0, 1] (paper: 0.5).
        V: Control volume, > 0 (paper: 1).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, a1: float = 2.0, a2: float = 1.0,
                 GP: float = 0.5, V: float = 1.0, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.a1 = interval("a1", a1, 0.0, 10.0, lo_open=True)
        self.a2 = interval("a2", a2, 0.0, 10.0, lo_open=True)
        self.GP = interval("GP", GP, 0.0, 1.0)
        self.V = interval("V", V, 0.0, np.inf, lo_open=True, hi_open=True)

    def _initialize_state(self) -> None:
        empty = np.empty((0, self.problem.n_var))
        cv0 = None if self.CV is None else np.empty(0)
        self.pool_X, self.pool_F, self.pool_CV = update_pool(
            empty, np.empty(0), cv0, self.X, self.F, self.CV)

    def _generation(self) -> Step:
        t1 = eo_schedule(self.t, self.max_iter, self.a2)
        X = concentration_update(self.X, with_mean(self.pool_X), t1, a1=self.a1, GP=self.GP,
                                 V=self.V, rng=self.random_state)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.pool_X, self.pool_F, self.pool_CV = update_pool(
            self.pool_X, self.pool_F, self.pool_CV, X, F, CV)
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
