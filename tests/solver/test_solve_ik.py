"""solve_ik: exact, within limits, deterministic, several branches, honest failures."""

import numpy as np
import pytest

from moik.exceptions import DegreesWarning, ParameterError, UnknownNameError
from moik.kinematics.criteria import joint_distance
from moik.kinematics.tolerance import Tolerance
from moik.problems import Target, random_reachable_targets
from moik.robots import get_robot
from moik.solver import solve_ik
from moik.solver.result import ik_result
from moik.solver.session import SolveSession, pose_errors


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
    """The compiled Levenberg-Marquardt first stage ends most solves within
    16 * 31 FK evaluations, before any global search; with starts=0 the global
    search alone still solves them."""
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


def test_solve_ik_defaults_are_the_search_defaults():
    """solve_ik's signature and solve_ik_batch's defaults (SEARCH_DEFAULTS) agree."""
    import inspect

    from moik.solver.options import SEARCH_DEFAULTS
    params = inspect.signature(solve_ik).parameters
    assert {k: params[k].default for k in SEARCH_DEFAULTS} == SEARCH_DEFAULTS


def test_q_current_gets_the_nearest_2pi_copy():
    """UR5 joints span +-2 pi: a solution and its copy shifted by 2 pi are the same
    configuration; the one nearest to q_current is returned."""
    robot = get_robot("ur5")
    target = random_reachable_targets(robot, 1, seed=3)[0]
    q = solve_ik(robot, target.pose, seed=0).q
    shift = np.where(q < 0, 2 * np.pi, -2 * np.pi)
    shift[2] = 0.0  # the elbow spans +-pi only
    current = q + shift + 0.01
    assert robot.within_limits(current)[0]
    res = solve_ik(robot, target.pose, seed=0, q_current=current)
    assert res.success and robot.within_limits(res.q)[0]
    assert np.abs(res.q - current).max() < 0.5  # not 2 pi away on any joint
    for sol in res.solutions:  # every solution is its nearest copy
        assert np.all(np.abs(sol - current) <= np.pi + 1e-9)


def test_out_of_reach_is_proven_and_fast():
    """Beyond the provable reach bound: 'unreachable' without any search, with a
    polished front whose position-only end is at least the excess away."""
    robot = get_robot("iiwa14")
    pose = np.eye(4)
    pose[:3, 3] = [0.0, 1.2 * robot.reach, 0.3]
    res = solve_ik(robot, pose, seed=0)
    assert res.status == "unreachable" and res.front is not None and len(res.front) >= 2
    excess = np.linalg.norm(pose[:3, 3]) - robot.reach
    assert res.front[:, 0].min() >= excess
    assert res.n_eval < 50_000 / 2  # a fraction of the search budget: no search ran
    assert np.all(np.diff(res.front[:, 0]) > 0) and np.all(np.diff(res.front[:, 1]) < 0)
    position_only = solve_ik(robot, pose[:3, 3], seed=0)
    assert position_only.status == "unreachable" and position_only.front is None
    assert position_only.position_error == pytest.approx(res.front[0, 0], rel=1e-6)


def test_unreachable_compromise_is_not_dominated_by_plain_least_squares():
    """A 4-DOF SCARA cannot reach most full poses: the returned compromise lies on a
    polished front that no bounded least-squares answer (16 starts) dominates."""
    from scipy.optimize import least_squares
    from scipy.spatial.transform import Rotation

    from moik.solver.session import pose_errors

    robot = get_robot("scara4")
    rng = np.random.default_rng(0)
    for k in range(2):
        q = robot.random_q(1, rng=rng)[0]
        target = Target(robot.fk(q)[:3, 3], Rotation.random(random_state=k).as_matrix())
        res = solve_ik(robot, target, seed=k)
        assert res.status == "unreachable"

        def residual(x, target=target):
            T = robot.fk(x)
            return np.concatenate([(T[:3, 3] - target.position) / robot.reach,
                                   Rotation.from_matrix(T[:3, :3] @ target.rotation.T).as_rotvec()])
        for q0 in robot.random_q(16, rng=rng):
            x = least_squares(residual, q0, bounds=(robot.lower, robot.upper)).x
            pos, ori = (v[0] for v in pose_errors(robot, target, x, reference=True))
            assert not (pos < res.position_error - 1e-12 and ori < res.orientation_error - 1e-12)


def test_max_evals_is_honoured_by_the_first_stage():
    robot = get_robot("puma560")
    target = random_reachable_targets(robot, 1, seed=5, with_orientation=False)[0]
    res = solve_ik(robot, target.position * 0.9 + 0.05, seed=0, max_evals=1, patience=1)
    assert res.n_eval <= 400  # one Levenberg-Marquardt start at most, then no search round
    assert res.status in ("solved", "not-converged")  # cut short by the budget: no verdict
    full = solve_ik(robot, target.position * 0.9 + 0.05, seed=0)
    assert full.n_eval >= res.n_eval


