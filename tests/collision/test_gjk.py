"""Compiled GJK lower bounds on hull distances (moik/collision/gjk.py), against coal."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision.gjk import halfspace_distance, hull_distance_bound

coal = pytest.importorskip("coal")


def _coal_hull(P):
    bvh = coal.BVHModelOBBRSS()
    bvh.beginModel(0, len(P))
    bvh.addVertices(np.ascontiguousarray(P))
    bvh.endModel()
    bvh.buildConvexHull(False, "Qt")
    return bvh.convex


@settings(max_examples=60, deadline=None, derandomize=True)
@given(seed=st.integers(0, 100_000), na=st.integers(4, 40), nb=st.integers(4, 40),
       ra=st.floats(0.0, 0.05), rb=st.floats(0.0, 0.05))
def test_a_lower_bound_that_is_tight_where_the_hulls_are_apart(seed, na, nb, ra, rb):
    rng = np.random.default_rng(seed)
    A = rng.normal(size=(na, 3)) * rng.uniform(0.02, 0.3, 3)
    B = rng.normal(size=(nb, 3)) * rng.uniform(0.02, 0.3, 3) + rng.normal(size=3) * 0.4
    bound = hull_distance_bound(A, ra, B, rb)
    req = coal.DistanceRequest()
    d = coal.distance(_coal_hull(A), coal.Transform3s(), _coal_hull(B), coal.Transform3s(), req,
                      coal.DistanceResult())
    if bound == -np.inf:
        assert d <= 1e-6  # not separated: coal finds them touching too
    else:
        assert bound <= d - ra - rb + 1e-12  # never above the distance
        assert bound >= d - ra - rb - 1e-6  # and converged to it


def test_touching_and_point_sets():
    cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    assert hull_distance_bound(cube, 0.0, cube + 0.5, 0.0) == -np.inf
    assert hull_distance_bound(cube, 0.0, cube + [3.0, 0, 0], 0.0) == pytest.approx(2.0, abs=1e-9)
    point = np.array([[0.0, 0.0, 5.0]])
    assert hull_distance_bound(cube, 0.1, point, 0.2) == pytest.approx(4.0 - 0.3, abs=1e-9)


def test_half_space_distance_is_signed():
    cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    up = np.array([0.0, 0.0, 1.0])
    assert halfspace_distance(cube + [0, 0, 0.3], 0.0, up, 0.0) == pytest.approx(0.3)
    assert halfspace_distance(cube - [0, 0, 0.2], 0.05, up, 0.0) == pytest.approx(-0.25)
