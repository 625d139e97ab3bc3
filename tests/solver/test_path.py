"""solve_path: the MO-m-PSO circle tracked on one branch."""

import numpy as np
import pytest

from moik.exceptions import ParameterError, TargetError, UnknownNameError
from moik.problems import circle_path
from moik.robots import get_robot
from moik.solver import solve_path, solve_paths


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
    with pytest.raises(ParameterError, match="unknown parameter\\(s\\) pop for solve_path"):
        solve_path(robot, circle_path([15, 0, 12], 8, 3), pop=20)
    with pytest.raises(ParameterError, match="first_branches must be an integer >= 1, got 2.0"):
        solve_path(robot, circle_path([15, 0, 12], 8, 3), first_branches=2.0)
    with pytest.raises(ParameterError, match=r"max_step must be a (positive )?finite number"):
        solve_path(robot, circle_path([15, 0, 12], 8, 3), max_step=0)
    with pytest.raises(ParameterError, match="seed must be a non-negative integer"):
        solve_path(robot, circle_path([15, 0, 12], 8, 3), seed=-2)


def test_solve_options_are_validated_even_when_warm_starts_do_everything():
    """With q_start on the path every target is solved by a warm start and
    solve_ik never runs; its options are checked up front all the same."""
    robot = get_robot("rokbani5")
    pts = circle_path([15, 0, 12], 8, 5)
    start = solve_path(robot, pts, seed=0)
    assert start.warm_started[1:].all()
    res = solve_path(robot, pts, q_start=start.Q[0], seed=0)
    assert res.warm_started.all()
    with pytest.raises(UnknownNameError, match="unknown orientation metric 'bogus'"):
        solve_path(robot, pts, q_start=start.Q[0], orientation="bogus")
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2, got 1"):
        solve_path(robot, pts, q_start=start.Q[0], pop_size=1)
    with pytest.raises(UnknownNameError, match="unknown algorithm 'nope'"):
        solve_path(robot, pts, q_start=start.Q[0], method="nope")


def test_many_paths_on_a_pool_are_each_solve_path():
    robot = get_robot("rokbani5")
    paths = [circle_path([15, 0, 12], r, 6) for r in (6, 7, 8)]
    fields = ("Q", "position_errors", "orientation_errors", "success", "statuses",
              "warm_started", "joint_steps", "max_joint_step", "n_eval")
    serial = solve_paths(robot, paths, workers=1, seed=2)
    pooled = solve_paths(robot, paths, workers=2, seed=2)
    for k, path in enumerate(paths):
        alone = solve_path(robot, path, seed=2)
        for field in fields:
            np.testing.assert_array_equal(getattr(serial[k], field), getattr(alone, field))
            np.testing.assert_array_equal(getattr(pooled[k], field), getattr(alone, field))
    with pytest.raises(TargetError, match="sequence of paths"):
        solve_paths(robot, "abc")
