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


def dominates(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """Row-wise Pareto dominance (EOSMA Eq. 11): ``A_i <= B_i`` everywhere, ``<`` somewhere."""
    return np.all(A <= B, axis=1) & np.any(A < B, axis=1)


def constrained_dominates(FA: np.ndarray, CVA: np.ndarray | None, FB: np.ndarray,
                          CVB: np.ndarray | None) -> np.ndarray:
    """Row-wise constraint-domination of ``(FA, CVA)`` over ``(FB, CVB)`` (see the module doc).

    ``CVA``/``CVB`` None (unconstrained) reduces it to :func:`dominates`.
    """
    if CVA is None:
        return dominates(FA, FB)
    feas_a, feas_b = CVA <= 0.0, CVB <= 0.0
    return np.where(feas_a & feas_b, dominates(FA, FB), (feas_a & ~feas_b)
                    | (~feas_a & ~feas_b & (CVA < CVB)))


def dominance_memory(X, F, CV, PX, PF, PCV):
    """Eq. 18 with (constraint-)domination: the memory keeps ``PX_i`` only if it dominates ``X_i``.

    An equal, incomparable or better new point replaces it (the authors' MOEOSMA.m
    keeps the old point only when it is better in every objective).

    Returns:
        The updated memory ``(PX, PF, PCV)`` as new arrays (``PCV`` None without constraints).
    """
    keep = constrained_dominates(PF, PCV, F, CV)
    PCV = None if CV is None else np.where(keep, PCV, CV)
    return np.where(keep[:, None], PX, X), np.where(keep[:, None], PF, F), PCV


def pareto_memory(X, F, PX, PF):
    """:func:`dominance_memory` without constraints: returns ``(PX, PF)``."""
    PX, PF, _ = dominance_memory(X, F, None, PX, PF, None)
    return PX, PF
