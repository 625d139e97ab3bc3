"""A URDF cylinder as a compound (moik/collision/prism.py): the prism holds the cylinder and
is at most 0.5 % of the radius outside it; measured against coal's own cylinder."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision import Capsule, ConvexHull
from moik.collision.prism import SIDES, cylinder_compound, prism_points
from moik.collision.shapes import Compound
from moik.exceptions import MoikError
from tests.world_pair import world_pair

coal = pytest.importorskip("coal")
EXCESS = 1.0 / np.cos(np.pi / SIDES) - 1.0  # the prism's largest excess, a fraction of r


def _distance(A, B) -> float:
    """moik's compiled distance of two world shapes (compounds measured on their parts)."""
    return float(world_pair(A, B)[0])


def _coal_cylinders(r1, l1, P1, r2, l2, P2) -> float:
    req = coal.DistanceRequest()
    return coal.distance(coal.Cylinder(r1, l1), coal.Transform3s(P1[:3, :3], P1[:3, 3]),
                         coal.Cylinder(r2, l2), coal.Transform3s(P2[:3, :3], P2[:3, 3]),
                         req, coal.DistanceResult())


def _pose(rng) -> np.ndarray:
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    T = np.eye(4)
    T[:3, :3] = q if np.linalg.det(q) > 0 else -q
    T[:3, 3] = rng.uniform(-0.3, 0.3, 3)
    return T


def test_the_prism_holds_the_cylinder_and_nothing_beyond_its_ends():
    r, length = 0.0325, 0.051
    P = prism_points(r, length)
    assert P.shape == (2 * SIDES, 3)
    # the sides' middles lie on the circle (circumscribed), the corners just outside it
    mids = (P[:SIDES] + np.roll(P[:SIDES], -1, axis=0)) / 2
    np.testing.assert_allclose(np.hypot(mids[:, 0], mids[:, 1]), r, rtol=1e-12)
    assert np.hypot(P[:, 0], P[:, 1]).max() == pytest.approx(r * (1 + EXCESS), rel=1e-12)
    assert np.abs(P[:, 2]).max() == pytest.approx(length / 2, rel=1e-12)
    c = cylinder_compound(radius=r, length=length, pose=np.eye(4))
    assert isinstance(c, Compound) and isinstance(c.bound, Capsule)
    assert len(c.parts) == 1 and isinstance(c.parts[0], ConvexHull)
    with pytest.raises(MoikError, match="radius"):
        cylinder_compound(radius=-1.0, length=0.1)


def test_end_to_end_cylinders_are_apart_where_their_capsules_overlap():
    """Two cylinders facing each other end to end 15 mm apart (a Unitree Z1's wrist): their
    enclosing capsules overlap by 50 mm, the compounds are 15 mm apart, as coal says."""
    r, length, gap = 0.0325, 0.05, 0.015
    A = np.eye(4)
    B = np.eye(4)
    B[2, 3] = length + gap
    caps = _distance(Capsule(radius=r, length=length, pose=A),
                     Capsule(radius=r, length=length, pose=B))
    assert caps == pytest.approx(gap - 2 * r, abs=1e-12)
    d = _distance(cylinder_compound(radius=r, length=length, pose=A),
                  cylinder_compound(radius=r, length=length, pose=B))
    assert d == pytest.approx(gap, abs=1e-9)
    assert d == pytest.approx(_coal_cylinders(r, length, A, r, length, B), abs=1e-9)


@settings(max_examples=80, derandomize=True, deadline=None)
@given(st.integers(0, 2**31 - 1))
def test_never_above_the_cylinders_distance_and_close_below_it(seed):
    """Sound (never above coal's distance of the cylinders themselves) and tight (at most
    the prisms' excess below it) for separated cylinders in random poses."""
    rng = np.random.default_rng(seed)
    r1, r2 = rng.uniform(0.01, 0.08, 2)
    l1, l2 = rng.uniform(0.02, 0.3, 2)
    P1, P2 = _pose(rng), _pose(rng)
    ref = _coal_cylinders(r1, l1, P1, r2, l2, P2)
    d = _distance(cylinder_compound(radius=r1, length=l1, pose=P1),
                  cylinder_compound(radius=r2, length=l2, pose=P2))
    if ref > 1e-6:
        assert d <= ref + 1e-9
        assert d >= ref - EXCESS * (r1 + r2) - 1e-9
    else:  # touching or overlapping cylinders: the prisms, which hold them, too
        assert d <= max(ref, 0.0) + 1e-9
