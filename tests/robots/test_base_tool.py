"""Base and tool transforms and joint names of a Robot (moik/robots/chain.py).

FK of a robot with ``base`` and ``tool`` is ``base @ fk_without(q) @ tool`` for
every kernel (folded into the constants of the kinematic chain), the reference,
the frames used by plots, the Jacobian and the solver.
"""

import pickle
from dataclasses import replace

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from moik import solve_ik
from moik.exceptions import NonFiniteError, ParameterError, ShapeError
from moik.kinematics.jacobian import pose_and_jacobian
from moik.robots import Robot, available_robots, fk_reference, get_robot
from moik.robots.urdf import load_urdf

NAMES = ["eosma7", "scara4", "irb2600", "rokbani5", "panda", "ur5", "puma560-urdf"]


def _rigid(seed: int, scale: float) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3] = Rotation.random(random_state=seed).as_matrix()
    T[:3, 3] = np.random.default_rng(seed).normal(scale=scale, size=3)
    return T


def _mounted(name: str, seed: int = 0) -> tuple[Robot, Robot]:
    robot = get_robot(name)
    base, tool = _rigid(seed, robot.reach / 3), _rigid(seed + 1, robot.reach / 8)
    return robot, replace(robot, base=base, tool=tool)


@pytest.mark.parametrize("name", NAMES)
def test_fk_is_base_times_chain_times_tool(name):
    robot, mounted = _mounted(name)
    Q = robot.random_q(70, rng=np.random.default_rng(1))
    want = mounted.base @ robot.fk(Q) @ mounted.tool
    atol = 1e-12 * mounted.reach
    for T in (mounted.fk(Q), fk_reference(mounted, Q), mounted.frames(Q)[:, -1]):
        np.testing.assert_allclose(T, want, rtol=0, atol=atol)
    R, p = mounted.fk_parts(Q)
    np.testing.assert_allclose(R, want[:, :3, :3], rtol=0, atol=1e-12)
    np.testing.assert_allclose(p, want[:, :3, 3], rtol=0, atol=atol)
    np.testing.assert_allclose(mounted.fk_position(Q), want[:, :3, 3], rtol=0, atol=atol)
    np.testing.assert_allclose(mounted.fk(Q[0]), want[0], rtol=0, atol=atol)
    frames = mounted.frames(Q[:3])
    np.testing.assert_array_equal(frames[:, 0], np.broadcast_to(mounted.base, (3, 4, 4)))
    inner = robot.frames(Q[:3])  # intermediate frames move with the base
    np.testing.assert_allclose(frames[:, 1:-1], mounted.base @ inner[:, 1:-1], atol=atol)


@pytest.mark.parametrize("name", NAMES)
def test_reach_bounds_the_tool_distance(name):
    robot, mounted = _mounted(name, seed=4)
    Q = mounted.random_q(2000, rng=np.random.default_rng(2))
    assert np.linalg.norm(mounted.fk_position(Q), axis=1).max() <= mounted.reach
    assert mounted.reach <= robot.reach + np.linalg.norm(mounted.base[:3, 3]) \
        + np.linalg.norm(mounted.tool[:3, 3]) + 1e-12 * robot.reach


def test_identity_base_and_tool_change_nothing():
    for name in available_robots():
        robot = get_robot(name)
        same = replace(robot, base=np.eye(4), tool=np.eye(4).tolist())
        np.testing.assert_array_equal(same.kinematic_chain.origins, robot.kinematic_chain.origins)
        np.testing.assert_array_equal(same.kinematic_chain.link_frames,
                                      robot.kinematic_chain.link_frames)
        assert same.reach == robot.reach
        np.testing.assert_array_equal(robot.base, np.eye(4))
        assert not robot.base.flags.writeable and not robot.tool.flags.writeable


def test_jacobian_honours_base_and_tool():
    """The geometric Jacobian of the mounted robot matches finite differences."""
    _, mounted = _mounted("eosma7-m", seed=2)
    q = mounted.random_q(1, rng=np.random.default_rng(3))[0]
    T, J = pose_and_jacobian(mounted, q)
    h = 1e-6
    for j in range(mounted.dof):
        dq = np.zeros(mounted.dof)
        dq[j] = h
        Tp, Tm = mounted.fk(q + dq), mounted.fk(q - dq)
        np.testing.assert_allclose(J[:3, j], (Tp[:3, 3] - Tm[:3, 3]) / (2 * h), atol=1e-7)
        dR = (Tp[:3, :3] - Tm[:3, :3]) / (2 * h) @ T[:3, :3].T  # skew(omega)
        np.testing.assert_allclose(J[3:, j], [dR[2, 1], dR[0, 2], dR[1, 0]], atol=1e-7)


