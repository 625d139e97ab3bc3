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
