"""The box kernels called directly: the segment-box minimum against a dense search and scipy,
and hand-derived capsule-box, box-box and box-half-space cases (separated, edge to edge,
penetrating), with coal as the oracle of the edge-to-edge and tilted cases and witnesses
that lie on their shapes (tests/collision/test_distance.py compares random pairs with coal
through the dispatch)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar

from moik.collision.box_distance import box_box, box_halfspace, capsule_box, segment_box_sq

coal = pytest.importorskip("coal")

SQ2 = math.sqrt(2.0)


def _pose(position=(0.0, 0.0, 0.0), rotation=None):
    P = np.eye(4)
    P[:3, :3], P[:3, 3] = np.eye(3) if rotation is None else rotation, position
    return P


def _rot(axis, a):
    c, s = math.cos(a), math.sin(a)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    R = np.eye(3)
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
    return R


def _f(p, d, e, t):
    """``|p + t d - box|^2`` for the box ``|x_i| <= e_i``, in numpy (``t`` scalar or 1-D)."""
    x = np.asarray(p) + np.multiply.outer(t, np.asarray(d))
    return np.sum(np.maximum(np.abs(x) - e, 0.0) ** 2, axis=-1)


coord = st.floats(-3.0, 3.0)
extent = st.floats(0.01, 1.5)


@settings(max_examples=200, deadline=None)
@given(p=st.tuples(coord, coord, coord), d=st.tuples(coord, coord, coord),
       e=st.tuples(extent, extent, extent))
def test_segment_box_minimum_is_the_minimum(p, d, e):
    """``f(t)`` is convex: scipy's bounded Brent search and a 2001-point grid find no lower
    value than the kernel, whose ``t`` is in [0, 1] and attains its value."""
    f_min, t = segment_box_sq(p, d, e)
    assert 0.0 <= t <= 1.0
    assert f_min == pytest.approx(_f(p, d, e, t), rel=1e-12, abs=1e-15)
    grid = _f(p, d, e, np.linspace(0.0, 1.0, 2001)).min()
    brent = minimize_scalar(lambda s: float(_f(p, d, e, s)), bounds=(0.0, 1.0), method="bounded",
                            options={"xatol": 1e-12}).fun
    assert f_min <= min(grid, brent) + 1e-12


@pytest.mark.parametrize("p, d, expected, t", [
    ((-2.0, 0.0, 0.0), (4.0, 0.0, 0.0), 0.0, None),  # through the unit box: 0 inside it
    ((-2.0, 2.0, 0.0), (4.0, 0.0, 0.0), 1.0, None),  # parallel to a face 1 above it
    ((3.0, 0.0, 0.0), (2.0, 0.0, 0.0), 4.0, 0.0),  # pointing away: its start, 2 from x = 1
    ((2.0, 2.0, 2.0), (0.0, 0.0, 0.0), 3.0, 0.0),  # a point: the corner (1, 1, 1)
    ((3.0, -1.0, 0.0), (0.0, 4.0, 0.0), 4.0, None),  # passing the face x = 1 at distance 2
])
def test_segment_box_by_hand(p, d, expected, t):
    f_min, t_min = segment_box_sq(p, d, (1.0, 1.0, 1.0))
    assert f_min == expected
    if t is not None:
        assert t_min == t
    else:
        assert _f(p, d, np.ones(3), t_min) == expected


def _on_box(point, P, s):
    """How far ``point`` is from the box's surface (0: on it), in its frame."""
    local = P[:3, :3].T @ (np.asarray(point) - P[:3, 3])
    outside = np.maximum(np.abs(local) - s, 0.0)
    return np.linalg.norm(outside) if outside.any() else float(np.min(s - np.abs(local)))


def _coal(shape_a, PA, shape_b, PB):
    req = coal.DistanceRequest()
    req.enable_signed_distance = True
    req.gjk_tolerance = req.epa_tolerance = 1e-14
    return coal.distance(shape_a, coal.Transform3s(PA[:3, :3], PA[:3, 3]),
                         shape_b, coal.Transform3s(PB[:3, :3], PB[:3, 3]), req,
                         coal.DistanceResult())


UNIT = np.array([0.5, 0.5, 0.5])  # the unit cube's half extents


def test_capsule_over_a_box_by_hand():
    """A capsule (r 0.2, h 1) along x at height 1.5 over the unit cube: 1.5 - 0.5 - 0.2; the
    witness on the cube is on its top face, the one on the capsule 0.2 below its axis."""
    PA = _pose((0.1, 0.0, 1.5), _rot(1, math.pi / 2))  # the capsule's z axis along x
    out = capsule_box(PA, np.array([0.2, 1.0, 0.0]), _pose(), UNIT)
    assert out[0] == pytest.approx(0.8, abs=1e-15)
    np.testing.assert_allclose(out[1:4], [0.0, 0.0, -1.0], atol=1e-15)
    assert out[6] == pytest.approx(1.3, abs=1e-15) and out[9] == pytest.approx(0.5, abs=1e-15)
    assert abs(out[4]) <= 0.5 and abs(out[7]) <= 0.5  # above the cube, not beyond it