def _issue27_case():
    """Issue 27 item 4 (1 in 200,000 soak solves at 62ac347): puma560, the 10705th of
    ``random_reachable_targets(r, 25000, seed=2024)``, solved with ``seed=10705``, whose
    500 random starts (drawn then from ``SeedSequence(10705)``) all stopped short of the
    stop (0.1 tol) and ended ``not-converged`` after 129,372 evaluations, one of them
    1.2e-10 x reach from the target (tol 1e-9)."""
    robot = get_robot("puma560")
    Q = robot.random_q(25000, rng=np.random.default_rng(2024))  # as random_reachable_targets
    T = robot.fk(Q)[10705]
    rng = np.random.Generator(np.random.PCG64(np.random.SeedSequence(10705)))
    return robot, Target(T[:3, 3], T[:3, :3]), [robot.random_q(8, rng=rng),
                                                 robot.random_q(492, rng=rng)]


def test_a_start_that_stalls_within_tolerance_is_a_solution():
    """The first stage re-checks an end whose cost could be within the tolerances."""
    robot, target, starts = _issue27_case()
    session = SolveSession(robot, target, Tolerance.of(1e-9, robot.reach), 0.1, 1, 50_000)
    for Q0 in starts:
        if not session.found:
            session.local_starts(Q0)
    assert len(session.found) == 1 and session.n_eval < 50_000
    pos, ori = pose_errors(robot, target, session.found[0], reference=True)
    assert pos[0] <= 1e-9 * robot.reach and ori[0] <= 1e-9


def test_an_answer_within_tolerance_is_never_not_converged():
    """The verdict: a best candidate within tolerance is ``solved``, whatever found it."""
    robot, target, _ = _issue27_case()
    q_source = robot.random_q(25000, rng=np.random.default_rng(2024))[10705]  # the pose's own
    session = SolveSession(robot, target, Tolerance.of(1e-9, robot.reach), 0.1, 1, 50_000)
    session.best = (0.0, q_source)  # a candidate no stage counted as found
    out = ik_result(session, None, 0.0, True, None, None)
    assert out.status == "solved" and out.success and len(out.solutions) == 1
    assert out.position_error <= 1e-9 * robot.reach


@pytest.mark.parametrize("tol, match", [
    (1e-300, r"tol must be at least 1e-14, the smallest tolerance float64 forward kinematics"),
    (1e-15, r"tol must be at least 1e-14"),
    ((1e-300, 1e-9), r"tol\[0\] \(position tolerance\) must be at least 1\.76\d*e-12 \(1e-14 x"),
    ((1e-3, 1e-20), r"tol\[1\] \(orientation tolerance\) must be at least 1e-14 rad"),
])
def test_tolerances_below_what_fk_can_certify_are_refused(tol, match):
    """Issue 27 item 7: tol=1e-300 was accepted and turned a reachable pose unreachable."""
    robot = get_robot("eosma7")
    reachable = random_reachable_targets(robot, 1, seed=0)[0]
    with pytest.raises(ParameterError, match=match):
        solve_ik(robot, reachable, tol=tol)


def test_the_smallest_accepted_tolerance_solves_a_reachable_pose():
    robot = get_robot("eosma7")
    res = solve_ik(robot, random_reachable_targets(robot, 1, seed=0)[0], tol=1e-14)
    assert res.status == "solved" and res.position_error <= 1e-14 * robot.reach


def test_fewer_solutions_than_requested_are_said():
    """Issue 25: n_solutions=50 returned 33 with status solved and no word. A Puma 560
    pose has at most 8 branches: 12 asked, fewer found, and the result says so."""
    robot = get_robot("puma560")
    target = random_reachable_targets(robot, 1, seed=4)[0]
    res = solve_ik(robot, target, n_solutions=12, seed=0, starts=64, patience=1)
    assert res.status == "solved" and res.success and res.n_requested == 12
    assert 1 <= len(res.solutions) < 12 and res.fewer_solutions
    assert res.detail.startswith(f"found {len(res.solutions)} of the 12 distinct solutions")
    one = solve_ik(robot, target, seed=0)
    assert not one.fewer_solutions and one.detail == "" and one.n_requested == 1


def test_the_front_polish_keeps_to_front_evals():
    """Issue 27 item 7: an unsolved pose spent ~8x front_evals in the front's polish. No
    scalarisation start begins past ``front_evals`` now."""
    robot = get_robot("eosma7")
    target = Target([1.2 * robot.reach, 0.0, 0.0], np.eye(3))  # proven out of reach: the
    full = solve_ik(robot, target, seed=0)  # polished front is all the solve does
    cut = solve_ik(robot, target, seed=0, front_evals=300)
    assert full.status == cut.status == "unreachable" and len(cut.front) >= 1
    assert cut.n_eval < full.n_eval and cut.n_eval <= 300 + 2_000  # + the start under way
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_equal_seeds_for_targets_and_solver_share_no_stream(seed):
    """The Quickstart's pattern: a target of ``seed=s`` solved with ``seed=s``. The first
    random start is not the configuration the target came from (it was, when both drew
    ``default_rng(s)``: ``solved`` with errors of exactly 0.0)."""
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=seed)[0]
    res = solve_ik(robot, target.pose, seed=seed)
    assert res.success and res.position_error > 0.0
    assert not np.array_equal(res.q, target.q_source)


def test_q_current_in_degrees_is_warned_about():
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=3)[0]
    with pytest.warns(DegreesWarning, match=r"q_current for robot 'eosma7': joint 1"):
        solve_ik(robot, target.pose, q_current=[45, 0, 45, 0, 45, 0, 0])
