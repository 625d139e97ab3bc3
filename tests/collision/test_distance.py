"""The pair kernels against coal (the maintained successor of hpp-fcl), on random shapes."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision.distance import BOX, CAPSULE, HALFSPACE, SPHERE
from moik.collision.pairs import pair_bound, pair_distance

coal = pytest.importorskip("coal")

KINDS = (SPHERE, CAPSULE, BOX, HALFSPACE)


def _rotation(v):
    """A rotation from 3 uniform numbers (Shoemake's quaternion)."""
    u1, u2, u3 = v
    a, b = np.sqrt(1 - u1), np.sqrt(u1)
    x, y, z, w = a * np.sin(2 * np.pi * u2), a * np.cos(2 * np.pi * u2), \
        b * np.sin(2 * np.pi * u3), b * np.cos(2 * np.pi * u3)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


unit = st.floats(0.0, 1.0)
# capsule half lengths are 0 (a sphere) or >= 1e-3: for shorter ones coal's GJK on the core
# segment is off by up to 1.2e-7 (its tolerance, not the geometry); see the test below
half = st.one_of(st.just(0.0), st.floats(1e-3, 0.6))
shape = st.tuples(st.sampled_from(KINDS), st.tuples(st.floats(0.02, 0.5), half,
                                                    st.floats(0.02, 0.5)),
                  st.tuples(unit, unit, unit), st.tuples(*[st.floats(-0.8, 0.8)] * 3))


def _build(item):
    kind, (r, h, z), rot, pos = item
    P = np.eye(4)
    P[:3, :3], P[:3, 3] = _rotation(rot), pos
    if kind == SPHERE:
        return kind, P, np.array([r, 0.0, 0.0]), coal.Sphere(r)
    if kind == CAPSULE:
        return kind, P, np.array([r, h, 0.0]), coal.Capsule(r, 2 * h)
    if kind == BOX:
        e = np.array([r, h + 0.02, z])
        return kind, P, e, coal.Box(*(2 * e))
    return kind, P, np.zeros(3), coal.Halfspace(np.array([0.0, 0.0, 1.0]), 0.0)


def coal_distance(a, b):
    req = coal.DistanceRequest()
    req.enable_signed_distance = True
    req.gjk_tolerance = req.epa_tolerance = 1e-14
    req.gjk_max_iterations = req.epa_max_iterations = 1000
    res = coal.DistanceResult()
    return coal.distance(a[3], coal.Transform3s(a[1][:3, :3], a[1][:3, 3]),
                         b[3], coal.Transform3s(b[1][:3, :3], b[1][:3, 3]), req, res)


@settings(max_examples=400, deadline=None)
@given(shape, shape)
def test_signed_distance_matches_coal(x, y):
    a, b = _build(x), _build(y)
    if a[0] == HALFSPACE and b[0] == HALFSPACE:
        return
    d = pair_distance(a[0], a[1], a[2], b[0], b[1], b[2])
    expected = coal_distance(a, b)
    if a[0] <= CAPSULE and b[0] <= CAPSULE and d[0] == -(a[2][0] + b[2][0]):
        # capsule cores that meet are exactly -(rA + rB) deep (the closed form); coal's EPA
        # stops short there (measured: 1.5e-8 to 2.5e-5 for coincident capsules): sign only
        assert expected < 0
    elif d[0] < 0 and BOX in (a[0], b[0]) and HALFSPACE not in (a[0], b[0]):
        # coal's EPA under-estimates some box penetrations (1.2e-2 for two thin boxes with
        # one centre: 0.0400 where the depth is 0.0523, as a 2e6-direction search confirms);
        # the depth here is the exact SAT minimum, never smaller than coal's
        assert d[0] <= expected + 1e-9, (d[0], expected)
    else:
        assert abs(d[0] - expected) <= 1e-9, (d[0], expected)
    assert (d[0] < 0) == (expected < 0) or abs(expected) < 1e-12


@settings(max_examples=400, deadline=None)
@given(shape, shape)
def test_broad_phase_bound_is_a_lower_bound(x, y):
    """The bounding-sphere bound never exceeds the signed distance, penetrating or not."""
    a, b = _build(x), _build(y)
    if a[0] == HALFSPACE and b[0] == HALFSPACE:
        return
    d = pair_distance(a[0], a[1], a[2], b[0], b[1], b[2])[0]
    kinds, W, sizes = np.array([a[0], b[0]]), np.array([a[1], b[1]]), np.array([a[2], b[2]])
    lb = pair_bound(kinds, W, sizes, 0, 1)
    assert lb <= d + 1e-12, (lb, d)
    assert pair_bound(kinds, W, sizes, 1, 0) == pytest.approx(lb, abs=1e-15)


@settings(max_examples=150, deadline=None)
@given(shape, shape)
def test_witnesses_and_normal(x, y):
    a, b = _build(x), _build(y)
    if a[0] == HALFSPACE and b[0] == HALFSPACE:
        return
    d, nx, ny, nz, ax, ay, az, bx, by, bz = pair_distance(a[0], a[1], a[2], b[0], b[1], b[2])
    n = np.array([nx, ny, nz])
    assert abs(np.linalg.norm(n) - 1) < 1e-9
    assert np.allclose(np.array([bx, by, bz]) - np.array([ax, ay, az]), d * n, atol=1e-9)
    swapped = pair_distance(b[0], b[1], b[2], a[0], a[1], a[2])
    assert abs(swapped[0] - d) <= 1e-12
    if d > 1e-9:  # separated: the normal is unique (touching inner segments have none)
        assert np.allclose(swapped[1:4], -n)


def _capsule_pose(axis, centre):
    """A pose whose z axis (the capsule's) is ``axis``, at ``centre``."""
    z = np.asarray(axis, float) / np.linalg.norm(axis)
    x = np.cross([0.0, 0.0, 1.0], z) if abs(z[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    x /= np.linalg.norm(x)
    P = np.eye(4)
    P[:3, :3], P[:3, 3] = np.column_stack([x, np.cross(z, x), z]), centre
    return P


@pytest.mark.parametrize("angle", [1e-8, 1e-6, 1e-3])
def test_nearly_parallel_crossing_capsules_touch_along_their_axes(angle):
    """Two capsule axes crossing at (0.3, 0, 0) at a small angle: the segments meet, so the
    signed distance is minus the sum of the radii, in either order. The earlier formula
    ((b f - c) / (1 - b^2), cancelling) treated angles below 1e-6 as parallel and put the
    closest points 0.3 sin(angle) apart (3e-9 at 1e-8), and hypothesis found the two
    orders of a pair differing by 1e-8."""
    A = (CAPSULE, _capsule_pose([1.0, 0.0, 0.0], [0.0, 0.0, 0.0]), np.array([0.2, 0.5, 0.0]))
    B = (CAPSULE, _capsule_pose([np.cos(angle), np.sin(angle), 0.0], [0.3, 0.0, 0.0]),
         np.array([0.1, 0.5, 0.0]))
    for a, b in ((A, B), (B, A)):
        assert pair_distance(*a, *b)[0] == pytest.approx(-0.3, abs=1e-15)


def test_hand_cases():
    eye = np.eye(4)
    far = np.eye(4)
    far[:3, 3] = [1.0, 0.0, 0.0]
    # two unit spheres 1 apart overlap by 1; a capsule and a box side by side
    assert pair_distance(SPHERE, eye, np.array([1.0, 0, 0]), SPHERE, far,
                         np.array([1.0, 0, 0]))[0] == -1.0
    d = pair_distance(CAPSULE, eye, np.array([0.1, 0.5, 0]), BOX, far,
                      np.array([0.2, 0.2, 0.2]))[0]
    assert d == pytest.approx(1.0 - 0.2 - 0.1, abs=1e-15)
    # a box resting 0.3 above a table
    up = np.eye(4)
    up[2, 3] = 0.5
    assert pair_distance(BOX, up, np.array([0.2, 0.2, 0.2]), HALFSPACE, eye,
                         np.zeros(3))[0] == pytest.approx(0.3, abs=1e-15)