def test_a_sphere_inside_a_box_by_hand():
    """Centre (0, 0, 0.4) in the unit cube, radius 0.2: 0.1 from the top face, so 0.3 deep
    along +z; the cube's witness is on that face."""
    out = capsule_box(_pose((0.0, 0.0, 0.4)), np.array([0.2, 0.0, 0.0]), _pose(), UNIT)
    assert out[0] == pytest.approx(-0.3, abs=1e-15)
    np.testing.assert_allclose(out[1:4], [0.0, 0.0, -1.0], atol=1e-15)
    np.testing.assert_allclose(out[4:7], [0.0, 0.0, 0.2], atol=1e-15)  # A's deepest point
    np.testing.assert_allclose(out[7:10], [0.0, 0.0, 0.5], atol=1e-15)


def test_boxes_face_to_face_and_overlapping_by_hand():
    sep = box_box(_pose(), UNIT, _pose((2.0, 0.3, -0.2)), UNIT)
    assert sep[0] == pytest.approx(1.0, abs=1e-15)
    np.testing.assert_allclose(sep[1:4], [1.0, 0.0, 0.0], atol=1e-15)
    assert sep[4] == pytest.approx(0.5) and sep[7] == pytest.approx(1.5)
    deep = box_box(_pose(), UNIT, _pose((0.8, 0.1, 0.0)), UNIT)
    assert deep[0] == pytest.approx(-0.2, abs=1e-15)  # overlap 1 - 0.8 along x
    np.testing.assert_allclose(deep[1:4], [1.0, 0.0, 0.0], atol=1e-15)


def test_boxes_edge_to_edge_by_hand_and_by_coal():
    """A turned 45 deg about z puts a vertical edge at x = sqrt(2)/2; B at (2, 0, 0) turned
    45 deg about y puts a horizontal edge (along y) at x = 2 - sqrt(2)/2. The edges cross:
    the distance is 2 - sqrt(2), along x, between the points (sqrt(2)/2, 0, 0) and
    (2 - sqrt(2)/2, 0, 0)."""
    PA, PB = _pose(rotation=_rot(2, math.pi / 4)), _pose((2.0, 0.0, 0.0), _rot(1, math.pi / 4))
    out = box_box(PA, UNIT, PB, UNIT)
    assert out[0] == pytest.approx(2.0 - SQ2, abs=1e-14)
    np.testing.assert_allclose(out[1:], [1, 0, 0, SQ2 / 2, 0, 0, 2 - SQ2 / 2, 0, 0],
                               atol=1e-14)
    assert out[0] == pytest.approx(_coal(coal.Box(1, 1, 1), PA, coal.Box(1, 1, 1), PB),
                                   abs=1e-9)
    swapped = box_box(PB, UNIT, PA, UNIT)
    assert swapped[0] == pytest.approx(out[0], abs=1e-15)


box = st.tuples(st.tuples(*[st.floats(0.05, 0.6)] * 3), st.tuples(*[st.floats(-1.5, 1.5)] * 3),
                st.tuples(*[st.floats(-math.pi, math.pi)] * 3))


def _box_pose(item):
    s, c, (a, b, g) = item
    return _pose(c, _rot(2, a) @ _rot(1, b) @ _rot(0, g)), np.array(s)


@settings(max_examples=150, deadline=None)
@given(box, box)
def test_box_witnesses_lie_on_their_boxes(x, y):
    """Separated: ``a`` on A's surface, ``b`` on B's, ``|b - a| = d``; the distance is the
    same in either order. (test_distance.py checks the value against coal.)"""
    (PA, sA), (PB, sB) = _box_pose(x), _box_pose(y)
    out = box_box(PA, sA, PB, sB)
    assert box_box(PB, sB, PA, sA)[0] == pytest.approx(out[0], abs=1e-12)
    if out[0] <= 1e-9:
        return
    a, b = np.array(out[4:7]), np.array(out[7:10])
    assert _on_box(a, PA, sA) <= 1e-9 and _on_box(b, PB, sB) <= 1e-9
    assert np.linalg.norm(b - a) == pytest.approx(out[0], abs=1e-12)


def test_a_tilted_box_over_a_plane_by_hand_and_by_coal():
    """The unit cube turned 45 deg about y, centre 1 above the plane z = 0: its lowest edge
    (along y) is sqrt(2)/2 below the centre: 1 - sqrt(2)/2 above the plane; with the centre
    at -0.5, 0.5 + sqrt(2)/2 deep. The witness on the plane is the lowest point moved up by
    the depth (z = 0)."""
    R = _rot(1, math.pi / 4)
    for height, expected in ((1.0, 1.0 - SQ2 / 2), (-0.5, -0.5 - SQ2 / 2)):
        P = _pose((0.0, 0.0, height), R)
        out = box_halfspace(P, UNIT, _pose())
        assert out[0] == pytest.approx(expected, abs=1e-15)
        np.testing.assert_allclose(out[1:4], [0.0, 0.0, -1.0], atol=1e-15)
        assert out[6] == pytest.approx(height - SQ2 / 2, abs=1e-15) and out[9] == 0.0
        ref = _coal(coal.Box(1, 1, 1), P, coal.Halfspace(np.array([0.0, 0.0, 1.0]), 0.0),
                    _pose())
        assert out[0] == pytest.approx(ref, abs=1e-9)
