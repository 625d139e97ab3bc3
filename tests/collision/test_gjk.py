"""moik/collision/gjk.py: distances of convex hulls, against coal (the independent oracle)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision import Box, Capsule, ConvexHull, HalfSpace, Sphere
from moik.collision.shapes import Compound
from moik.exceptions import MoikError
from moik.robots import get_robot
from tests.world_pair import world_pair

coal = pytest.importorskip("coal")
ROBOT = get_robot("planar2")


def _rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


def _pose(rng, spread=0.3):
    T = np.eye(4)
    T[:3, :3] = _rotation(rng)
    T[:3, 3] = rng.uniform(-spread, spread, 3)
    return T


def _coal_geometry(s):
    if isinstance(s, ConvexHull):
        v = coal.StdVec_Vec3s()
        for p in s.points:
            v.append(np.array(p, dtype=float))
        return coal.Convex.convexHull(v, False, "")
    if isinstance(s, Sphere):
        return coal.Sphere(s.radius)
    if isinstance(s, Capsule):
        return coal.Capsule(s.radius, s.length)
    if isinstance(s, Box):
        return coal.Box(*s.size)
    return coal.Halfspace(np.array([0.0, 0.0, 1.0]), 0.0)


def _coal_distance(A, B) -> float:
    req = coal.DistanceRequest()
    req.enable_signed_distance = True
    req.gjk_tolerance = req.epa_tolerance = 1e-14
    return coal.distance(_coal_geometry(A), coal.Transform3s(A.pose[:3, :3], A.pose[:3, 3]),
                         _coal_geometry(B), coal.Transform3s(B.pose[:3, :3], B.pose[:3, 3]),
                         req, coal.DistanceResult())


def _other(kind: str, rng):
    pose = _pose(rng)
    if kind == "sphere":
        return Sphere(radius=rng.uniform(0.01, 0.1), pose=pose)
    if kind == "capsule":
        return Capsule(radius=rng.uniform(0.01, 0.1), length=rng.uniform(0.0, 0.3), pose=pose)
    if kind == "box":
        return Box(size=rng.uniform(0.02, 0.3, 3), pose=pose)
    if kind == "halfspace":
        return HalfSpace(pose=_pose(rng, spread=0.5))
    return ConvexHull(points=rng.normal(size=(rng.integers(4, 40), 3)) * 0.08, pose=pose)


@settings(max_examples=120, derandomize=True, deadline=None)
@given(st.sampled_from(["sphere", "capsule", "box", "hull", "halfspace"]),
       st.integers(0, 2**31 - 1), st.booleans())
def test_hull_distances_match_coal(kind, seed, swap):
    """Separated: equal to coal's distance (1e-9); penetrating: negative and not above coal's
    signed distance (the overlap along the centres bounds the depth from above)."""
    rng = np.random.default_rng(seed)
    hull = ConvexHull(points=rng.normal(size=(rng.integers(4, 60), 3)) * 0.1, pose=_pose(rng))
    other = _other(kind, rng)
    A, B = (other, hull) if swap else (hull, other)
    d, _ = world_pair(A, B)
    ref = _coal_distance(A, B)
    if ref > 1e-9:
        assert d == pytest.approx(ref, abs=1e-9)
    elif ref < -1e-9:  # penetrating: never reported farther than coal's signed distance
        assert d < 0 and d <= ref + 1e-9


def test_hull_holds_its_points_and_drops_inner_ones():
    rng = np.random.default_rng(3)
    corners = np.array([[x, y, z] for x in (0, 1) for y in (0, 2) for z in (0, 3)], dtype=float)
    inner = rng.uniform(0.1, 0.9, (50, 3)) * [1, 2, 3]
    hull = ConvexHull(points=np.vstack([corners, inner]))
    assert len(hull.points) == 8
    # centred on the middle of the bounding box; the pose carries the offset
    np.testing.assert_allclose(hull.pose[:3, 3], [0.5, 1.0, 1.5])
    assert hull.sizes[1] == pytest.approx(np.linalg.norm([0.5, 1.0, 1.5]))


def test_flat_and_tiny_point_sets_are_kept_as_they_are():
    flat = ConvexHull(points=[[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0.5, 0.5, 0]])
    assert len(flat.points) == 5
    one = ConvexHull(points=[[1.0, 2.0, 3.0]])
    np.testing.assert_allclose(one.pose[:3, 3], [1, 2, 3])
    d, _ = world_pair(one, Sphere(radius=0.5))
    assert d == pytest.approx(np.linalg.norm([1, 2, 3]) - 0.5, abs=1e-12)


def test_the_hull_of_a_box_is_the_box():
    """A hull of a box's corners gives the box's distances (moik's exact box kernels)."""
    rng = np.random.default_rng(7)
    for _ in range(30):
        pose, size = _pose(rng), rng.uniform(0.05, 0.4, 3)
        corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
        hull = ConvexHull(points=corners * size / 2, pose=pose)
        box = Box(size=size, pose=pose)
        other = _other("capsule", rng)
        d_box, _ = world_pair(box, other)
        d_hull, _ = world_pair(hull, other)
        if d_box > 0:
            assert d_hull == pytest.approx(d_box, abs=1e-9)
        else:
            assert d_hull <= d_box + 1e-9


@pytest.mark.parametrize("bad", [np.zeros((0, 3)), np.zeros((4, 2)), [[0, 0, np.nan]]])
def test_bad_points(bad):
    with pytest.raises(MoikError, match="points"):
        ConvexHull(points=bad)


def _compound(rng, pose):
    """Convex pieces of a random blob, bounded by a capsule that holds them all."""
    parts = [ConvexHull(points=rng.normal(size=(12, 3)) * 0.03 + [0, 0, z])
             for z in (-0.08, 0.0, 0.08)]
    bound = Capsule(radius=0.2, length=0.2)
    return Compound(bound=bound, parts=tuple(parts)).moved(pose)


@settings(max_examples=60, derandomize=True, deadline=None)
@given(st.integers(0, 2**31 - 1))
def test_a_compound_pair_is_its_parts_closest_pair(seed):
    """Compound pairs measure the parts (the bounds only cull): the distance equals the
    smallest over the parts' pairs, and the limited measure agrees below its limit."""
    from moik.collision.kernels import distance_below, distance_scratch

    rng = np.random.default_rng(seed)
    A = _compound(rng, _pose(rng, 0.25))
    B = _compound(rng, _pose(rng, 0.25))
    d, cs = world_pair(A, B)
    parts = min(world_pair(a, b)[0] for a in A.parts for b in B.parts)
    assert d == pytest.approx(parts, abs=1e-9)
    ref = min(_coal_distance(a, b) for a in A.parts for b in B.parts)
    if ref > 1e-9:
        assert d == pytest.approx(ref, abs=1e-9)
    scratch = distance_scratch(cs)
    for limit in (0.0, d + 1e-3, d - 1e-3, 0.05):
        below, _ = distance_below(cs, np.zeros(ROBOT.dof), scratch, limit)
        if d < limit:
            assert below == pytest.approx(d, abs=1e-12)
        else:
            assert below >= limit


def test_compound_needs_hull_parts_inside_a_primitive_bound():
    with pytest.raises(MoikError, match="bound"):
        Compound(bound=HalfSpace(), parts=(ConvexHull(points=np.eye(3)),))
    with pytest.raises(MoikError, match="parts"):
        Compound(bound=Sphere(radius=1.0), parts=())
