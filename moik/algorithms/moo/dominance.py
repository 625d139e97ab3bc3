"""Pareto and constraint-domination of paired rows, and the memories built on them.

Every multi-objective memory in moik (MOEOSMA's personal bests, MOMPA's marine
memory, MOPSO's personal bests and mutants) compares a new point with the
point it would replace, row by row. Without constraints that is Pareto
dominance (EOSMA paper, Yin et al. 2022, DOI 10.1038/s41598-022-13516-3,
Eq. 11): ``a`` dominates ``b`` when ``a <= b`` in every objective and ``a < b``
in at least one.

With constraints (``CV``: total violation per row, 0 when feasible) it is
constraint-domination (Deb's rules, as pymoo's multi-objective algorithms and
the archives, :mod:`moik.algorithms.archive.base`): a feasible point dominates
an infeasible one, of two infeasible points the smaller violation dominates,
two feasible points compare by Pareto dominance. ``CV`` is ``None`` for
unconstrained problems, which keeps their comparisons to Eq. 11 alone. Rows
left unevaluated by an ``n_eval`` budget carry ``F = CV = inf``: they never
dominate and are dominated by every evaluated row.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit, kernel_array


@jit(inline=True)
def _dominates(FA, cva: float, FB, cvb: float, i: int) -> bool:
    """Row i of ``FA`` (violation ``cva``) constraint-dominates row i of ``FB`` (``cvb``)."""
    a_ok, b_ok = cva <= 0.0, cvb <= 0.0
    if not (a_ok and b_ok):
        return (a_ok and not b_ok) or (not a_ok and not b_ok and cva < cvb)
    less = False
    for j in range(FA.shape[1]):
        if not FA[i, j] <= FB[i, j]:  # worse, or NaN
            return False
        less = less or FA[i, j] < FB[i, j]
    return less


@jit
def _dominates_rows(FA, CVA, FB, CVB):
    """Row i of ``(FA, CVA)`` constraint-dominates row i of ``(FB, CVB)`` (module doc)."""
    out = np.empty(FA.shape[0], dtype=np.bool_)
    for i in range(FA.shape[0]):
        out[i] = _dominates(FA, CVA[i], FB, CVB[i], i)
    return out


@jit
def _pareto_memory_rows(X, F, PX, PF):
    """Eq. 18 with Pareto dominance (no constraints): new ``(PX, PF)`` arrays."""
    MX, MF = X.copy(), F.copy()
    for i in range(X.shape[0]):
        if _dominates(PF, 0.0, F, 0.0, i):  # element loops: no row assignment, whose
            for j in range(X.shape[1]):  # shape-error code takes seconds to compile
                MX[i, j] = PX[i, j]
            for j in range(F.shape[1]):
                MF[i, j] = PF[i, j]
    return MX, MF


def dominates(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """Row-wise Pareto dominance (EOSMA Eq. 11): ``A_i <= B_i`` everywhere, ``<`` somewhere."""
    zero = np.zeros(len(A))
    return _dominates_rows(kernel_array(A), zero, kernel_array(B), zero)


def constrained_dominates(FA: np.ndarray, CVA: np.ndarray | None, FB: np.ndarray,
                          CVB: np.ndarray | None) -> np.ndarray:
    """Row-wise constraint-domination of ``(FA, CVA)`` over ``(FB, CVB)`` (see the module doc).

    ``CVA``/``CVB`` None (unconstrained) reduces it to :func:`dominates`.
    """
    if CVA is None:
        return dominates(FA, FB)
    return _dominates_rows(kernel_array(FA), kernel_array(CVA), kernel_array(FB),
                           kernel_array(CVB))


def dominance_memory(X, F, CV, PX, PF, PCV):
    """Eq. 18 with (constraint-)domination: the memory keeps ``PX_i`` only if it dominates ``X_i``.

    An equal, incomparable or better new point replaces it (the authors' MOEOSMA.m
    keeps the old point only when it is better in every objective).

    Returns:
        The updated memory ``(PX, PF, PCV)`` as new arrays (``PCV`` None without constraints).
    """
    if CV is None:
        PX, PF = _pareto_memory_rows(kernel_array(X), kernel_array(F), kernel_array(PX),
                                     kernel_array(PF))
        return PX, PF, None
    keep = constrained_dominates(PF, PCV, F, CV)
    return (np.where(keep[:, None], PX, X), np.where(keep[:, None], PF, F),
            np.where(keep, PCV, CV))


def pareto_memory(X, F, PX, PF):
    """:func:`dominance_memory` without constraints: returns ``(PX, PF)``."""
    PX, PF, _ = dominance_memory(X, F, None, PX, PF, None)
    return PX, PF
