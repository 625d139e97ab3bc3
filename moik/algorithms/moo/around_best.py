"""The move around the best solution shared by MSSA (salp leaders) and MOMVO (wormholes).

The salp-chain leader (SSA Eq. 3.1, Mirjalili et al. 2017,
DOI 10.1016/j.advengsoft.2017.07.002) and the wormhole (MVO Eq. 3.2, Mirjalili,
Mirjalili & Hatamlou 2016, DOI 10.1007/s00521-015-1870-7) are the same move:
a coordinate jumps to the best solution plus or minus a scaled random point of
the box, ``best_j +/- c ((ub_j - lb_j) r + lb_j)``. The ``+ lb_j`` is printed in
both papers and kept in both reference codes (it shifts the step when
``lb != 0``); it is kept here too.
"""

from __future__ import annotations

import numpy as np


def around_best(best: np.ndarray, scale: float, xl: np.ndarray, xu: np.ndarray,
                shape: tuple[int, int], *, rng: np.random.Generator) -> np.ndarray:
    """``best +/- scale ((xu - xl) r + xl)`` per coordinate, ``+`` when a second draw < 0.5.

    Args:
        best: The guiding point, shape (d,) or broadcastable to ``shape``.
        scale: ``c1`` of SSA Eq. 3.2 or ``TDR`` of MVO Eq. 3.4.
        xl: Lower bounds (d,).
        xu: Upper bounds (d,).
        shape: Output shape (n, d).
        rng: Random generator (draws ``r`` then the sign, each of ``shape``).

    Returns:
        Array of ``shape``.
    """
    step = scale * ((xu - xl) * rng.random(shape) + xl)
    return np.where(rng.random(shape) < 0.5, best + step, best - step)
