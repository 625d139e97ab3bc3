"""Links behind movable joints outside the IK chain (panda's fingers) in the URDF collision
model (moik/collision/urdf.py), checked against coal on the arm's own geometry placed by
an oracle that shares no code with moik's placement (studies/urdf_oracle.py)."""

import numpy as np
import pytest

from moik import get_robot, load_urdf, solve_ik
from moik.collision import Box, CollisionChecker, Scene
from moik.collision.urdf import model_from_urdf, robot_model
from moik.exceptions import ParameterError
from moik.robots.catalog import DATA
from tests.coal_oracle import coal

PANDA = DATA / "panda.urdf"
OPEN = {"panda_finger_joint1": 0.04}
READY = np.array([0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785])


def _oracle(robot, values=None):
    from studies.urdf_oracle import URDFOracle

    return URDFOracle(PANDA, robot.joint_names, [DATA / "packages"], joint_values=values)


def _against_the_left_fingertip(oracle, q, *, inward=0.001):
    """A 1 cm cube pressed ``inward`` into the outer face of the left finger's rubber tip
    (the finger's box at y 7.58 mm, 15.2 mm thick: outer face at y = 15.18 mm)."""
    local = np.eye(4)
    local[:3, 3] = [0.0, 0.01518 + 0.005 - inward, 0.045]
    return oracle.pose(q, "panda_leftfinger") @ local


def test_the_fingers_are_on_the_hand_and_the_model_says_where():
    model = robot_model(get_robot("panda"))
    assert "panda_finger_joint1 = 0 (default: its zero clipped into its limits)" in model.source
    assert "panda_finger_joint2 = 0 (mimics panda_finger_joint1)" in model.source
    hand = model.shapes["panda_link7"]
    assert sum(isinstance(s, Box) for s in hand) == 8  # 4 boxes per finger
    with pytest.raises(ParameterError, match="panda_finger_joint1.*must be a number in"):
        robot_model(get_robot("panda"), joint_values={"panda_finger_joint1": 0.1})


def test_another_opening_is_another_model_and_another_cache_entry(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    robot = get_robot("panda")
    closed = model_from_urdf(PANDA, robot, package_dirs=[DATA / "packages"], samples=20)
    opened = model_from_urdf(PANDA, robot, package_dirs=[DATA / "packages"], samples=20,
                             joint_values=OPEN)
    assert len(list(tmp_path.rglob("acm-*.json"))) == 2  # one matrix per opening
    y = [[s.pose[:3, 3] for s in m.shapes["panda_link7"] if isinstance(s, Box)]
         for m in (closed, opened)]
    moved = np.linalg.norm(np.array(y[1]) - np.array(y[0]), axis=1)
    np.testing.assert_allclose(moved, 0.04, atol=1e-12)  # every finger box, 4 cm out
    assert "panda_finger_joint1 = 0.04 (given)" in opened.source


@pytest.mark.parametrize("values", [None, OPEN])
def test_configurations_called_free_are_free_for_coal_fingers_included(values):
    """Random configurations with a cube near the left fingertip (within 2 cm, so the
    fingers decide many verdicts): every one moik calls free has coal distance >= 0
    from the cube to every link, and no two non-neighbouring links touching."""
    robot = get_robot("panda")
    model = robot_model(robot, joint_values=values)
    oracle = _oracle(robot, values)
    rng = np.random.default_rng(7)
    Q = robot.random_q(60, rng=rng)
    cube = Box(size=[0.01, 0.01, 0.01])
    called, finger_only = [], 0
    for q in Q:
        T = _against_the_left_fingertip(oracle, q, inward=-rng.uniform(-0.004, 0.02))
        scene = Scene({"cube": Box(size=[0.01] * 3, pose=T)})
        free = CollisionChecker(model=model, scene=scene,
                                self_collision=True).min_distance(q[None])[0] >= 0.0
        d = oracle.distances_to(q, coal.Box(*cube.size), T)
        touched = {link for link, v in d.items() if v < 0.0}
        self_touch = bool(oracle.touching(q[None])[0])
        called.append(free)
        if free:
            assert not touched and not self_touch, (q, touched)
        finger_only += bool(touched) and touched <= {"panda_leftfinger", "panda_rightfinger"}
    assert finger_only > 0 and any(called)  # the fingers alone decided some verdicts


def test_a_collision_of_the_fingers_alone_is_rejected():
    robot = get_robot("panda")
    oracle = _oracle(robot)
    T = _against_the_left_fingertip(oracle, READY)
    d = oracle.distances_to(READY, coal.Box(0.01, 0.01, 0.01), T)
    assert {link for link, v in d.items() if v < 0.0} == {"panda_leftfinger"}
    scene = Scene({"cube": Box(size=[0.01] * 3, pose=T)})
    checker = CollisionChecker(model=robot_model(robot), scene=scene)
    assert checker.min_distance(READY[None])[0] < 0.0
    # the hand's pose fixes the fingers': no answer reaches it without the cube
    res = solve_ik(robot, robot.fk(READY), scene=scene, self_collision=True, seed=0)
    assert res.status == "collides"


def test_a_urdf_with_a_mesh_behind_an_offchain_joint(tmp_path, monkeypatch):
    trimesh = pytest.importorskip("trimesh")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    trimesh.creation.box(extents=(0.02, 0.02, 0.1)).export(tmp_path / "finger.stl")
    urdf = tmp_path / "arm.urdf"
    urdf.write_text("""<robot name="a">
  <link name="base"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="arm"><collision><origin xyz="0 0 0.25"/><geometry><box size="0.05 0.05 0.5"/>
    </geometry></collision></link>
  <link name="finger"><collision><origin xyz="0 0 0.05"/><geometry>
    <mesh filename="finger.stl"/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 1 0"/><limit lower="-2" upper="2"/></joint>
  <joint name="grip" type="prismatic"><parent link="arm"/><child link="finger"/>
    <origin xyz="0 0 0.5"/><axis xyz="1 0 0"/><limit lower="-0.1" upper="0.1"/></joint>
</robot>""")
    robot = load_urdf(urdf, tip_link="arm")
    models = [model_from_urdf(urdf, robot, samples=0, joint_values={"grip": v})
              for v in (0.0, 0.05)]
    centres = [m.shapes["arm"][1].bound.pose[:3, 3] for m in models]
    np.testing.assert_allclose(centres[1] - centres[0], [0.05, 0, 0], atol=1e-9)
    assert len(list((tmp_path / "cache").rglob("fit-*.json"))) == 2  # one fit per placement
