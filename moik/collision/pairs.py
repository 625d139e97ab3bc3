"""A pair of shapes: the broad-phase bound and the dispatch to its distance kernel
(:mod:`moik.collision.distance`, :mod:`moik.collision.box_distance`)."""

from __future__ import annotations

import math

from moik._jit import jit
from moik.collision.box_distance import box_box, box_halfspace, capsule_box
from moik.collision.distance import (
    BOX,
    CAPSULE,
    HALFSPACE,
    HULL,
    SPHERE,
    capsule_capsule,
    capsule_halfspace,
)


@jit
def _bounding_radius(kinds, sizes, k):
    """Radius of the sphere about shape ``k``'s origin that holds it (not a half-space)."""
    if kinds[k] == SPHERE:
        return sizes[k, 0]
    if kinds[k] == CAPSULE:
        return sizes[k, 0] + sizes[k, 1]
    if kinds[k] == HULL:
        return sizes[k, 1]  # (hull index, bounding radius, 0)
    return math.sqrt(sizes[k, 0] ** 2 + sizes[k, 1] ** 2 + sizes[k, 2] ** 2)


@jit
def pair_bound(kinds, W, sizes, a, b):
    """A lower bound on the signed distance of shapes ``a`` and ``b`` (kinds ``(m,)``, world
    poses ``W (m, 4, 4)``, sizes ``(m, 3)``): bounding spheres, or the plane distance of
    the other shape's sphere for a half-space (the module doc). Scalar reads only (no
    array views: this runs for every pair of every query)."""
    if kinds[a] == HALFSPACE or kinds[b] == HALFSPACE:
        h, o = (a, b) if kinds[a] == HALFSPACE else (b, a)
        return (W[h, 0, 2] * (W[o, 0, 3] - W[h, 0, 3]) + W[h, 1, 2] * (W[o, 1, 3] - W[h, 1, 3])
                + W[h, 2, 2] * (W[o, 2, 3] - W[h, 2, 3])) - _bounding_radius(kinds, sizes, o)
    dx, dy, dz = W[b, 0, 3] - W[a, 0, 3], W[b, 1, 3] - W[a, 1, 3], W[b, 2, 3] - W[a, 2, 3]
    return (math.sqrt(dx * dx + dy * dy + dz * dz) - _bounding_radius(kinds, sizes, a)
            - _bounding_radius(kinds, sizes, b))


@jit
def _ordered_pair(kA, PA, sA, kB, PB, sB):
    """:func:`pair_distance` for ``kA <= kB``."""
    if kB <= CAPSULE:
        return capsule_capsule(PA, sA, PB, sB)
    if kB == BOX:
        if kA == BOX:
            return box_box(PA, sA, PB, sB)
        return capsule_box(PA, sA, PB, sB)
    if kA <= CAPSULE:
        return capsule_halfspace(PA, sA, PB)
    if kA == BOX:
        return box_halfspace(PA, sA, PB)
    nan = math.nan
    return nan, nan, nan, nan, nan, nan, nan, nan, nan, nan


@jit
def pair_distance(kA, PA, sA, kB, PB, sB):
    """Signed distance, normal and witnesses of any supported pair (see the module doc).

    Kinds are :data:`SPHERE`, :data:`CAPSULE`, :data:`BOX`, :data:`HALFSPACE`; a pair of
    half-spaces is not a pair moik evaluates (NaN; the models refuse it before).
    """
    if kA <= kB:
        return _ordered_pair(kA, PA, sA, kB, PB, sB)
    d, nx, ny, nz, bx, by, bz, ax, ay, az = _ordered_pair(kB, PB, sB, kA, PA, sA)
    return d, -nx, -ny, -nz, ax, ay, az, bx, by, bz
