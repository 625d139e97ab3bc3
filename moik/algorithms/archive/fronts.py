"""Pareto filters of the archives: non-dominated rows, constraint-domination, duplicates.

Ordinary Pareto dominance (EOSMA paper, Yin et al. 2022, Eq. 11, minimization):
``a`` dominates ``b`` when ``a <= b`` in every objective and ``a < b`` in at least
one; constraint-domination (Deb's rules, as pymoo's multi-objective algorithms)
first compares the total violations (see :mod:`moik.algorithms.archive.base`).

Pairwise dominance is vectorized as (m, m) comparisons, one per objective. For two
objectives a sort-based O(m log m) test gives the same mask; it is used
automatically because the archive update runs every generation.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit, kernel_array
from moik.algorithms.mechanics import stable_order


def nondominated_mask(F: np.ndarray) -> np.ndarray:
    """Mask of the rows of ``F`` that no other row dominates (Eq. 11, minimization).

    Exact duplicates do not dominate each other, so all copies of a
    non-dominated row are kept; see :func:`first_unique_mask`.

    Args:
        F: Objective values, shape (m, n_obj).

    Returns:
        Boolean array of shape (m,).
    """
    if F.shape[0] <= 1:
        return np.ones(F.shape[0], dtype=bool)
    if F.shape[1] == 2:
        return front_mask_2d(kernel_array(F), False)
    m = F.shape[0]
    leq = np.ones((m, m), dtype=bool)  # leq[j, i]: F_j <= F_i in every objective
    lt = np.zeros((m, m), dtype=bool)  # lt[j, i]: F_j < F_i in some objective
    for k in range(F.shape[1]):  # loop over objectives only
        col = F[:, k]
        leq &= col[:, None] <= col[None, :]
        lt |= col[:, None] < col[None, :]
    return ~np.any(leq & lt, axis=0)


@jit
def front_mask_2d(F: np.ndarray, unique: bool) -> np.ndarray:
    """Two-objective :func:`nondominated_mask` by lexicographic sort, O(m log m), compiled;
    with ``unique`` also dropping every repeat of a row after its first occurrence.

    After sorting by (f1, f2) (stable, so equal rows stay in index order), row i is
    dominated exactly when a row with a smaller f1 has f2 <= f2_i, or a row with the
    same f1 has f2 < f2_i; a repeat directly follows an equal row.
    """
    m = F.shape[0]
    by_f2 = stable_order(F[:, 1].copy(), np.empty(m, np.int64))
    order = by_f2[stable_order(F[by_f2, 0], np.empty(m, np.int64))]  # np.lexsort((f2, f1))
    mask = np.empty(m, dtype=np.bool_)
    before = np.inf  # smallest f2 of the rows with a smaller f1
    k = 0
    while k < m:
        f1 = F[order[k], 0]
        group_min = F[order[k], 1]  # the first row of a group has its smallest f2
        e = k
        while e < m and F[order[e], 0] == f1:
            f2 = F[order[e], 1]
            repeat = unique and e > k and F[order[e - 1], 1] == f2
            mask[order[e]] = not (before <= f2 or group_min < f2 or repeat)
            e += 1
        before = min(before, group_min)
        k = e
    return mask


def constrained_nondominated_mask(F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
    """Rows no other row constraint-dominates (see the module doc); ``CV`` None: Eq. 11.

    Args:
        F: Objective values, shape (m, n_obj).
        CV: Total constraint violation per row (m,), 0 when feasible, or None.

    Returns:
        Boolean array of shape (m,): the feasible non-dominated rows if any row is
        feasible, else the non-dominated rows among those of the smallest violation.
    """
    if CV is None:
        return nondominated_mask(F)
    best = CV <= 0.0
    if not best.any():
        best = CV.min() == CV if CV.size else best
    mask = np.zeros(F.shape[0], dtype=bool)
    idx = np.flatnonzero(best)
    mask[idx] = nondominated_mask(F[idx])
    return mask


def first_unique_mask(F: np.ndarray) -> np.ndarray:
    """Mask keeping the first occurrence of every distinct row of ``F``.

    Rows compare with ``==`` (so ``-0.0`` equals ``0.0``).
    """
    m = F.shape[0]
    if m <= 1:
        return np.ones(m, dtype=bool)
    order = np.lexsort(F.T[::-1])  # stable: equal rows stay in index order
    Fs = F[order]
    repeat = np.zeros(m, dtype=bool)
    repeat[1:] = np.all(Fs[1:] == Fs[:-1], axis=1)
    mask = np.empty(m, dtype=bool)
    mask[order] = ~repeat
    return mask
