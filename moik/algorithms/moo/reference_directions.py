"""Default Das-Dennis reference directions for the decomposition-based MO algorithms.

Das & Dennis, "Normal-Boundary Intersection", SIAM J. Optim. 8(3), 631-657 (1998),
as built by pymoo's ``get_reference_directions("das-dennis", ...)``: the directions
with ``n_partitions`` steps per objective on the unit simplex, ``C(p + m - 1, m - 1)``
of them for ``m`` objectives and ``p`` partitions. MOEA/D and MOMPA use the most
partitions that give at most ``pop_size`` directions (two objectives:
``p = pop_size - 1``, exactly ``pop_size`` directions).
"""

from __future__ import annotations

from math import comb

import numpy as np
from pymoo.util.ref_dirs import get_reference_directions

from moik._validate import integer
from moik.exceptions import ParameterError


def das_dennis_partitions(n_obj: int, pop_size: int) -> int:
    """Largest ``p`` with ``C(p + n_obj - 1, n_obj - 1) <= pop_size`` (at least 1).

    Raises:
        ParameterError: For ``n_obj < 2`` (one objective has one direction for every
            ``p``: there is no largest) or ``pop_size < 1``.
    """
    if integer("n_obj", n_obj) < 2:
        raise ParameterError(f"reference directions need n_obj >= 2 objectives, got {n_obj}")
    pop_size = integer("pop_size", pop_size, minimum=1)
    p = 1
    while comb(p + 1 + n_obj - 1, n_obj - 1) <= pop_size:
        p += 1
    return p


def default_ref_dirs(n_obj: int, pop_size: int) -> np.ndarray:
    """Das-Dennis reference directions, at most ``pop_size`` of them (see module doc).

    Raises:
        ParameterError: As :func:`das_dennis_partitions`.
    """
    return get_reference_directions("das-dennis", n_obj,
                                    n_partitions=das_dennis_partitions(n_obj, pop_size))
