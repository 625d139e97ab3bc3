"""Bounded least-squares refinement: an exact residual Jacobian, iterates within the limits."""

import numpy as np

from moik.problems import Target, random_reachable_targets
from moik.robots import get_robot
from moik.solver.polish import ResidualModel, polish
from moik.solver.session import pose_errors


def test_pose_residual_jacobian_exact_away_from_solution():
    """The orientation rows include J_l^{-1}: exact even for large residuals."""
    robot = get_robot("eosma7")
    target = Target([-25.0, 100.0, 50.0], np.eye(3))  # EOSMA P1, unreachable
    q = robot.random_q(1, rng=np.random.default_rng(2))[0]
    model = ResidualModel(robot, target, robot.reach)
    J = model.jacobian(q)
    h = 1e-6
    J_fd = np.array([(model.residual(q + h * e) - model.residual(q - h * e)) / (2 * h)
                     for e in np.eye(7)]).T
    np.testing.assert_allclose(J, J_fd, atol=1e-7)


def test_refines_a_nearby_start_within_the_limits():
    robot = get_robot("puma560")
    target = random_reachable_targets(robot, 1, seed=3)[0]
    q0 = np.clip(target.q_source + 0.05, robot.lower, robot.upper)
    out = polish(robot, target, q0, length=robot.reach, stop_position=1e-12 * robot.reach,
                 stop_orientation=1e-12)
    assert out.stationary and robot.within_limits(out.q)[0]
    pos, ori = pose_errors(robot, target, out.q)
    assert pos[0] <= 1e-10 * robot.reach and ori[0] <= 1e-10
