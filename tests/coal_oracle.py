"""coal (the maintained successor of hpp-fcl) as the independent oracle of moik.collision's
distances, shared by tests/collision and tests/solver (the test extra installs coal)."""

from __future__ import annotations

import numpy as np
import pytest

from moik.collision import Box, Capsule, ConvexHull, Sphere
from moik.collision.shapes import Compound

coal = pytest.importorskip("coal")


def coal_shape(s):
    """The coal geometry of a moik shape (a half-space is ``z <= 0`` of its pose; a hull is
    coal's convex hull of its points)."""
    if isinstance(s, ConvexHull):
        points = coal.StdVec_Vec3s()
        for p in s.points:
            points.append(np.array(p, dtype=float))
        return coal.Convex.convexHull(points, False, "")
    r, h, _ = s.sizes
    if isinstance(s, Sphere):
        return coal.Sphere(r)
    if isinstance(s, Capsule):
        return coal.Capsule(r, 2 * h)
    if isinstance(s, Box):
        return coal.Box(*s.size)
    return coal.Halfspace(np.array([0.0, 0.0, 1.0]), 0.0)


def _placed(shape):
    return coal_shape(shape), coal.Transform3s(shape.pose[:3, :3], shape.pose[:3, 3])


def coal_pair_distance(A, B, built: dict | None = None) -> float:
    """coal's signed distance of two placed moik shapes (``built``: coal's geometry of
    shapes already built, by ``id``, filled as they are).

    Asked for a tolerance of 1e-14, coal's GJK answers 0 for some pairs of convex hulls
    that are far apart (measured: two panda mesh pieces 0.47 m apart, hulls of 84 and 60
    vertices, at one placement; at 1e-10 it gives 0.4738...): so the distance of a pair
    is coal's plain (unsigned) GJK at 1e-10 when that finds it apart, and coal's signed
    (GJK then EPA) distance at 1e-14 only for a pair it finds touching.
    """
    built = {} if built is None else built
    for s in (A, B):
        if id(s) not in built:
            built[id(s)] = _placed(s)
    (gA, tA), (gB, tB) = built[id(A)], built[id(B)]
    req = coal.DistanceRequest()
    req.gjk_tolerance = 1e-10
    apart = coal.distance(gA, tA, gB, tB, req, coal.DistanceResult())
    if apart > 0.0:
        return apart
    req.enable_signed_distance = True
    req.gjk_tolerance = req.epa_tolerance = 1e-14
    return coal.distance(gA, tA, gB, tB, req, coal.DistanceResult())


def coal_distances(checker, q) -> np.ndarray:
    """coal's signed distance of every pair the checker checks, at configuration ``q``."""
    placed = dict(checker.world_shapes(q))
    built: dict = {}  # each part's coal geometry built once (qhull), for all its pairs
    out = []
    for a, b in checker.pair_names:  # a compound is measured on its parts (the bound culls)
        parts_a = placed[a].parts if isinstance(placed[a], Compound) else (placed[a],)
        parts_b = placed[b].parts if isinstance(placed[b], Compound) else (placed[b],)
        out.append(min(coal_pair_distance(A, B, built) for A in parts_a for B in parts_b))
    return np.array(out)