@pytest.mark.parametrize("name", ["eosma7", "scara4", "panda"])
def test_solve_with_a_tool_frame(name):
    robot = get_robot(name)
    tool = np.eye(4)
    tool[:3, :3] = Rotation.from_euler("xyz", [0.3, -0.2, 0.5]).as_matrix()
    tool[:3, 3] = np.array([0.02, -0.01, 0.15]) * robot.reach
    mounted = replace(robot, tool=tool, base=_rigid(9, robot.reach / 5))
    q0 = mounted.random_q(1, rng=np.random.default_rng(5))[0]
    target = mounted.fk(q0)
    res = solve_ik(mounted, target, seed=0)
    assert res.status == "solved"
    T = mounted.fk(res.q)
    assert np.linalg.norm(T[:3, 3] - target[:3, 3]) == pytest.approx(res.position_error,
                                                                     abs=1e-12 * robot.reach)
    assert res.position_error <= 1e-9 * mounted.reach and res.orientation_error <= 1e-9
    # the same q on the bare robot misses the target by the tool and base transforms
    assert np.linalg.norm(robot.fk(res.q)[:3, 3] - target[:3, 3]) > 1e-3 * robot.reach


def test_locked_joints_keep_base_tool_and_names():
    robot, mounted = _mounted("panda", seed=6)
    sub = mounted.with_locked_joints({1: 0.2, 5: 1.0})
    np.testing.assert_array_equal(sub.base, mounted.base)
    np.testing.assert_array_equal(sub.tool, mounted.tool)
    assert sub.joint_names == tuple(f"panda_joint{j}" for j in (1, 3, 4, 5, 7))
    Qs = sub.random_q(20, rng=np.random.default_rng(7))
    Q = np.insert(np.insert(Qs, 1, 0.2, axis=1), 5, 1.0, axis=1)
    np.testing.assert_allclose(sub.fk(Qs), mounted.fk(Q), atol=1e-12 * mounted.reach)
    np.testing.assert_allclose(fk_reference(sub, Qs), mounted.fk(Q), atol=1e-12 * mounted.reach)


def test_pickle_keeps_base_and_tool():
    _, mounted = _mounted("irb2600")
    again = pickle.loads(pickle.dumps(mounted))
    np.testing.assert_array_equal(again.base, mounted.base)
    Q = mounted.random_q(5, rng=np.random.default_rng(0))
    np.testing.assert_array_equal(again.fk(Q), mounted.fk(Q))


@pytest.mark.parametrize(("value", "error", "message"), [
    (np.eye(3), ShapeError, r"robot 'x' base must have shape \(4, 4\), got \(3, 3\)"),
    ([["a"] * 4] * 4, ShapeError, "must be an array of real numbers, got strings"),
    (np.full((4, 4), np.nan), NonFiniteError, "finite"),
    (np.diag([1.0, 1.0, 2.0, 1.0]), ParameterError, "orthonormal with determinant \\+1"),
    (np.diag([1.0, 1.0, -1.0, 1.0]), ParameterError, "orthonormal with determinant \\+1"),
    (np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1.0]]), ParameterError,
     r"last row \[0, 0, 0, 1\]"),
])
def test_bad_base_and_tool(value, error, message):
    robot = get_robot("planar2")
    with pytest.raises(error, match=message):
        replace(robot, name="x", base=value)
    with pytest.raises(error, match=message.replace("base", "tool")):
        replace(robot, name="x", tool=value)


def test_joint_names():
    assert get_robot("eosma7").joint_names == tuple(f"q{j}" for j in range(1, 8))
    assert get_robot("iiwa14").joint_names == tuple(f"joint_a{j}" for j in range(1, 8))
    assert get_robot("panda").joint_names == tuple(f"panda_joint{j}" for j in range(1, 8))
    assert get_robot("ur5").joint_names == (
        "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
        "wrist_2_joint", "wrist_3_joint")
    assert get_robot("puma560-urdf").joint_names == tuple(f"j{j}" for j in range(1, 7))
    urdf = """<robot name="two"><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
      <joint name="hip" type="revolute"><parent link="a"/><child link="b"/>
        <limit lower="-1" upper="1"/></joint>
      <joint name="glue" type="fixed"><parent link="b"/><child link="c"/></joint>
      <joint name="slide" type="prismatic"><parent link="c"/><child link="d"/>
        <limit lower="0" upper="0.5"/></joint></robot>"""
    robot = load_urdf(urdf)
    assert robot.joint_names == ("hip", "slide") and robot.joint_types[1] == "prismatic"
    assert replace(robot, source="other").joint_names == ("hip", "slide")


@pytest.mark.parametrize(("names", "message"), [
    ("q1q2", "joint_names must be a sequence of 2 names, got the string"),
    (("a",), "joint_names must be 2 distinct non-empty strings"),
    (("a", "a"), "joint_names must be 2 distinct non-empty strings"),
    (("a", 3), "joint_names must be 2 distinct non-empty strings"),
    (("a", ""), "joint_names must be 2 distinct non-empty strings"),
])
def test_bad_joint_names(names, message):
    with pytest.raises(ParameterError, match=message):
        replace(get_robot("planar2"), joint_names=names)
