"""solve_path: the MO-m-PSO circle tracked on one branch."""

import numpy as np
import pytest

from moik.exceptions import ParameterError
from moik.problems import circle_path
from moik.robots import get_robot
from moik.solver import solve_path


def test_circle_path_tracked_continuously():
    """MO-m-PSO Section 4.4: 50 points, centre (15, 0, 12) cm, radius 8 cm."""
    robot = get_robot("rokbani5")
    res = solve_path(robot, circle_path([15, 0, 12], 8, 50), seed=0)
    assert res.success.all()
    assert res.position_errors.max() <= 1e-9 * robot.reach
    assert np.all(robot.within_limits(res.Q))
    assert res.warm_started[1:].all()  # every point after the first from its neighbour
    assert res.max_joint_step < 0.2  # 7.2 deg of arc per point: no branch jump


def test_path_is_deterministic():
    robot = get_robot("rokbani5")
    pts = circle_path([15, 0, 12], 8, 10)
    np.testing.assert_array_equal(solve_path(robot, pts, seed=1).Q,
                                  solve_path(robot, pts, seed=1).Q)


def test_bad_input():
    robot = get_robot("rokbani5")
    with pytest.raises(ParameterError, match="at least one target"):
        solve_path(robot, [])
    with pytest.raises(ParameterError, match="solve_path sets 'q_current' itself"):
        solve_path(robot, circle_path([15, 0, 12], 8, 3), **{"q_current": None})
