"""pymoo's multi-objective algorithms as registered in moik, for comparisons.

``NSGA2``, ``SMSEMOA`` and ``MOPSO_CD`` are registered unchanged (pymoo 0.6.2
defaults). pymoo's ``MOEAD`` needs reference directions at construction;
:class:`MOEAD` here is pymoo's with a default: when ``ref_dirs`` is None, the
Das-Dennis directions for the problem's number of objectives are built at setup
with the most partitions that give at most ``pop_size`` directions (for two
objectives: ``n_partitions = pop_size - 1``, exactly ``pop_size`` directions).
"""

from __future__ import annotations

from math import comb

import numpy as np
from pymoo.algorithms.moo import moead
from pymoo.util.ref_dirs import get_reference_directions

from moik.algorithms.driver import is_int
from moik.exceptions import ParameterError


def das_dennis_partitions(n_obj: int, pop_size: int) -> int:
    """Largest ``p`` with ``C(p + n_obj - 1, n_obj - 1) <= pop_size`` (at least 1)."""
    p = 1
    while comb(p + 1 + n_obj - 1, n_obj - 1) <= pop_size:
        p += 1
    return p


def default_ref_dirs(n_obj: int, pop_size: int) -> np.ndarray:
    """Das-Dennis reference directions, at most ``pop_size`` of them (see module doc)."""
    return get_reference_directions("das-dennis", n_obj,
                                    n_partitions=das_dennis_partitions(n_obj, pop_size))


class MOEAD(moead.MOEAD):
    """pymoo's MOEA/D with default reference directions (see the module doc).

    Args:
        ref_dirs: Reference directions (n, n_obj), or None for Das-Dennis ones.
        pop_size: Number of directions when ``ref_dirs`` is None, an integer >= 2.
        **kwargs: pymoo ``MOEAD`` options (``n_neighbors``, ``decomposition`` ...).
    """

    def __init__(self, *, ref_dirs: np.ndarray | None = None, pop_size: int = 100, **kwargs):
        if not is_int(pop_size) or pop_size < 2:
            raise ParameterError(f"pop_size must be an integer >= 2, got {pop_size!r}")
        self._default_dirs = ref_dirs is None
        self._n_dirs = int(pop_size)
        dirs = default_ref_dirs(2, self._n_dirs) if ref_dirs is None else ref_dirs
        super().__init__(ref_dirs=dirs, **kwargs)

    def _setup(self, problem, **kwargs) -> None:
        if self._default_dirs and self.ref_dirs.shape[1] != problem.n_obj:
            self.ref_dirs = default_ref_dirs(problem.n_obj, self._n_dirs)
        super()._setup(problem, **kwargs)
