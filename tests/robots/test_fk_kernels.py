"""Compiled FK kernels against the plain-numpy oracle ``fk_reference``.

Every kernel (4x4 poses, positions, rotations + positions, per-joint frames, the
single-row kernels) on every catalog robot, on robots with locked joints, on DH
chains with offsets and prismatic joints in both conventions, and on general
chains loaded from URDF text written here (non-z axes, rpy origins, fixed and
prismatic joints), and on robots with base and tool transforms. Tolerance: 1e-12
relative to the robot's size.
"""

import pickle
from dataclasses import replace

import numba
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from moik.exceptions import DegreesWarning, ShapeError
from moik.robots import Robot, available_robots, fk_kernels, fk_reference, get_robot
from moik.robots.transforms import fk_general_reference
from moik.robots.urdf import load_urdf

TOL = 1e-12

# A 7-joint URDF chain: axes along +-x, +-y, -z and a skew axis, rpy origins,
# fixed joints inside and at the tip, one prismatic and one continuous joint.
URDF = """<robot name="skewed">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="l3b"/>
  <link name="l4"/><link name="l5"/><link name="l6"/><link name="l7"/><link name="tip"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0.01 -0.02 0.3" rpy="0.1 -0.2 0.3"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="0 0.05 0.25" rpy="1.5707963267948966 0 0"/><axis xyz="0 -1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="j3" type="prismatic"><parent link="l2"/><child link="l3"/>
    <origin xyz="0.2 0 0" rpy="0 0.4 0"/><axis xyz="0 1 0"/>
    <limit lower="-0.1" upper="0.3" effort="1" velocity="1"/></joint>
  <joint name="fixed_mid" type="fixed"><parent link="l3"/><child link="l3b"/>
    <origin xyz="0.03 0.02 0.01" rpy="-0.7 0.2 1.1"/></joint>
  <joint name="j4" type="continuous"><parent link="l3b"/><child link="l4"/>
    <origin xyz="0 0 0.1" rpy="0 0 0"/><axis xyz="0.3 -0.5 0.8"/></joint>
  <joint name="j5" type="revolute"><parent link="l4"/><child link="l5"/>
    <origin xyz="0.1 0.1 0" rpy="3.141592653589793 0 0"/><axis xyz="0 0 -1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j6" type="revolute"><parent link="l5"/><child link="l6"/>
    <origin xyz="0 0 0.08" rpy="0 -1.5707963267948966 0.25"/><axis xyz="-1 0 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j7" type="revolute"><parent link="l6"/><child link="l7"/>
    <origin xyz="0.02 0 0.05" rpy="0.3 0.3 0.3"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="tool" type="fixed"><parent link="l7"/><child link="tip"/>
    <origin xyz="0 0.01 0.12" rpy="0.2 0 -0.4"/></joint>
</robot>"""


def urdf_robot(tmp_path) -> Robot:
    path = tmp_path / "skewed.urdf"
    path.write_text(URDF)
    return load_urdf(path)


def dh_variants() -> list[Robot]:
    """DH chains with angle offsets and prismatic joints, standard and modified."""
    rows = dict(a=[0.1, 0.3, 0.0, 0.05], alpha=[np.pi / 2, 0.3, -np.pi / 2, np.pi],
                d=[0.2, 0.1, 0.05, 0.1], theta=[0.4, np.pi / 2, -0.2, 0.0],
                lower=[-3, -3, 0.0, -3], upper=[3, 3, 0.4, 3],
                joint_types=("revolute", "revolute", "prismatic", "revolute"))
    return [Robot(name="dh-std", **rows), Robot(name="dh-mod", convention="modified", **rows)]


def rigid(seed: int, scale: float) -> np.ndarray:
    """A random rigid transform with a translation of about ``scale``."""
    T = np.eye(4)
    T[:3, :3] = Rotation.random(random_state=seed).as_matrix()
    T[:3, 3] = np.random.default_rng(seed).normal(scale=scale, size=3)
    return T


