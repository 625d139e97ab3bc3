"""Adaptive hypercube-grid archive of MOPSO and MOGWO.

Sources:

- Coello Coello, Pulido, Lechuga (2004), "Handling multiple objectives with
  particle swarm optimization", IEEE Trans. Evol. Comput. 8(3), 256-279,
  https://doi.org/10.1109/TEVC.2004.826067 (adaptive grid, Section III).
- Mirjalili, Saremi, Mirjalili, Coelho (2016), "Multi-objective grey wolf
  optimizer", Expert Syst. Appl. 47, 106-119,
  https://doi.org/10.1016/j.eswa.2015.10.039 (Section 3.1).
- Parameters from the EOSMA paper's Table 4 (Yin et al. 2022,
  https://doi.org/10.1038/s41598-022-13516-3): MOPSO 7 grids, inflation 0.1,
  beta 2, gamma 2; MOGWO 10 grids, inflation 0.1, beta 4, gamma 2.

Rules (``M`` objectives):

- Merge, keep the non-dominated rows, drop duplicate objective rows (see
  :mod:`moik.algorithms.archive.base`).
- Grid: per objective, the members' range ``[min, max]`` inflated by
  ``inflation * (max - min)`` on both sides, cut into ``n_grid`` equal
  intervals; a value on an interior edge belongs to the upper interval. The
  grid index of a member is its vector of interval numbers (0-based).
- Overflow: remove members one at a time; each removal picks an occupied cell
  with probability proportional to ``exp(gamma * n_c)`` (``n_c`` = members in
  the cell, updated after each removal), then a uniform member of that cell.
- Leaders: an occupied cell with probability proportional to
  ``exp(-beta * n_c)``, then a uniform member of that cell.

Decisions and deviations:

- Selection pressures follow the reference MATLAB implementations that the
  EOSMA paper's parameter names come from: ``pressure="exp"`` weighs cells by
  ``exp(-beta n)`` / ``exp(gamma n)`` (Yarpiz MOPSO by M. K. Heris, the MOPSO
  preset); ``pressure="power"`` by ``n**(-beta)`` / ``n**gamma`` (Mirjalili's
  MOGWO code, SelectLeader.m and DeleteFromRep.m, the MOGWO preset; the MOGWO
  paper's ``P_i = c / N_i`` is ``beta = 1``). The 2004 paper states the leader
  fitness as ``10 / n_c`` and replaces members of the most crowded cell;
  ``beta``/``gamma`` generalize both.
- The reference codes add a -inf and a +inf interval at the ends; members never
  fall there (the grid spans their inflated range), so they are omitted. When
  all members share one objective value the range is zero and every member is
  in interval 0 of that objective.
- The grid is built over the merged non-dominated set for truncation and
  rebuilt over the surviving members afterwards (as MOGWO's code does; Yarpiz
  MOPSO keeps the pre-truncation grid), so :attr:`grid_index` always describes
  the current members.
- Cells are identified by the whole index vector (``np.unique`` rows), not by
  the reference codes' scalar formula, which can map two cells to one number.
- Duplicate objective rows are removed (the reference codes keep them).
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.archive.base import ArchiveBase, check_count, check_positive, roulette
from moik.exceptions import ParameterError

PRESSURES = ("exp", "power")


def grid_bounds(F: np.ndarray, inflation: float) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper grid bounds: the range of ``F`` inflated on both sides.

    Args:
        F: Objective values, shape (m, M) with m >= 1.
        inflation: Fraction ``alpha`` of the range added below and above.

    Returns:
        Two arrays of shape (M,).
    """
    fmin, fmax = F.min(axis=0), F.max(axis=0)
    pad = inflation * (fmax - fmin)
    return fmin - pad, fmax + pad


def grid_index(F: np.ndarray, lower: np.ndarray, upper: np.ndarray, n_grid: int) -> np.ndarray:
    """Interval number of every objective value on an ``n_grid`` grid.

    Args:
        F: Objective values, shape (m, M).
        lower: Lower grid bounds, shape (M,).
        upper: Upper grid bounds, shape (M,).
        n_grid: Number of intervals per objective.

    Returns:
        Integer array (m, M) with entries in ``0 .. n_grid - 1``; a value on an
        interior edge gets the upper interval, values outside are clipped, and
        an objective with ``upper <= lower`` (zero range) gives 0.
    """
    index = np.empty(F.shape, dtype=np.int64)
    for k in range(F.shape[1]):  # loop over objectives only
        if upper[k] <= lower[k]:  # zero range: a single interval holds everyone
            index[:, k] = 0
            continue
        edges = np.linspace(lower[k], upper[k], n_grid + 1)[1:-1]
        index[:, k] = np.searchsorted(edges, F[:, k], side="right")
    return index


