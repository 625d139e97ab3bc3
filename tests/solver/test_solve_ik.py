"""solve_ik: exact, within limits, deterministic, several branches, honest failures."""

import numpy as np
import pytest

from moik.exceptions import ParameterError, UnknownNameError
from moik.problems import Target, random_reachable_targets
from moik.robots import get_robot
from moik.solver import solve_ik
from moik.solver.session import joint_distance


@pytest.mark.parametrize("name", ["eosma7", "sawyer7", "irb2600"])
def test_reachable_poses_are_solved_exactly(name):
    robot = get_robot(name)
    for i, target in enumerate(random_reachable_targets(robot, 4, seed=1)):
        res = solve_ik(robot, target.pose, seed=i)
        assert res.status == "solved" and res.success
        assert res.position_error <= 1e-9 * robot.reach
        assert res.orientation_error <= 1e-9
        assert robot.within_limits(res.q)[0]
        # errors are the FK truth, not the optimizer's word
        T = robot.fk(res.q)
        assert np.linalg.norm(T[:3, 3] - target.position) == pytest.approx(
            res.position_error, abs=1e-12 * robot.reach)


def test_local_first_attempt_solves_most_reachable_poses():
    """The batched Levenberg-Marquardt attempt (16 starts, <= 30 iterations:
    at most 16 * 31 FK evaluations) ends most solves before any global search;
    with starts=0 the global search alone still solves them."""
    robot = get_robot("eosma7")
    targets = random_reachable_targets(robot, 20, seed=4)
    local = [solve_ik(robot, t, seed=i) for i, t in enumerate(targets)]
    assert all(r.success for r in local)
    assert sum(r.n_eval <= 16 * 31 for r in local) >= 16
    searched = [solve_ik(robot, t, seed=i, starts=0) for i, t in enumerate(targets[:4])]
    assert all(r.success for r in searched)
    several = solve_ik(robot, targets[0], n_solutions=3, seed=0)  # 16 starts converge
    assert several.solutions.shape == (3, robot.dof)  # no more than asked for


def test_position_only_target():
    robot = get_robot("rokbani5")
    res = solve_ik(robot, [25.1441, 9.5735, 18.0927], seed=3)  # MO-m-PSO Section 4.1 target
    assert res.success and res.orientation_error == 0.0
    assert res.position_error <= 1e-9 * robot.reach


def test_same_seed_same_result_bit_for_bit():
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=9)[0]
    a = solve_ik(robot, target.pose, seed=42)
    b = solve_ik(robot, target.pose, seed=42)
    np.testing.assert_array_equal(a.q, b.q)
    assert a.n_eval == b.n_eval


# I-BES paper Section 5.1.3: the five wrist-centre targets (m) of the Puma 560
# comparison with the geometric method (Kalra et al.); each has 4 branches.
IBES_TABLE9_TARGETS = [(0.60, 0.15, 0.20), (0.50, 0.24, 0.23), (0.54, 0.21, 0.26),
                       (0.18, -0.40, 0.40), (-0.18, 0.40, -0.20)]


@pytest.mark.parametrize("position", IBES_TABLE9_TARGETS)
def test_puma_wrist_centre_has_four_branches(position):
    robot = get_robot("puma560").with_locked_joints({3: 0.0, 4: 0.0, 5: 0.0})
    res = solve_ik(robot, np.array(position), n_solutions=4, seed=0)
    assert res.solutions.shape == (4, 3)
    for q in res.solutions:
        assert np.linalg.norm(robot.fk(q)[:3, 3] - position) <= 1e-9 * robot.reach
    for i in range(4):  # pairwise distinct configurations
        others = np.delete(res.solutions, i, axis=0)
        assert np.all(joint_distance(robot, res.solutions[i], others) > 0.1)


def test_q_current_prefers_nearest_solution():
    robot = get_robot("puma560").with_locked_joints({3: 0.0, 4: 0.0, 5: 0.0})
    position = np.array(IBES_TABLE9_TARGETS[1])
    branches = solve_ik(robot, position, n_solutions=4, seed=0).solutions
    current = branches[2] + 0.05
    res = solve_ik(robot, position, n_solutions=4, seed=0, q_current=current)
    assert res.q == pytest.approx(branches[2], abs=1e-6)


def test_unreachable_position_is_reported_not_solved():
    robot = get_robot("eosma7")
    res = solve_ik(robot, [0.0, 0.0, 300.0], seed=0)  # reach is 176 cm
    assert res.status == "unreachable" and not res.success
    assert robot.within_limits(res.q)[0]
    assert res.position_error > 100.0
    assert res.front is None


