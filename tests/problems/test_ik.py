"""IK problems: zero at the generating joint vector, formulas, bad input."""

import numpy as np
import pytest

from moik.exceptions import NonFiniteError, ParameterError, ShapeError, TargetError
from moik.kinematics.orientation import eosma_euler
from moik.problems import BiObjectiveIK, PoseIK, PositionIK, Target, random_reachable_targets
from moik.robots import available_robots, get_robot


@pytest.mark.parametrize("name", available_robots())
def test_zero_error_at_source_configuration(name):
    robot = get_robot(name)
    for target in random_reachable_targets(robot, 5, seed=7):
        X = target.q_source[None]
        problems = [PositionIK(robot, target.position),
                    PoseIK(robot, target), PoseIK(robot, target, orientation="geodesic"),
                    PoseIK(robot, target, orientation="frobenius"),
                    BiObjectiveIK(robot, target), BiObjectiveIK(robot, target,
                                                                orientation="zyx-euler")]
        for problem in problems:
            F = problem.evaluate(X)
            assert np.all(F < 1e-12), (type(problem).__name__, F)


def test_eosma_pose_objective_formula():
    """Eq. 28-30 by hand for one configuration."""
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=1)[0]
    q = robot.random_q(1, rng=np.random.default_rng(5))
    T = robot.fk(q[0])
    f1 = np.linalg.norm(T[:3, 3] - target.position)
    f2 = np.linalg.norm(eosma_euler(T[:3, :3]) - eosma_euler(target.rotation))
    F = PoseIK(robot, target, weights=(0.3, 0.7), orientation="eosma-euler").evaluate(q)
    assert F[0, 0] == pytest.approx(0.3 * f1 + 0.7 * f2, rel=1e-12)
    F2 = BiObjectiveIK(robot, target, orientation="eosma-euler").evaluate(q)
    np.testing.assert_allclose(F2[0], [f1, f2], rtol=1e-12)


def test_displacement_term_eq31():
    robot = get_robot("eosma7")
    q0 = np.zeros(7)
    target = Target(robot.fk(q0)[:3, 3])
    q = np.full((1, 7), 0.1)
    base = PositionIK(robot, target).evaluate(q)[0, 0]
    pen = PositionIK(robot, target, displacement_weight=2.0, q_start=q0).evaluate(q)[0, 0]
    assert pen - base == pytest.approx(2.0 * np.linalg.norm(q[0]), rel=1e-12)


def test_bounds_are_joint_limits():
    robot = get_robot("irb2600")
    problem = PositionIK(robot, [500.0, 0.0, 1000.0])
    np.testing.assert_array_equal(problem.xl, robot.lower)
    np.testing.assert_array_equal(problem.xu, robot.upper)
    assert (problem.n_var, problem.n_obj) == (6, 1)
    assert BiObjectiveIK(robot, np.eye(4)).n_obj == 2


def test_bad_input():
    robot = get_robot("eosma7")
    with pytest.raises(TargetError, match="needs a target with an orientation"):
        PoseIK(robot, [10.0, 0.0, 50.0])
    with pytest.raises(ParameterError, match="weights must be two finite non-negative"):
        PoseIK(robot, np.eye(4), weights=(0.0, 0.0))
    with pytest.raises(ParameterError, match="weights must be two finite non-negative"):
        PoseIK(robot, np.eye(4), weights=(-0.5, 1.5))
    with pytest.raises(ParameterError, match="needs q_start"):
        PositionIK(robot, [10.0, 0.0, 50.0], displacement_weight=1.0)
    with pytest.raises(ShapeError, match=r"q_start for robot 'eosma7' must have shape"):
        PositionIK(robot, [10.0, 0.0, 50.0], displacement_weight=1.0, q_start=np.zeros(3))
    with pytest.raises(TargetError, match=r"more than 10x its reach .* expected a position in cm"):
        PositionIK(robot, [5000.0, 0.0, 0.0])  # mm given to a cm robot
    with pytest.raises(NonFiniteError, match="joint values contain NaN"):
        PositionIK(robot, [10.0, 0.0, 50.0]).evaluate(np.full((2, 7), np.nan))
    with pytest.raises(ParameterError, match="robot must be a moik Robot"):
        PositionIK("eosma7", [10.0, 0.0, 50.0])
