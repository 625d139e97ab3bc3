"""External archives of non-dominated solutions for the multi-objective algorithms.

- :class:`CrowdingArchive`: crowding-radius counts (MOEOSMA; Mirjalili's MSSA,
  MOALO, MODA, MOMVO via :meth:`CrowdingArchive.mirjalili`).
- :class:`GridArchive`: adaptive hypercube grid (MOPSO, MOGWO via
  :meth:`GridArchive.mopso` / :meth:`GridArchive.mogwo`).

Both keep ``X`` (m, n_var) and ``F`` (m, n_obj) arrays, merge with
``add(X, F, rng=rng)`` and draw leader row indices with ``leaders(k, rng=rng)``.
"""

from moik.algorithms.archive.base import ArchiveBase
from moik.algorithms.archive.crowding import CrowdingArchive, crowding_counts, crowding_radius
from moik.algorithms.archive.fronts import (
    constrained_nondominated_mask,
    first_unique_mask,
    nondominated_mask,
)
from moik.algorithms.archive.grid import GridArchive, grid_bounds, grid_index

__all__ = [
    "ArchiveBase",
    "CrowdingArchive",
    "GridArchive",
    "constrained_nondominated_mask",
    "crowding_counts",
    "crowding_radius",
    "first_unique_mask",
    "grid_bounds",
    "grid_index",
    "nondominated_mask",
]
