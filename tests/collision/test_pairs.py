"""The broad-phase bound and the pair dispatch (moik.collision.pairs), by hand.

tests/collision/test_distance.py checks every kind pair against coal on random shapes (the
distance, the bound below it, the normal); here: the bounding radii, the bound's exact
value where it is tight (two spheres; a sphere over a plane) and where it is not, the
dispatch of both orders of each kind pair to one kernel (witnesses swapped, normal
negated), and the pair moik never evaluates (two half-spaces: NaN).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision.distance import BOX, CAPSULE, HALFSPACE, SPHERE
from moik.collision.pairs import _bounding_radius, pair_bound, pair_distance


def _pose(position=(0.0, 0.0, 0.0), rotation=None):
    P = np.eye(4)
    P[:3, :3], P[:3, 3] = np.eye(3) if rotation is None else rotation, position
    return P


def _ry(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


SIZES = {SPHERE: [0.1, 0.0, 0.0], CAPSULE: [0.1, 0.3, 0.0], BOX: [0.1, 0.2, 0.3],
         HALFSPACE: [0.0, 0.0, 0.0]}


def test_bounding_radius_by_hand():
    kinds = np.array([SPHERE, CAPSULE, BOX])
    sizes = np.array([SIZES[SPHERE], SIZES[CAPSULE], SIZES[BOX]])
    assert _bounding_radius(kinds, sizes, 0) == 0.1  # the sphere itself
    assert _bounding_radius(kinds, sizes, 1) == pytest.approx(0.4, abs=1e-15)  # r + h
    assert _bounding_radius(kinds, sizes, 2) == pytest.approx(math.sqrt(0.14), abs=1e-15)


@pytest.mark.parametrize("kind, turn, bound, exact", [
    (SPHERE, 0.0, 0.5 - 0.1, 0.5 - 0.1),  # tight: the sphere is its bounding sphere
    (CAPSULE, 0.0, 0.5 - 0.4, 0.5 - 0.3 - 0.1),  # standing on its end: tight
    (CAPSULE, math.pi / 2, 0.5 - 0.4, 0.5 - 0.1),  # lying: the bound counts h, d does not
    (BOX, 0.0, 0.5 - math.sqrt(0.14), 0.5 - 0.3),  # on its 0.1 x 0.2 face: z = 0.3 down
    (BOX, -math.pi / 2, 0.5 - math.sqrt(0.14), 0.5 - 0.1),  # its x along the normal
])
def test_half_space_bound_by_hand(kind, turn, bound, exact):
    """The plane ``z <= 0`` of a pose tilted 30 deg about y; the shape's centre 0.5 along
    the plane's normal, its frame the plane's turned by ``turn`` about y (sizes: sphere
    r = 0.1; capsule r = 0.1, h = 0.3; box half extents 0.1, 0.2, 0.3). The bound is the
    centre's height less the bounding radius; the distance, the lowest point's height."""
    R = _ry(math.radians(30))
    W = np.array([_pose(rotation=R), _pose(0.5 * R[:, 2], R @ _ry(turn))])
    kinds = np.array([HALFSPACE, kind])
    sizes = np.array([SIZES[HALFSPACE], SIZES[kind]])
    assert pair_bound(kinds, W, sizes, 0, 1) == pytest.approx(bound, abs=1e-14)
    assert pair_bound(kinds, W, sizes, 1, 0) == pair_bound(kinds, W, sizes, 0, 1)
    d = pair_distance(kinds[0], W[0], sizes[0], kinds[1], W[1], sizes[1])[0]
    assert d == pytest.approx(exact, abs=1e-14)


radius = st.floats(0.01, 1.0)
point = st.tuples(*[st.floats(-2.0, 2.0)] * 3)


@settings(max_examples=100, deadline=None)
@given(ra=radius, rb=radius, ca=point, cb=point)
def test_the_bound_of_two_spheres_is_their_distance(ra, rb, ca, cb):
    """A sphere is its own bounding sphere: the bound is exact (the broad phase never
    evaluates a sphere pair it need not)."""
    W = np.array([_pose(ca), _pose(cb)])
    kinds = np.array([SPHERE, SPHERE])
    sizes = np.array([[ra, 0.0, 0.0], [rb, 0.0, 0.0]])
    d = pair_distance(SPHERE, W[0], sizes[0], SPHERE, W[1], sizes[1])[0]
    expected = math.dist(ca, cb) - ra - rb
    assert pair_bound(kinds, W, sizes, 0, 1) == pytest.approx(expected, abs=1e-14)
    assert d == pytest.approx(expected, abs=1e-14)


ORDERED = [(a, b) for a in (SPHERE, CAPSULE, BOX, HALFSPACE)
           for b in (SPHERE, CAPSULE, BOX, HALFSPACE) if a < b]


@pytest.mark.parametrize("ka, kb", ORDERED + [(SPHERE, SPHERE), (CAPSULE, CAPSULE),
                                              (BOX, BOX)])
def test_both_orders_reach_one_kernel(ka, kb):
    """Swapping A and B keeps the distance, negates the normal and swaps the witnesses
    (separated shapes: their closest points are unique)."""
    PA = _pose((0.05, -0.1, 0.0), _ry(0.3))
    PB = _pose((0.1, 0.2, 1.5), _ry(-0.4))
    if ka == HALFSPACE:
        PA = _pose((0.0, 0.0, -1.0))
    if kb == HALFSPACE:  # a plane below A: B is the one at the bottom
        PA, PB = PB, _pose((0.0, 0.0, -1.0))
    sA, sB = np.array(SIZES[ka]), np.array(SIZES[kb])
    ab = np.array(pair_distance(ka, PA, sA, kb, PB, sB))
    ba = np.array(pair_distance(kb, PB, sB, ka, PA, sA))
    assert ab[0] > 0.1 and ba[0] == ab[0]
    np.testing.assert_array_equal(ba[1:4], -ab[1:4])
    np.testing.assert_array_equal(ba[4:7], ab[7:10])
    np.testing.assert_array_equal(ba[7:10], ab[4:7])
    np.testing.assert_allclose(ab[7:10] - ab[4:7], ab[0] * ab[1:4], atol=1e-12)


def test_sphere_against_a_box_by_hand():
    """A sphere of radius 0.1 at (1, 0, 0) and the box of half extents 0.2 at the origin:
    0.8 from the face x = 0.2, less the radius; witnesses on the sphere and the face."""
    d = pair_distance(SPHERE, _pose((1.0, 0.0, 0.0)), np.array([0.1, 0.0, 0.0]),
                      BOX, _pose(), np.array([0.2, 0.2, 0.2]))
    assert d[0] == pytest.approx(0.7, abs=1e-15)
    np.testing.assert_allclose(d[1:], [-1, 0, 0, 0.9, 0, 0, 0.2, 0, 0], atol=1e-15)


def test_two_half_spaces_are_not_a_pair():
    out = pair_distance(HALFSPACE, _pose(), np.zeros(3), HALFSPACE, _pose((0, 0, 1.0)),
                        np.zeros(3))
    assert len(out) == 10 and all(math.isnan(x) for x in out)
