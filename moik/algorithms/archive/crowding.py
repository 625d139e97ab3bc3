"""Crowding-radius archive of MOEOSMA and of Mirjalili's MSSA/MOALO/MODA/MOMVO.

Source: Yin, Luo, Zhou, Zhou, Zhu (2022), "An equilibrium optimizer slime mould
algorithm for inverse kinematics of the 7-DOF robotic manipulator", Sci. Rep.
12, 9421, https://doi.org/10.1038/s41598-022-13516-3 -- Fig. 2, Eqs. 11, 19, 20,
Algorithm 2 -- and the authors' MATLAB code (Shihong-Yin/MOEOSMA:
UpdateArchive.m, RankingProcess.m, HandleFullArchive.m, MOEOSMA.m).

Rules (``m`` members, ``M`` objectives):

- Merge, keep the non-dominated rows, drop duplicate objective rows (see
  :mod:`moik.algorithms.archive.base`).
- Crowding count ("congestion level", Fig. 2) of member i = number of members j,
  i itself included, with ``|F_jk - F_ik| < dr_k`` for every objective k, where
  ``dr = (max F - min F) / radius_divisor`` over the current members. Eq. 19
  uses ``radius_divisor = capacity`` (MOEOSMA); Mirjalili's MSSA (Mirjalili et
  al. 2017, https://doi.org/10.1016/j.advengsoft.2017.07.002), MOALO, MODA and
  MOMVO use 20.
- Overflow (Eq. 20): remove ``m - capacity`` members by roulette wheel with
  probability ``N_i / sum(N)``, then recount (Algorithm 2, step 5).
- Leaders: ``"min-count"`` (MOEOSMA's equilibrium pool) draws uniformly among
  the members with the smallest count; ``"roulette"`` (Mirjalili) draws by
  roulette on ``1 / count``.

Decisions and deviations:

- Dominance follows Eq. 11 (ordinary Pareto dominance). The authors'
  UpdateArchive.m uses strict dominance (``all(F_j < F_i)``), which would keep
  weakly dominated rows (equal in one objective, worse in another).
- Removal counts: Eq. 20 defines the probabilities once, over the
  non-dominated set, and HandleFullArchive.m does the same: it deletes the
  chosen member's entry from the count vector but does not recompute the
  counts of the others between removals (Mirjalili's HandleFullArchive.m
  behaves alike). That is the default, implemented as weighted sampling
  without replacement, which has the same distribution as repeated roulette
  with the drawn entry deleted. ``recount=True`` instead recomputes ``dr`` and
  the counts after each single removal (slower, O(excess * m^2 * M)).
- Degenerate radius: when all members share the same value of objective k,
  ``dr_k = 0``. RankingProcess.m then counts nobody (not even the member
  itself), giving all-zero counts, a removal that always picks the first row
  and a leader pool of every member. Here an objective with ``dr_k = 0`` does
  not separate anyone (it is ignored in the test), so every count is >= 1 and
  a single member has count 1.
- The radius test is evaluated as ``F_ik - dr_k < F_jk < F_ik + dr_k``
  (identical to ``|F_jk - F_ik| < dr_k`` in exact arithmetic, it can differ in
  the last bit), so that two-objective fronts are counted by binary search.
- Random streams differ from MATLAB's; only the distributions match.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit, kernel_array
from moik.algorithms.archive.base import ArchiveBase, check_count, roulette
from moik.algorithms.mechanics import stable_order
from moik.exceptions import UnknownNameError

LEADER_RULES = ("min-count", "roulette")


def crowding_radius(F: np.ndarray, divisor: float) -> np.ndarray:
    """Radius ``dr = (max F - min F) / divisor`` per objective (Eq. 19).

    Args:
        F: Objective values, shape (m, M) with m >= 1.
        divisor: The archive capacity (MOEOSMA) or 20 (Mirjalili).

    Returns:
        Array of shape (M,).
    """
    return (F.max(axis=0) - F.min(axis=0)) / divisor


@jit
def _radius_2d(F: np.ndarray, divisor: float) -> np.ndarray:
    """:func:`crowding_radius` of two objectives, compiled (loops: numba's ``max``/``min``
    of a column compile several helpers; a NaN gives NaN, as numpy's do)."""
    dr = np.empty(2)
    for k in range(2):
        lo = hi = F[0, k]
        for i in range(F.shape[0]):
            v = F[i, k]
            if np.isnan(v):
                lo = hi = v
                break
            if v > hi:
                hi = v
            if v < lo:
                lo = v
        dr[k] = (hi - lo) / divisor
    return dr


def crowding_counts(F: np.ndarray, divisor: float) -> np.ndarray:
    """Crowding count of every row of ``F`` (Fig. 2, RankingProcess.m).

    The test ``|F_jk - F_ik| < dr_k`` is evaluated as
    ``F_ik - dr_k < F_jk < F_ik + dr_k`` (identical in exact arithmetic), which
    lets a mutually non-dominated two-objective set be counted by binary
    search in O(m log m) with exactly the pairwise result.

    Args:
        F: Objective values, shape (m, M).
        divisor: Divisor of the objective ranges giving the radius (Eq. 19).

    Returns:
        Integer array (m,): for row i, the number of rows j (i included) with
        ``|F_jk - F_ik| < dr_k`` for every k, at least 1; objectives with ``dr_k = 0``
        are ignored.
    """
    m = F.shape[0]
    if m == 0:
        return np.zeros(0, dtype=np.int64)
    # a member always counts itself, also where F +/- dr rounds back to F (a radius
    # below the values' last bit), so that 1 / count stays finite
    if F.shape[1] == 2 and m > 1:
        counts = _crowding_counts_front_2d(kernel_array(F), _radius_2d(F, float(divisor)))
        if counts.size == m:
            return counts
    return np.maximum(_crowding_counts_pairwise(F, crowding_radius(F, divisor)), 1)


def _crowding_counts_pairwise(F: np.ndarray, dr: np.ndarray) -> np.ndarray:
    """Counts from the (m, m) pairwise radius test, any number of objectives."""
    m = F.shape[0]
    within = np.ones((m, m), dtype=bool)
    for k in np.flatnonzero(dr > 0):  # loop over objectives only
        col = F[:, k]
        within &= (col[None, :] > (col - dr[k])[:, None]) & (col[None, :] < (col + dr[k])[:, None])
    return np.count_nonzero(within, axis=1).astype(np.int64)


@jit
def sorted_positions(a: np.ndarray, v: np.ndarray, right: bool) -> np.ndarray:
    """``np.searchsorted(a, v, side="right" if right else "left")`` for an ascending
    finite ``a`` (bisection; numba's own searchsorted takes seconds to compile). Callers
    pass ``right`` as ``np.bool_``: one compiled version for both sides, not one per
    literal."""
    out = np.empty(v.size, np.int64)
    for k in range(v.size):
        lo, hi, x = 0, a.size, v[k]
        while lo < hi:
            mid = (lo + hi) // 2
            if a[mid] < x or (right and a[mid] == x):
                lo = mid + 1
            else:
                hi = mid
        out[k] = lo
    return out


@jit
def _crowding_counts_front_2d(F: np.ndarray, dr: np.ndarray) -> np.ndarray:
    """Counts of a two-objective front by binary search (compiled); empty if not a front.

    Sorted by f1 ascending, a mutually non-dominated set without duplicates has
    f2 strictly descending, so both radius windows are index intervals and the
    count is the length of their intersection (at least 1, see :func:`crowding_counts`).
    A set that is not such a front gives an empty array (the caller then counts
    pairwise).
    """
    m = F.shape[0]
    f1, f2 = np.empty(m), np.empty(m)
    for k in range(m):
        f1[k] = F[k, 0]
    order = stable_order(f1, np.empty(m, np.int64))
    for k in range(m):  # loops, not F[order, 0] or f1 - dr[0]: less code to compile
        f1[k], f2[k] = F[order[k], 0], F[order[k], 1]
    for k in range(1, m):
        if not (f1[k] > f1[k - 1] and f2[k] < f2[k - 1]):
            return np.empty(0, dtype=np.int64)
    lo, hi = np.empty(m, dtype=np.int64), np.empty(m, dtype=np.int64)
    for k in range(m):
        lo[k], hi[k] = 0, m
    v = np.empty(m)
    if dr[0] > 0:
        for k in range(m):
            v[k] = f1[k] - dr[0]
        lo = sorted_positions(f1, v, np.bool_(True))
        for k in range(m):
            v[k] = f1[k] + dr[0]
        hi = sorted_positions(f1, v, np.bool_(False))
    if dr[1] > 0:
        g = np.empty(m)
        for k in range(m):  # ascending; -(a - b) is exact, so the thresholds match the
            g[k] = -f2[k]  # pairwise test
            v[k] = -(f2[k] + dr[1])
        low = sorted_positions(g, v, np.bool_(True))
        for k in range(m):
            v[k] = -(f2[k] - dr[1])
        high = sorted_positions(g, v, np.bool_(False))
        for k in range(m):
            if low[k] > lo[k]:
                lo[k] = low[k]
            if high[k] < hi[k]:
                hi[k] = high[k]
    counts = np.empty(m, dtype=np.int64)
    for k in range(m):  # a loop, not counts[order] = ...: no shape-error code to compile
        counts[order[k]] = hi[k] - lo[k] if hi[k] - lo[k] > 1 else 1
    return counts


class CrowdingArchive(ArchiveBase):
    """External archive with crowding-radius counts (MOEOSMA, Mirjalili's MO codes).

    Args:
        capacity: Maximum number of members (the paper: population size, 100).
        radius_divisor: Divisor of the objective ranges giving the radius ``dr``;
            ``None`` (default) means ``capacity`` as in Eq. 19; Mirjalili's
            codes use 20.
        leader: ``"min-count"`` (uniform among the least crowded members,
            MOEOSMA) or ``"roulette"`` (roulette on 1/count, Mirjalili).
        recount: Recompute the counts after each single removal instead of
            using the counts of the merged set (the paper and code).

    Attributes:
        counts: Crowding counts of the current members, shape (m,).

    Example:
        >>> rng = np.random.default_rng(0)
        >>> archive = CrowdingArchive(2)
        >>> archive.add(np.zeros((3, 1)), np.array([[0.0, 2.0], [1.0, 1.0], [2.0, 0.0]]), rng=rng)
        >>> len(archive)
        2
    """

    def __init__(
        self,
        capacity: int,
        *,
        radius_divisor: int | None = None,
        leader: str = "min-count",
        recount: bool = False,
    ):
        super().__init__(capacity)
        self.radius_divisor = (
            self.capacity
            if radius_divisor is None
            else check_count("radius_divisor", radius_divisor, 1)
        )
        if leader not in LEADER_RULES:
            raise UnknownNameError("leader rule", leader, LEADER_RULES)
        self.leader = leader
        self.recount = bool(recount)
        self.counts = np.zeros(0, dtype=np.int64)

    @classmethod
    def moeosma(cls, capacity: int) -> CrowdingArchive:
        """Archive as in MOEOSMA: ``dr = range / capacity``, min-count leaders."""
        return cls(capacity)

    @classmethod
    def mirjalili(cls, capacity: int) -> CrowdingArchive:
        """Archive as in MSSA/MOALO/MODA/MOMVO: ``dr = range / 20``, roulette on 1/count."""
        return cls(capacity, radius_divisor=20, leader="roulette")

    def _update(self, rng: np.random.Generator) -> None:
        excess = len(self) - self.capacity
        if excess > 0 and self.recount:
            for _ in range(excess):
                counts = crowding_counts(self._F, self.radius_divisor)
                self._remove(roulette(counts, 1, rng))
        elif excess > 0:
            counts = crowding_counts(self._F, self.radius_divisor)
            drop = rng.choice(len(self), size=excess, replace=False, p=counts / counts.sum())
            self._remove(drop)
        self.counts = crowding_counts(self._F, self.radius_divisor)
        self.counts.flags.writeable = False

    def leaders(self, k: int, *, rng: np.random.Generator) -> np.ndarray:
        """Draw ``k`` leader indices (with replacement) from the members.

        Args:
            k: Number of leaders, e.g. one per search agent.
            rng: Random generator.

        Returns:
            Integer array (k,) of row indices into :attr:`X` / :attr:`F`.

        Raises:
            ShapeError: If the archive is empty.
            ParameterError: If ``k`` is not an integer >= 0.
        """
        k = self._check_leaders(k)
        if self.leader == "min-count":
            pool = np.flatnonzero(self.counts == self.counts.min())
            return pool[rng.integers(pool.size, size=k)]
        return roulette(1.0 / self.counts, k, rng)

    def __repr__(self) -> str:
        return (
            f"CrowdingArchive(capacity={self.capacity}, radius_divisor={self.radius_divisor}, "
            f"leader={self.leader!r}, recount={self.recount}, members={len(self)})"
        )
