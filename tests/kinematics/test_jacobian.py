"""Geometric Jacobian checked against finite differences of the FK."""

import numba
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from moik.kinematics.jacobian import (
    jacobian,
    parts_and_jacobian,
    pose_and_jacobian,
    pose_jacobian_into,
)
from moik.robots import Robot, available_robots, fk_reference, get_robot


def _finite_difference_jacobian(robot, q, h=1e-6):
    J = np.zeros((6, robot.dof))
    T0 = robot.fk(q)
    for j in range(robot.dof):
        dq = np.zeros(robot.dof)
        dq[j] = h
        Tp, Tm = robot.fk(q + dq), robot.fk(q - dq)
        J[:3, j] = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
        # angular velocity: rotation vector of R(q+h) R(q-h)^T over 2h
        J[3:, j] = Rotation.from_matrix(Tp[:3, :3] @ Tm[:3, :3].T).as_rotvec() / (2 * h)
    return T0, J


@pytest.mark.parametrize("name", available_robots())
def test_jacobian_matches_finite_differences(name):
    robot = get_robot(name)
    rng = np.random.default_rng(11)
    Q = robot.random_q(3, rng=rng)
    T, J = pose_and_jacobian(robot, Q)
    assert J.shape == (3, 6, robot.dof)
    for i in range(3):
        T_fd, J_fd = _finite_difference_jacobian(robot, Q[i])
        np.testing.assert_allclose(T[i], T_fd, atol=1e-12 * max(1, robot.reach))
        scale = max(1.0, robot.reach)
        np.testing.assert_allclose(J[i, :3], J_fd[:3], atol=1e-6 * scale)
        np.testing.assert_allclose(J[i, 3:], J_fd[3:], atol=1e-6)


def test_single_configuration_shape():
    robot = get_robot("eosma7")
    assert jacobian(robot, np.zeros(7)).shape == (6, 7)


def _test_robots() -> list[Robot]:
    """Catalog arms, locked joints, and general chains with prismatic joints."""
    robots = [get_robot(name) for name in available_robots()]
    robots += [get_robot("puma560").with_locked_joints({2: 0.4}),
               get_robot("scara4").with_locked_joints({0: -0.3})]
    rng = np.random.default_rng(0)
    for k, types in enumerate([("prismatic", "revolute", "revolute", "prismatic", "revolute"),
                               ("revolute",) * 6]):
        origins = np.tile(np.eye(4), (len(types) + 1, 1, 1))
        origins[:, :3, :3] = Rotation.random(len(types) + 1, random_state=k).as_matrix()
        origins[:, :3, 3] = rng.normal(size=(len(types) + 1, 3))
        robots.append(Robot(name=f"general{k}", origins=origins, lower=-2 * np.ones(len(types)),
                            upper=2 * np.ones(len(types)), joint_types=types))
    return robots


ROBOTS = _test_robots()


def _reference_jacobian(robot, q, h=1e-6):
    """Central differences of fk_reference: linear rows from positions, angular rows
    from the rotation vector of R(q + h) R(q - h)^T."""
    E = np.eye(robot.dof) * h
    Tp, Tm = fk_reference(robot, q + E), fk_reference(robot, q - E)
    J = np.empty((6, robot.dof))
    J[:3] = ((Tp[:, :3, 3] - Tm[:, :3, 3]) / (2 * h)).T
    J[3:] = (Rotation.from_matrix(Tp[:, :3, :3] @ np.swapaxes(Tm[:, :3, :3], 1, 2)).as_rotvec()
             / (2 * h)).T
    return J


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(range(len(ROBOTS))), st.integers(0, 2**32 - 1))
def test_jacobian_matches_finite_differences_of_reference(index, seed):
    robot = ROBOTS[index]
    q = robot.random_q(1, rng=np.random.default_rng(seed))[0]
    T, J = pose_and_jacobian(robot, q)
    np.testing.assert_allclose(T, fk_reference(robot, q), atol=1e-12 * max(1.0, robot.reach))
    J_ref = _reference_jacobian(robot, q)
    np.testing.assert_allclose(J[:3], J_ref[:3], atol=1e-6 * max(1.0, robot.reach))
    np.testing.assert_allclose(J[3:], J_ref[3:], atol=1e-6)


@pytest.mark.parametrize("index", range(len(ROBOTS)))
def test_jacobian_pose_is_the_fk_pose(index):
    """Same chain walk as the FK kernels: the pose is robot.fk's, bit for bit."""
    robot = ROBOTS[index]
    Q = robot.random_q(70, rng=np.random.default_rng(index))
    T, J = pose_and_jacobian(robot, Q)
    np.testing.assert_array_equal(T, robot.fk(Q))
    R, p, J2 = parts_and_jacobian(robot, Q)
    np.testing.assert_array_equal(R, T[:, :3, :3])
    np.testing.assert_array_equal(p, T[:, :3, 3])
    np.testing.assert_array_equal(J2, J)
    prismatic = robot.is_prismatic
    np.testing.assert_array_equal(J[:, 3:, prismatic], 0.0)


@numba.njit
def _compiled_caller(F, types, q):
    T = np.empty((4, 4))
    J = np.empty((6, types.size))
    pose_jacobian_into(F, types, q, T, J)
    return T, J


def test_kernel_callable_from_compiled_code():
    robot = get_robot("sawyer7")
    chain = robot.kinematic_chain
    q = robot.random_q(1, rng=np.random.default_rng(3))[0]
    T, J = _compiled_caller(chain.origins, chain.joint_types, q)
    T_ref, J_ref = pose_and_jacobian(robot, q)
    np.testing.assert_array_equal(T, T_ref)
    np.testing.assert_array_equal(J, J_ref)