class GridArchive(ArchiveBase):
    """External archive with an adaptive hypercube grid (MOPSO, MOGWO).

    Args:
        capacity: Maximum number of members (the EOSMA paper: 100).
        n_grid: Intervals per objective (MOPSO 7, MOGWO 10).
        inflation: Grid inflation rate ``alpha`` (0.1 in both).
        beta: Leader selection pressure; larger favours emptier cells more
            (MOPSO 2, MOGWO 4).
        gamma: Deletion selection pressure; larger favours crowded cells more
            (2 in both).
        pressure: ``"exp"`` (weights ``exp(-beta n)``, ``exp(gamma n)``; MOPSO)
            or ``"power"`` (``n**-beta``, ``n**gamma``; MOGWO).

    Attributes:
        lower: Lower grid bounds, shape (M,).
        upper: Upper grid bounds, shape (M,).
        grid_index: Interval numbers of the members, shape (m, M).
        cells: Occupied-cell id of each member, shape (m,); ids are
            ``0 .. n_cells - 1`` in lexicographic order of the grid index.
        cell_counts: Number of members in each occupied cell, shape (n_cells,).
    """

    def __init__(
        self,
        capacity: int,
        *,
        n_grid: int = 7,
        inflation: float = 0.1,
        beta: float = 2.0,
        gamma: float = 2.0,
        pressure: str = "exp",
    ):
        super().__init__(capacity)
        if pressure not in PRESSURES:
            raise ParameterError(f"pressure must be one of {', '.join(PRESSURES)}; "
                                 f"got {pressure!r}")
        self.pressure = pressure
        self.n_grid = check_count("n_grid", n_grid, 1)
        self.inflation = check_positive("inflation", inflation, allow_zero=True)
        self.beta = check_positive("beta", beta)
        self.gamma = check_positive("gamma", gamma)
        self._set_grid()

    @classmethod
    def mopso(cls, capacity: int) -> GridArchive:
        """MOPSO preset (EOSMA Table 4): 7 grids, inflation 0.1, beta 2, gamma 2."""
        return cls(capacity, n_grid=7, inflation=0.1, beta=2.0, gamma=2.0)

    @classmethod
    def mogwo(cls, capacity: int) -> GridArchive:
        """MOGWO preset (Mirjalili 2016; EOSMA Table 4): 10 grids, 0.1, beta 4, gamma 2, power."""
        return cls(capacity, n_grid=10, inflation=0.1, beta=4.0, gamma=2.0, pressure="power")

    def leader_weights(self, counts: np.ndarray) -> np.ndarray:
        """Leader roulette weights of cells holding ``counts >= 1`` members (emptier: heavier)."""
        if self.pressure == "power":
            return counts.astype(float) ** -self.beta
        return np.exp(-self.beta * (counts - counts.min()))

    def _set_grid(self) -> None:
        """Build the grid over the current members and locate them in it."""
        n_obj = self._F.shape[1]
        if len(self) == 0:
            self.lower = self.upper = np.zeros(n_obj)
            self.grid_index = np.zeros((0, n_obj), dtype=np.int64)
            self.cells = np.zeros(0, dtype=np.int64)
            self.cell_counts = np.zeros(0, dtype=np.int64)
            return
        self.lower, self.upper = grid_bounds(self._F, self.inflation)
        self.grid_index = grid_index(self._F, self.lower, self.upper, self.n_grid)
        if n_obj * np.log2(self.n_grid) < 62:  # a scalar cell number fits in int64
            keys = np.ravel_multi_index(self.grid_index.T, (self.n_grid,) * n_obj)
            _, cells, self.cell_counts = np.unique(keys, return_inverse=True, return_counts=True)
        else:
            _, cells, self.cell_counts = np.unique(
                self.grid_index, axis=0, return_inverse=True, return_counts=True
            )
        self.cells = cells.reshape(-1)

    def _update(self, rng: np.random.Generator) -> None:
        self._set_grid()
        excess = len(self) - self.capacity
        if excess > 0:
            counts = self.cell_counts.copy()
            alive = np.ones(len(self), dtype=bool)
            u = rng.random((excess, 2))
            for e in range(excess):
                occupied = counts > 0
                weights = np.zeros(counts.size)
                n_occ = counts[occupied]
                weights[occupied] = (n_occ.astype(float) / n_occ.max()) ** self.gamma if (
                    self.pressure == "power") else np.exp(self.gamma * (n_occ - n_occ.max()))
                cdf = np.cumsum(weights)
                cell = min(
                    int(np.searchsorted(cdf, u[e, 0] * cdf[-1], side="right")), counts.size - 1
                )
                members = np.flatnonzero(alive & (self.cells == cell))
                alive[members[min(int(u[e, 1] * members.size), members.size - 1)]] = False
                counts[cell] -= 1
            self._remove(np.flatnonzero(~alive))
            self._set_grid()

    def leaders(self, k: int, *, rng: np.random.Generator) -> np.ndarray:
        """Draw ``k`` leader indices (with replacement): emptier cells are likelier.

        Args:
            k: Number of leaders, e.g. one per particle.
            rng: Random generator.

        Returns:
            Integer array (k,) of row indices into :attr:`X` / :attr:`F`.

        Raises:
            ShapeError: If the archive is empty.
            ParameterError: If ``k`` is not an integer >= 0.
        """
        k = self._check_leaders(k)
        counts = self.cell_counts
        cell = roulette(self.leader_weights(counts), k, rng)
        order = np.argsort(self.cells, kind="stable")
        starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
        offset = np.minimum((rng.random(k) * counts[cell]).astype(np.int64), counts[cell] - 1)
        return order[starts[cell] + offset]

    def __repr__(self) -> str:
        return (
            f"GridArchive(capacity={self.capacity}, n_grid={self.n_grid}, "
            f"inflation={self.inflation}, beta={self.beta}, gamma={self.gamma}, "
            f"pressure={self.pressure!r}, "
            f"members={len(self)})"
        )
