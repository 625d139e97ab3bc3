"""Enclosing capsules (moik/collision/fit.py): every point inside, on synthetic clouds;
the capsule a dense surface sample came from recovered; URDF meshes on the bodies."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik import load_urdf
from moik.collision.fit import capsule_excess, capsule_volume, enclosing_capsule, urdf_mesh_points
from moik.exceptions import GeometryError
from moik.robots.urdf_geometry import mesh_geometry

coord = st.floats(-3.0, 3.0, allow_nan=False, allow_infinity=False)
point = st.tuples(coord, coord, coord)
length = st.floats(0.0, 2.0, allow_nan=False, allow_infinity=False)
seed = st.integers(0, 2**32 - 1)
TOL = 1e-9


def _inside(P, axes=()):
    a, b, r = enclosing_capsule(P, axes)
    assert r >= 0.0 and np.all(np.isfinite(a)) and np.all(np.isfinite(b))
    assert capsule_excess(P, a, b, r) <= TOL
    return a, b, r


def _rotation(rng):
    Q, R = np.linalg.qr(rng.normal(size=(3, 3)))
    return Q * np.sign(np.diag(R))


def _capsule_surface(a, b, r, n, rng):
    """``n`` points on the surface of the capsule (a, b, r): on the cylinder or a cap."""
    a, b = np.asarray(a), np.asarray(b)
    d = b - a
    L = np.linalg.norm(d)
    z = d / L if L > 0 else np.array([0.0, 0.0, 1.0])
    e1 = np.cross(z, np.eye(3)[np.argmin(np.abs(z))])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(z, e1)
    out = []
    for _ in range(n):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        kind = rng.integers(3)
        if kind == 0:  # the cylinder
            phi = rng.uniform(0, 2 * np.pi)
            out.append(a + rng.uniform(0, 1) * d + r * (np.cos(phi) * e1 + np.sin(phi) * e2))
        else:  # a cap: the half-sphere pointing away from the segment
            end, sign = (a, -1.0) if kind == 1 else (b, 1.0)
            if u @ z * sign < 0:
                u -= 2 * (u @ z) * z
            out.append(end + r * u)
    return np.array(out)


@settings(max_examples=60, deadline=None)
@given(point, point, st.floats(0.0, 1.0), st.integers(1, 60), seed)
def test_points_on_a_random_capsule_are_inside(a, b, r, n, s):
    _inside(_capsule_surface(a, b, r, n, np.random.default_rng(s)))


@settings(max_examples=60, deadline=None)
@given(point, length, length, length, seed)
def test_the_corners_of_a_random_box_are_inside(centre, x, y, z, s):
    corners = np.array([[i, j, k] for i in (-0.5, 0.5) for j in (-0.5, 0.5) for k in (-0.5, 0.5)])
    P = (corners * [x, y, z]) @ _rotation(np.random.default_rng(s)).T + centre
    _inside(P)


@settings(max_examples=30, deadline=None)
@given(point)
def test_a_single_point_is_a_capsule_of_radius_zero(p):
    a, b, r = _inside(np.array([p]))
    assert r == 0.0
    np.testing.assert_allclose(a, p, atol=1e-12)
    np.testing.assert_allclose(b, p, atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(point, point, st.lists(st.floats(-2.0, 2.0), min_size=1, max_size=20))
def test_collinear_points_are_inside(p, d, ts):
    P = np.asarray(p) + np.outer(ts, d)
    _, _, r = _inside(P)
    assert r <= 1e-9


@settings(max_examples=40, deadline=None)
@given(st.lists(point, min_size=1, max_size=40), st.lists(point, max_size=3))
def test_any_cloud_and_any_extra_axes(points, axes):
    _inside(np.array(points), axes)


def test_a_dense_surface_sample_gives_back_its_capsule():
    rng = np.random.default_rng(4)
    a, b, r = np.array([0.1, -0.2, 0.3]), np.array([0.5, 0.4, -0.1]), 0.15
    P = _capsule_surface(a, b, r, 2000, rng)
    fa, fb, fr = _inside(P)
    L = np.linalg.norm(b - a)
    assert fr == pytest.approx(r, rel=1e-2)
    assert np.linalg.norm(fb - fa) == pytest.approx(L, rel=2e-2)
    assert capsule_volume(fr, np.linalg.norm(fb - fa)) <= 1.02 * capsule_volume(r, L)
    ends = sorted([fa, fb], key=lambda e: np.linalg.norm(e - a))
    np.testing.assert_allclose(ends[0], a, atol=0.01)
    np.testing.assert_allclose(ends[1], b, atol=0.01)


def test_bad_points():
    with pytest.raises(GeometryError, match=r"\(n, 3\)"):
        enclosing_capsule(np.zeros((0, 3)))
    with pytest.raises(GeometryError, match=r"\(n, 3\)"):
        enclosing_capsule(np.zeros((4, 2)))


URDF = """<robot name="two">
  <link name="base"><collision><geometry><mesh filename="package://pkg/m/base.stl"/>
    </geometry></collision></link>
  <link name="arm"><collision><origin xyz="0 0 0.25" rpy="0 1.5707963267948966 0"/><geometry>
    <mesh filename="package://pkg/m/arm.stl" scale="2 2 2"/></geometry></collision>
    <visual><geometry><mesh filename="package://pkg/m/arm_visual.stl"/></geometry></visual>
  </link>
  <link name="flange"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-2" upper="2"/></joint>
  <joint name="f" type="fixed"><parent link="arm"/><child link="flange"/>
    <origin xyz="0 0 0.5"/></joint>
</robot>"""


def test_mesh_references_on_the_bodies():
    robot = load_urdf(URDF, tip_link="flange")
    names, items = mesh_geometry(URDF, robot)
    assert names == ["base", "arm"]
    assert [(i["link"], i["body"], i["filename"]) for i in items] == [
        ("base", 0, "package://pkg/m/base.stl"), ("arm", 1, "package://pkg/m/arm.stl")]
    np.testing.assert_array_equal(items[1]["scale"], [2, 2, 2])
    # the collision origin in body 1's frame: 0.25 up, x turned onto -z
    np.testing.assert_allclose(robot.frames(np.zeros(1))[1] @ items[1]["pose"] @ [1, 0, 0, 1],
                               [0, 0, 0.1 + 0.25 - 1, 1], atol=1e-12)
    _, visual = mesh_geometry(URDF, robot, element="visual")
    assert [i["filename"] for i in visual] == ["package://pkg/m/arm_visual.stl"]


def test_urdf_mesh_points_apply_scale_and_origin(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    for name in ("base", "arm"):
        trimesh.creation.box(extents=(0.1, 0.2, 0.3)).export(tmp_path / f"{name}.stl")
    robot = load_urdf(URDF, tip_link="flange")
    names, links = urdf_mesh_points(URDF, robot, tmp_path)
    assert names == ["base", "arm"] and sorted(links) == ["arm", "base"]
    body, P = links["arm"]
    assert body == 1
    world = P @ robot.frames(np.zeros(1))[1][:3, :3].T + robot.frames(np.zeros(1))[1][:3, 3]
    # the box scaled by 2 (0.2 x 0.4 x 0.6), its x turned onto -z, centred 0.35 up
    np.testing.assert_allclose(np.ptp(world, axis=0), [0.6, 0.4, 0.2], atol=1e-12)
    np.testing.assert_allclose(world.mean(axis=0), [0, 0, 0.35], atol=1e-12)
