"""URDF <collision> primitives on the loaded chain's bodies (moik/collision/urdf.py and
moik/robots/urdf_geometry.py)."""

import numpy as np
import pytest

from moik import load_urdf
from moik.collision import Box, Capsule, CollisionChecker, Sphere
from moik.collision.urdf import model_from_urdf
from moik.exceptions import GeometryError, URDFError

URDF = """<robot name="two">
  <link name="base"><collision><origin xyz="0 0 0.05"/><geometry><box size="0.2 0.2 0.1"/>
    </geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.25" rpy="0 0 0"/><geometry>
    <cylinder radius="0.04" length="0.5"/></geometry></collision></link>
  <link name="fore"><collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.05"/>
    </geometry></collision>
    <collision><geometry><mesh filename="package://x/fore.stl"/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 1 0"/><limit lower="-2" upper="2"/></joint>
  <joint name="j2" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.5" rpy="0 1.5707963267948966 0"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2"/></joint>
</robot>"""


PRIMITIVES = URDF.replace(
    '<collision><geometry><mesh filename="package://x/fore.stl"/></geometry></collision>', "")


def test_primitives_on_the_bodies():
    robot = load_urdf(PRIMITIVES)
    model = model_from_urdf(PRIMITIVES, robot, samples=0)
    assert model.links == ("base", "upper", "fore")
    assert isinstance(model.shapes["base"][0], Box)
    assert isinstance(model.shapes["upper"][0], Capsule)  # the cylinder's enclosing capsule
    assert isinstance(model.shapes["fore"][0], Sphere)
    checker = CollisionChecker(model=model)
    for q in ([0.0, 0.0], [0.7, -1.1]):
        placed = dict(checker.world_shapes(np.array(q)))
        # by hand: base -> j1 at z 0.1 rotating about y; j2 0.5 above, pitched by pi/2
        c1, s1 = np.cos(q[0]), np.sin(q[0])
        Ry1 = np.array([[c1, 0, s1], [0, 1, 0], [-s1, 0, c1]])
        p_upper = np.array([0, 0, 0.1]) + Ry1 @ [0, 0, 0.25]
        np.testing.assert_allclose(placed["upper[1]"].pose[:3, 3], p_upper, atol=1e-12)
        a = q[1] + np.pi / 2
        Ry2 = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
        p_fore = np.array([0, 0, 0.1]) + Ry1 @ ([0, 0, 0.5] + Ry2 @ [0.2, 0, 0])
        np.testing.assert_allclose(placed["fore[2]"].pose[:3, 3], p_fore, atol=1e-12)
    assert checker.n_pairs == 1  # base and fore (upper is adjacent to both)


def test_not_this_robots_urdf():
    other = load_urdf(URDF.replace('"j1"', '"k1"').replace('"j2"', '"k2"'))
    with pytest.raises(URDFError, match="has no joints"):
        model_from_urdf(URDF, other)


def test_an_unresolvable_mesh_names_link_file_and_folders(tmp_path):
    path = tmp_path / "two.urdf"
    path.write_text(URDF)
    robot = load_urdf(path, package_dirs=[tmp_path / "pkgs"])
    with pytest.raises(GeometryError, match=r"link 'fore'.*package://x/fore\.stl.*not found.*"
                       r"pkgs/x/fore\.stl"):
        model_from_urdf(path, robot, package_dirs=[tmp_path / "pkgs"])


def test_a_body_without_geometry_is_an_error_or_an_explicit_choice():
    bare = PRIMITIVES.replace('<collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.05"/>'
                              '\n    </geometry></collision>', "")
    robot = load_urdf(bare)
    with pytest.raises(GeometryError, match=r"bodies \['fore'\] have no <collision>.*"
                       "missing='ignore'"):
        model_from_urdf(bare, robot, samples=0)
    model = model_from_urdf(bare, robot, samples=0, missing="ignore")
    assert "fore" not in model.shapes and "NOT checked: fore" in model.source
