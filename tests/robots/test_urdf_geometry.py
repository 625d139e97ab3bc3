"""URDF links placed on the loaded chain's bodies (moik/robots/urdf_geometry.py)."""

from dataclasses import replace

import hypothesis.strategies as st
import numpy as np
from hypothesis import given, settings
from scipy.spatial.transform import Rotation

from moik import get_robot
from moik.robots.catalog import DATA
from moik.robots.urdf_geometry import collision_geometry, joint_frames, link_placements


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


@settings(max_examples=25, deadline=None)
@given(name=st.sampled_from(["panda", "ur5", "iiwa14", "puma560", "eosma7"]),
       seed=st.integers(0, 2**32 - 1), mounted=st.booleans())
def test_joint_frames_are_the_robots_frames(name, seed, mounted):
    """joint_frames (the collision kernels' world_frames) gives Robot.frames bit for bit,
    on a base and tool of its own too."""
    robot = get_robot(name)
    rng = np.random.default_rng(seed)
    if mounted:
        base, tool = np.eye(4), np.eye(4)
        base[:3, :3] = Rotation.random(random_state=seed).as_matrix()
        base[:3, 3], tool[:3, 3] = rng.normal(size=3), rng.normal(size=3)
        robot = replace(robot, base=base, tool=tool)
    q = robot.random_q(1, rng=rng)[0]
    np.testing.assert_array_equal(joint_frames(robot, q), robot.frames(q))