def with_base_tool(robot: Robot, seed: int) -> Robot:
    """``robot`` mounted on a random base, with a random tool frame."""
    return replace(robot, name=f"{robot.name}+base+tool", base=rigid(seed, robot.reach / 4),
                   tool=rigid(seed + 1, robot.reach / 10))


def all_robots(tmp_path) -> list[Robot]:
    robots = [get_robot(name) for name in available_robots()]
    robots += [get_robot("puma560").with_locked_joints({1: 0.3, 4: -0.2}),
               get_robot("scara4").with_locked_joints({2: 0.15}),
               get_robot("irb2600").with_locked_joints({0: 1.0})]
    robots += dh_variants() + [urdf_robot(tmp_path)]
    mounted = [with_base_tool(robots[k], k) for k in (0, 5, 10, len(robots) - 1)]
    mounted.append(with_base_tool(robots[-1], 7).with_locked_joints({2: 0.1}))
    return robots + mounted


def _scale(robot: Robot) -> float:
    return TOL * max(1.0, robot.reach)


def test_every_kernel_equals_reference(tmp_path):
    for robot in all_robots(tmp_path):
        for n in (1, 3, 4, 64, 150):  # single-row path, one block, blocks + remainder
            Q = robot.random_q(n, rng=np.random.default_rng(n))
            T_ref = fk_reference(robot, Q)
            np.testing.assert_allclose(robot.fk(Q), T_ref, rtol=0, atol=_scale(robot),
                                       err_msg=robot.name)
            np.testing.assert_allclose(robot.fk_position(Q), T_ref[:, :3, 3], rtol=0,
                                       atol=_scale(robot))
            R, p = robot.fk_parts(Q)
            np.testing.assert_allclose(R, T_ref[:, :3, :3], rtol=0, atol=TOL)
            np.testing.assert_allclose(p, T_ref[:, :3, 3], rtol=0, atol=_scale(robot))
            frames = robot.frames(Q)
            np.testing.assert_allclose(frames[:, -1], T_ref, rtol=0, atol=_scale(robot))


def test_general_chain_frames_are_partial_products(tmp_path):
    """Frame j of a general chain is F_0 M_1 F_1 ... M_j F_j."""
    robot = urdf_robot(tmp_path)
    F, prismatic = robot.origins, robot.is_prismatic
    Q = robot.random_q(5, rng=np.random.default_rng(0))
    frames = robot.frames(Q)
    np.testing.assert_array_equal(frames[:, 0], np.broadcast_to(np.eye(4), (5, 4, 4)))
    for j in range(1, robot.dof + 1):
        expected = fk_general_reference(F[:j + 1], prismatic[:j], Q[:, :j])
        np.testing.assert_allclose(frames[:, j], expected, atol=TOL)


@numba.njit
def _rows_one_by_one(F, types, Q, T, p):
    for i in range(Q.shape[0]):
        fk_kernels.fk_pose_into(F, types, Q[i], T[i])
        fk_kernels.fk_position_into(F, types, Q[i], p[i])


def test_single_row_kernels_bit_identical_to_batched(tmp_path):
    """The block kernels and the single-row kernels (callable from compiled code)
    do the same operations: same bits, whatever the batch a row is in."""
    for robot in all_robots(tmp_path):
        chain = robot.kinematic_chain
        Q = robot.random_q(150, rng=np.random.default_rng(7))
        T1, p1 = np.empty((150, 4, 4)), np.empty((150, 3))
        _rows_one_by_one(chain.origins, chain.joint_types, Q, T1, p1)
        T = robot.fk(Q)
        np.testing.assert_array_equal(T, T1, err_msg=robot.name)
        np.testing.assert_array_equal(robot.fk_position(Q), p1)
        for i in (0, 63, 64, 149):
            np.testing.assert_array_equal(robot.fk(Q[i]), T[i])
            np.testing.assert_array_equal(robot.fk(Q[i:i + 2])[0], T[i])