def test_unreachable_pose_returns_front():
    """EOSMA paper P1 = (-25, 100, 50) cm with the identity orientation cannot be
    reached (reference-facts.md: checked by multi-start least squares)."""
    robot = get_robot("eosma7")
    res = solve_ik(robot, Target([-25.0, 100.0, 50.0], np.eye(3)), seed=0, front_evals=4000)
    assert res.status == "unreachable" and not res.success
    assert res.front is not None and len(res.front) >= 2
    assert np.all(robot.within_limits(res.front_q))
    assert robot.within_limits(res.q)[0]


def test_bad_input():
    robot = get_robot("eosma7")
    with pytest.raises(ParameterError, match="tol must be a number or"):
        solve_ik(robot, [10.0, 0.0, 50.0], tol=(1, 2, 3))
    with pytest.raises(ParameterError, match="n_solutions must be an integer >= 1"):
        solve_ik(robot, [10.0, 0.0, 50.0], n_solutions=0)
    reachable = random_reachable_targets(robot, 1, seed=0)[0]  # solved before any search
    with pytest.raises(UnknownNameError, match="unknown algorithm 'nope'"):
        solve_ik(robot, reachable, method="nope")
    with pytest.raises(UnknownNameError, match="unknown algorithm 'nope'"):
        solve_ik(robot, reachable, front_method="nope")
    with pytest.raises(ParameterError, match="method must be a single-objective"):
        solve_ik(robot, reachable, method="moeosma")
    with pytest.raises(ParameterError, match="front_method must be a multi-objective"):
        solve_ik(robot, reachable, front_method="eosma")
    with pytest.raises(ParameterError, match="starts must be an integer >= 0"):
        solve_ik(robot, reachable, starts=2.5)


def test_every_argument_is_validated_whichever_stage_ends_the_solve():
    """The batched first attempt solves these targets, so a check made only when
    the search starts would never run: every bad value must raise all the same."""
    robot = get_robot("eosma7")
    reachable = random_reachable_targets(robot, 1, seed=0)[0]
    assert solve_ik(robot, reachable, seed=0).n_eval <= 16 * 31  # solved by the first stage
    position = reachable.position
    with pytest.raises(UnknownNameError, match="unknown orientation metric 'bogus'.*geodesic"):
        solve_ik(robot, position, orientation="bogus")
    with pytest.raises(UnknownNameError, match="unknown orientation metric 'bogus'"):
        solve_ik(robot, reachable, orientation="bogus")
    with pytest.raises(ParameterError, match=r"pop_size must be an integer >= 2, got 2\.0"):
        solve_ik(robot, reachable, pop_size=2.0)
    with pytest.raises(ParameterError, match="n_solutions must be an integer >= 1, got True"):
        solve_ik(robot, reachable, n_solutions=True)
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2, got 1"):
        solve_ik(robot, reachable, pop_size=1)
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 3, got 2"):
        solve_ik(robot, reachable, pop_size=2)  # EOSMA's own minimum, checked up front too
    bad = [("max_evals", 0, "max_evals must be an integer >= 1"),
           ("starts", -1, "starts must be an integer >= 0"),
           ("generations", 1.5, "generations must be an integer >= 1"),
           ("candidates_per_round", 0, "candidates_per_round must be an integer >= 1"),
           ("patience", False, "patience must be an integer >= 1"),
           ("front_evals", 0, "front_evals must be an integer >= 1"),
           ("distinct", 0.0, r"distinct must be a (positive )?finite number"),
           ("distinct", float("inf"), r"distinct must be a (positive )?finite number"),
           ("polish", 1, "polish must be True or False"),
           ("seed", -1, "seed must be a non-negative integer"),
           ("seed", 1.5, "seed must be a non-negative integer"),
           ("tol", True, r"tol must be a (positive )?finite number"),
           ("tol", -1e-9, r"tol must be a (positive )?finite number"),
           ("tol", (1e-6, float("nan")),
            r"tol\[1\] \(orientation tolerance\) must be a (positive )?finite")]
    for name, value, message in bad:
        with pytest.raises(ParameterError, match=message):
            solve_ik(robot, reachable, **{name: value})


def test_orientation_metric_names_are_case_insensitive():
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=0)[0]
    a = solve_ik(robot, target, seed=0, starts=0, orientation="Geodesic")
    b = solve_ik(robot, target, seed=0, starts=0)
    np.testing.assert_array_equal(a.q, b.q)
