"""coal (the maintained successor of hpp-fcl) as the independent oracle of moik.collision's
distances, shared by tests/collision and tests/solver (the test extra installs coal)."""

from __future__ import annotations

import numpy as np
import pytest

from moik.collision import Box, Capsule, Sphere

coal = pytest.importorskip("coal")


def coal_shape(s):
    """The coal geometry of a moik shape (a half-space is ``z <= 0`` of its pose)."""
    r, h, _ = s.sizes
    if isinstance(s, Sphere):
        return coal.Sphere(r)
    if isinstance(s, Capsule):
        return coal.Capsule(r, 2 * h)
    if isinstance(s, Box):
        return coal.Box(*s.size)
    return coal.Halfspace(np.array([0.0, 0.0, 1.0]), 0.0)


def coal_distances(checker, q) -> np.ndarray:
    """coal's signed distance of every pair the checker checks, at configuration ``q``."""
    placed = dict(checker.world_shapes(q))
    req = coal.DistanceRequest()
    req.enable_signed_distance = True
    req.gjk_tolerance = req.epa_tolerance = 1e-14
    out = []
    for a, b in checker.pair_names:
        A, B = placed[a], placed[b]
        out.append(coal.distance(coal_shape(A), coal.Transform3s(A.pose[:3, :3], A.pose[:3, 3]),
                                 coal_shape(B), coal.Transform3s(B.pose[:3, :3], B.pose[:3, 3]),
                                 req, coal.DistanceResult()))
    return np.array(out)