def test_joint_values_beyond_inline_trigonometry_range():
    """Rows with |q| > TRIG_MAX take libm's sin/cos; the rest of the block is unchanged."""
    robot = get_robot("eosma7")
    Q = robot.random_q(80, rng=np.random.default_rng(1))
    Q[5, 2] = 3.0e6
    Q[70, 0] = -1.0e9
    with pytest.warns(DegreesWarning, match="look like degrees"):  # they do: legal, suspicious
        T, reference = robot.fk(Q), fk_reference(robot, Q)
    np.testing.assert_allclose(T, reference, rtol=0, atol=_scale(robot))
    np.testing.assert_array_equal(T[6:70], robot.fk(Q[6:70]))


def test_non_finite_joint_values_give_non_finite_poses():
    robot = dh_variants()[0]
    chain = robot.kinematic_chain
    for j, bad in ((0, np.nan), (2, np.inf), (3, -np.inf)):
        Q = np.zeros((5, robot.dof))
        Q[1, j] = bad
        T = np.empty((5, 4, 4))
        fk_kernels.fk_poses(chain.origins, chain.joint_types, Q, T)
        assert not np.all(np.isfinite(T[1]))
        assert np.all(np.isfinite(np.delete(T, 1, axis=0)))


def test_kinematic_chain_is_the_general_form(tmp_path):
    for robot in all_robots(tmp_path):
        chain = robot.kinematic_chain
        assert chain is robot.kinematic_chain  # built once
        assert chain.dof == robot.dof
        assert chain.origins.shape == (robot.dof + 1, 4, 4)
        assert chain.link_frames.shape == (robot.dof, 4, 4)
        np.testing.assert_array_equal(chain.origins, robot.chain_origins())
        np.testing.assert_array_equal(chain.joint_types == fk_kernels.PRISMATIC, robot.is_prismatic)
        for arr in (chain.origins, chain.joint_types, chain.link_frames):
            assert arr.flags.c_contiguous and not arr.flags.writeable
        again = pickle.loads(pickle.dumps(robot)).kinematic_chain
        assert not again.origins.flags.writeable and not again.joint_types.flags.writeable
        np.testing.assert_array_equal(again.origins, chain.origins)


@st.composite
def general_chains(draw):
    dof = draw(st.integers(1, 8))
    seed = draw(st.integers(0, 2**32 - 1))
    rng = np.random.default_rng(seed)
    origins = np.tile(np.eye(4), (dof + 1, 1, 1))
    origins[:, :3, :3] = Rotation.random(dof + 1, random_state=seed).as_matrix()
    origins[:, :3, 3] = rng.normal(size=(dof + 1, 3))
    types = tuple(draw(st.sampled_from(["revolute", "prismatic"])) for _ in range(dof))
    robot = Robot(name="random", origins=origins, lower=-4 * np.ones(dof),
                  upper=4 * np.ones(dof), joint_types=types)
    return robot, robot.random_q(draw(st.integers(1, 70)), rng=rng)


@settings(max_examples=60, deadline=None)
@given(general_chains())
def test_random_general_chains_equal_reference(chain_and_q):
    robot, Q = chain_and_q
    np.testing.assert_allclose(robot.fk(Q), fk_reference(robot, Q), rtol=0,
                               atol=_scale(robot))


@pytest.mark.parametrize("name", ["eosma7", "irb2600"])
def test_reference_is_independent_of_general_form(name):
    """fk_reference of a DH robot multiplies textbook DH matrices; the general-form
    reference from chain_origins agrees with it."""
    robot = get_robot(name)
    Q = robot.random_q(20, rng=np.random.default_rng(2))
    np.testing.assert_allclose(
        fk_general_reference(robot.chain_origins(), robot.is_prismatic, Q),
        fk_reference(robot, Q), atol=_scale(robot))


def test_hot_paths_check_the_batch_shape():
    """No finiteness check on the hot paths, but the shape is checked: a kernel
    given fewer columns would read past the array."""
    robot = get_robot("eosma7")
    for fn in (robot.fk_position, robot.fk_parts, robot.kernel_batch):
        with pytest.raises(ShapeError, match=r"must have shape \(n, 7\), got \(4, 6\)"):
            fn(np.zeros((4, 6)))
        with pytest.raises(ShapeError, match=r"got \(7,\)"):
            fn(np.zeros(7))
