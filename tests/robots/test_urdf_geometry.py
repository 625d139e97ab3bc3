"""URDF links placed on the loaded chain's bodies (moik/robots/urdf_geometry.py)."""

import numpy as np

from moik import get_robot
from moik.robots.catalog import DATA
from moik.robots.urdf_geometry import collision_geometry, link_placements


def test_urdf_link_frames_do_not_depend_on_q():
    robot = get_robot("panda")
    rng = np.random.default_rng(0)
    _, a = link_placements(DATA / "panda.urdf", robot, robot.random_q(1, rng=rng)[0])
    names, b = link_placements(DATA / "panda.urdf", robot, robot.random_q(1, rng=rng)[0])
    assert names[0] == "panda_link0" and names[-1] == "panda_link7"
    for link in a:
        assert a[link][0] == b[link][0]
        np.testing.assert_allclose(a[link][1], b[link][1], atol=1e-12)



def test_meshes_reported_as_skipped():
    robot = get_robot("ur5")
    names, items = collision_geometry(DATA / "ur5_robot.urdf", robot)
    assert len(names) == 7
    assert {i["type"] for i in items} <= {"mesh", "box"}
    assert all(i["skipped"] for i in items if i["type"] == "mesh")
