"""Geometric Jacobian checked against finite differences of the FK."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from moik.kinematics.jacobian import jacobian, pose_and_jacobian
from moik.robots import available_robots, get_robot


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


def test_pose_residual_jacobian_exact_away_from_solution():
    """The orientation rows include J_l^{-1}: exact even for large residuals."""
    from moik.kinematics.polish import pose_residual, pose_residual_jacobian
    from moik.problems import Target

    robot = get_robot("eosma7")
    target = Target([-25.0, 100.0, 50.0], np.eye(3))  # EOSMA P1, unreachable
    q = robot.random_q(1, rng=np.random.default_rng(2))[0]
    J = pose_residual_jacobian(robot, target, robot.reach, q)
    h = 1e-6
    J_fd = np.array([(pose_residual(robot, target, robot.reach, q + h * e)
                      - pose_residual(robot, target, robot.reach, q - h * e)) / (2 * h)
                     for e in np.eye(7)]).T
    np.testing.assert_allclose(J, J_fd, atol=1e-7)
