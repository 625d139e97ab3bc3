"""A corpus of bad input: each case raises a MoikError subclass that says what was expected.

Every entry is ``(callable, bad input, expected error class, message regex)``: the
callable is called with the bad input. The corpus covers robots, targets, IK
problems, algorithms, the solver (cases it already refuses correctly) and the
command line; angles that look like degrees give a ``DegreesWarning`` instead.
A bad ``seed`` given to pymoo's ``minimize`` is refused by moik's own algorithms
(their ``setup()``); pymoo's registered algorithms keep pymoo's behaviour.
"""

import re
from dataclasses import replace

import numpy as np
import pytest
from pymoo.optimize import minimize

from moik import MoikError, get_robot, load_urdf, solve_ik, solve_ik_batch, solve_path
from moik.algorithms import get_algorithm
from moik.cli import main
from moik.exceptions import (
    DegreesWarning,
    LimitsError,
    NonFiniteError,
    ParameterError,
    ShapeError,
    TargetError,
    UnknownNameError,
    URDFError,
)
from moik.problems import BiObjectiveIK, PoseIK, PositionIK, Target
from moik.problems.targets import as_target, circle_path, random_reachable_targets
from moik.robots import Robot

ARM = get_robot("eosma7")
SCARA = get_robot("scara4")
POSE = ARM.fk(np.radians([45, 0, 45, 0, 45, 0, 0]))
POSITION = POSE[:3, 3]
STRINGS = ["a"] * 7
RAGGED = [[0.0] * 7, [0.0] * 6]
COMPLEX = np.zeros(7) + 1j
REAL = "must be an array of real numbers"
TARGET_FORMS = (r"target must be a 3-vector position, a \(4, 4\) pose, a \(position, rotation\) "
                r"pair with a \(3, 3\) rotation, or a Target")
SEED = "seed must be a non-negative integer, a numpy SeedSequence or None, got "


def _dh(**kw) -> Robot:
    rows = dict(a=[0.3, 0.2], alpha=[np.pi / 2, 0.0], d=[0.1, 0.0], theta=[0.0, 0.0],
                lower=[-np.pi, -np.pi], upper=[np.pi, np.pi])
    return Robot(name="arm", **{**rows, **kw})


def _case(call, bad, error, message, id):
    return pytest.param(call, bad, error, message, id=id)


ROBOTS = [
    _case(ARM.fk, STRINGS, ShapeError, f"q for robot 'eosma7' {REAL}, got strings", "fk-strings"),
    _case(ARM.fk, ["0"] * 7, ShapeError, f"{REAL}, got strings", "fk-numeric-strings"),
    _case(ARM.fk, RAGGED, ShapeError, f"{REAL} with rows of equal length", "fk-ragged"),
    _case(ARM.fk, COMPLEX, ShapeError, f"{REAL}, got complex numbers", "fk-complex"),
    _case(ARM.fk, [True] * 7, ShapeError, f"{REAL}, got booleans", "fk-bools"),
    _case(ARM.fk, {"q1": 0.0}, ShapeError, f"{REAL}, got a dict", "fk-dict"),
    _case(ARM.fk, np.zeros(6), ShapeError, r"must have shape \(7,\) or \(n, 7\), got \(6,\)",
          "fk-short"),
    _case(ARM.fk, [0, 0, np.nan, 0, 0, 0, 0], NonFiniteError, "must be finite", "fk-nan"),
    _case(ARM.fk_position, np.zeros(7), ShapeError,
          r"must have shape \(n, 7\), got \(7,\); for one joint vector pass q\[None\] or use "
          r"robot.fk\(q\)", "fk_position-1d"),
    _case(ARM.fk_parts, np.zeros(7), ShapeError, r"got \(7,\); for one joint vector pass",
          "fk_parts-1d"),
    _case(ARM.fk_position, [STRINGS], ShapeError, f"a batch for robot 'eosma7' {REAL}",
          "fk_position-strings"),
    _case(ARM.fk_parts, np.zeros((2, 7)) + 1j, ShapeError, f"{REAL}, got complex numbers",
          "fk_parts-complex"),
    _case(ARM.frames, RAGGED, ShapeError, "with rows of equal length", "frames-ragged"),
    _case(ARM.within_limits, STRINGS, ShapeError, f"{REAL}, got strings", "within-strings"),
    _case(lambda n: ARM.random_q(n, rng=np.random.default_rng(0)), "3", ParameterError,
          "n must be an integer >= 0, got '3'", "random_q-n-string"),
    _case(lambda rng: ARM.random_q(3, rng=rng), 0, ParameterError,
          "rng must be a numpy.random.Generator, got int", "random_q-rng-seed"),
    _case(ARM.with_locked_joints, [0.0], ParameterError,
          r"locked must be a dict \{joint index: value\}, got list", "lock-list"),
    _case(ARM.with_locked_joints, {0: "a"}, ParameterError,
          "locked value of joint 0 must be a finite number, got 'a'", "lock-value-string"),
    _case(ARM.with_locked_joints, {True: 0.0}, ParameterError,
          r"locked joint indices must be in 0..6, got \[True\]", "lock-bool-index"),
    _case(lambda a: _dh(a=a), ["0.3", "0.2"], ShapeError, f"a {REAL}, got strings",
          "robot-dh-strings"),
    _case(lambda d: _dh(d=d), [0.1 + 1j, 0.0], ShapeError, f"d {REAL}, got complex numbers",
          "robot-dh-complex"),
    _case(lambda alpha: _dh(alpha=alpha), [[0.0], [0.0, 1.0]], ShapeError,
          "with rows of equal length", "robot-dh-ragged"),
    _case(lambda lower: _dh(lower=lower), [0.0, 4.0], LimitsError,
          r"lower limit > upper limit for joint\(s\) \[2\]", "robot-limits-crossed"),
    _case(lambda upper: _dh(upper=upper), {"q1": 1.0}, ShapeError, f"upper {REAL}, got a dict",
          "robot-limits-dict"),
    _case(lambda base: _dh(base=base), np.eye(3), ShapeError,
          r"robot 'arm' base must have shape \(4, 4\), got \(3, 3\)", "robot-base-shape"),
    _case(lambda tool: _dh(tool=tool), np.diag([1.0, 2.0, 1.0, 1.0]), ParameterError,
          r"tool must be a rigid transform: its rotation part \(upper-left 3x3\) must be "
          r"orthonormal", "robot-tool-not-rigid"),
    _case(lambda names: _dh(joint_names=names), ("a", "a"), ParameterError,
          "joint_names must be 2 distinct non-empty strings", "robot-joint-names"),
    _case(lambda types: _dh(joint_types=types), "revolute", ParameterError,
          "joint_types must be a sequence of 2 entries", "robot-joint-types-string"),
    _case(lambda unit: _dh(unit=unit), "inch", ParameterError, "unit must be one of",
          "robot-unit"),
    _case(get_robot, "nope", UnknownNameError, "unknown robot 'nope'; expected one of: "
          "anthropomorphic3, eosma7", "get_robot-unknown"),
    _case(get_robot, 3, UnknownNameError, "unknown robot 3", "get_robot-int"),
    _case(load_urdf, 3, URDFError, "a URDF must be a file path or an XML string, got int",
          "urdf-int"),
    _case(load_urdf, "/nonexistent/arm.urdf", URDFError, "cannot read URDF", "urdf-missing"),
    _case(load_urdf, "<robot name='x'><link name='a'/></robot>", URDFError,
          "no movable joint", "urdf-no-joint"),
]

TARGETS = [
    _case(as_target, {"x": 1.0}, TargetError, f"{TARGET_FORMS}; got a dict", "as_target-dict"),
    _case(as_target, "0 0 1", TargetError, f"{TARGET_FORMS}; got a str", "as_target-string"),
    _case(as_target, None, TargetError, f"{TARGET_FORMS}; got a NoneType", "as_target-none"),
    _case(as_target, ["1", "2", "3"], TargetError, f"{TARGET_FORMS}; target {REAL}, got strings",
          "as_target-strings"),
    _case(as_target, [1j, 0, 0], TargetError, "got complex numbers", "as_target-complex"),
    _case(as_target, [[1, 2], [3]], TargetError, "with rows of equal length",
          "as_target-ragged"),
    _case(as_target, np.zeros(5), ShapeError, r"got an array of shape \(5,\)", "as_target-5"),
    _case(as_target, (POSITION, "x"), ShapeError, f"target rotation {REAL}, got a str",
          "as_target-pair-string"),
    _case(as_target, (POSITION, 2 * np.eye(3)), TargetError,
          r"target rotation must be a rotation matrix", "as_target-pair-not-rotation"),
    _case(Target, "abc", ShapeError, f"target position {REAL}, got a str", "Target-string"),
    _case(Target, [1j, 0, 0], ShapeError, f"target position {REAL}, got complex", "Target-cplx"),
    _case(Target, [np.inf, 0, 0], NonFiniteError, "target position must be finite",
          "Target-inf"),
    _case(Target.from_pose, "abc", ShapeError, f"pose {REAL}", "from_pose-string"),
    _case(Target.from_pose, np.zeros((4, 4)), TargetError, r"last row must be \[0, 0, 0, 1\]",
          "from_pose-last-row"),
    _case(lambda angles: Target.from_euler(POSITION, angles), "abc", ShapeError,
          f"Euler angles {REAL}", "from_euler-string"),
    _case(lambda angles: Target.from_euler(POSITION, angles), [90, 0, 0], TargetError,
          r"exceed 2\*pi in magnitude; angles are radians \(pass degrees=True", "from_euler-deg"),
    _case(lambda deg: Target.from_euler(POSITION, [0, 0, 0], degrees=deg), "yes", TargetError,
          "degrees must be True or False", "from_euler-flag"),
    _case(lambda c: Target.from_euler(POSITION, [0, 0, 0], convention=c), "xyz",
          UnknownNameError, "unknown Euler convention 'xyz'", "from_euler-convention"),
    _case(lambda seed: random_reachable_targets(ARM, 3, seed=seed), -1, ParameterError,
          SEED + "-1", "targets-seed-negative"),
    _case(lambda seed: random_reachable_targets(ARM, 3, seed=seed), 1.5, ParameterError,
          SEED + "1.5", "targets-seed-float"),
    _case(lambda seed: random_reachable_targets(ARM, 3, seed=seed), "7", ParameterError,
          SEED + "'7'", "targets-seed-string"),
    _case(lambda robot: random_reachable_targets(robot, 3, seed=0), "eosma7", ParameterError,
          r"robot must be a moik Robot \(for the catalog robot call moik.get_robot\('eosma7'\)\)",
          "targets-robot-name"),
    _case(lambda n: random_reachable_targets(ARM, n, seed=0), 2.0, TargetError,
          "n must be an integer >= 1, got 2.0", "targets-n-float"),
    _case(lambda c: circle_path(c, 1.0, 5), "abc", ShapeError, f"circle center {REAL}",
          "circle-center-string"),
    _case(lambda r: circle_path([0, 0, 0], r, 5), -1.0, TargetError,
          "circle radius must be a positive finite number", "circle-radius"),
]

PROBLEMS = [
    _case(lambda t: PositionIK(ARM, t), "abc", TargetError, f"{TARGET_FORMS}; got a str",
          "PositionIK-target-string"),
    _case(lambda t: PositionIK(ARM, t), {"x": 1}, TargetError, f"{TARGET_FORMS}; got a dict",
          "PositionIK-target-dict"),
    _case(lambda t: PositionIK(ARM, t), [0, 0, 1e5], TargetError, "expected a position in cm",
          "PositionIK-unit"),
    _case(lambda robot: PositionIK(robot, POSITION), "eosma7", ParameterError,
          "robot must be a moik Robot, got str", "PositionIK-robot-name"),
    _case(lambda q: PositionIK(ARM, POSITION, q_start=q, displacement_weight=1.0), STRINGS,
          ShapeError, f"q_start for robot 'eosma7' {REAL}, got strings", "PositionIK-q_start"),
    _case(lambda w: PositionIK(ARM, POSITION, displacement_weight=w), "a", ParameterError,
          "displacement_weight must be a finite number >= 0", "PositionIK-weight"),
    _case(lambda X: PositionIK(ARM, POSITION).evaluate(X), np.array([STRINGS]), ShapeError,
          f"a batch for robot 'eosma7' {REAL}, got strings", "evaluate-strings"),
    _case(lambda t: PoseIK(ARM, t), POSITION, TargetError,
          "PoseIK needs a target with an orientation", "PoseIK-position-only"),
    _case(lambda m: PoseIK(ARM, POSE, orientation=m), "bogus", UnknownNameError,
          "unknown orientation metric 'bogus'; expected one of: eosma-euler", "PoseIK-metric"),
    _case(lambda w: PoseIK(ARM, POSE, weights=w), (-1, 1), ParameterError,
          "weights must be two finite non-negative numbers", "PoseIK-weights"),
    _case(lambda m: BiObjectiveIK(ARM, POSE, orientation=m), None, UnknownNameError,
          "unknown orientation metric None", "BiObjectiveIK-metric"),
]

ALGORITHMS = [
    _case(get_algorithm, "nope", UnknownNameError, "unknown algorithm 'nope'; expected one of",
          "get_algorithm-unknown"),
    _case(get_algorithm, 3, UnknownNameError, "unknown algorithm 3", "get_algorithm-int"),
    _case(lambda z: get_algorithm("eosma", z=z), "a", ParameterError,
          r"z must be a number in \[0.0, 1.0\], got 'a'", "get_algorithm-param"),
    _case(lambda n: get_algorithm("pso", pop_size=n), 2.0, ParameterError,
          "pop_size must be an integer >= 2, got 2.0", "get_algorithm-pop-float"),
    _case(lambda kw: get_algorithm("eosma", **kw), {"pop_sise": 10}, ParameterError,
          r"unknown parameter\(s\) pop_sise for algorithm 'eosma'", "get_algorithm-typo"),
    _case(lambda name: minimize(PositionIK(ARM, POSITION), get_algorithm(name), ("n_gen", 2),
                                seed=0), "moeosma", ParameterError,
          "MOEOSMA is multi-objective; the problem has n_obj=1", "minimize-kind"),
]

SOLVER = [
    _case(lambda q: solve_ik(ARM, POSE, q_current=q), STRINGS, ShapeError,
          f"q_current for robot 'eosma7' {REAL}, got strings", "solve_ik-q_current-strings"),
    _case(lambda q: solve_ik(ARM, POSE, q_current=q), RAGGED, ShapeError,
          "with rows of equal length", "solve_ik-q_current-ragged"),
    _case(lambda q: solve_ik(ARM, POSE, q_current=q), COMPLEX, ShapeError,
          "got complex numbers", "solve_ik-q_current-complex"),
    _case(lambda t: solve_ik(ARM, t), {"x": 1.0}, TargetError, f"{TARGET_FORMS}; got a dict",
          "solve_ik-target-dict"),
    _case(lambda t: solve_ik(ARM, t), "abc", TargetError, f"{TARGET_FORMS}; got a str",
          "solve_ik-target-string"),
    _case(lambda m: solve_ik(ARM, POSITION, orientation=m), "bogus", UnknownNameError,
          "unknown orientation metric 'bogus'", "solve_ik-metric-position-only"),
    _case(lambda s: solve_ik(ARM, POSE, seed=s), -1, ParameterError, SEED + "-1",
          "solve_ik-seed-negative"),
    _case(lambda s: solve_ik(ARM, POSE, seed=s), 2.0, ParameterError, SEED + "2.0",
          "solve_ik-seed-float"),
    _case(lambda s: solve_ik(ARM, POSE, seed=s), "1", ParameterError, SEED + "'1'",
          "solve_ik-seed-string"),
    _case(lambda s: solve_ik(ARM, POSE, seed=s), True, ParameterError, SEED + "True",
          "solve_ik-seed-bool"),
    _case(lambda t: solve_ik(ARM, POSE, tol=t), "a", ParameterError,
          "tol must be a positive finite number, got 'a'", "solve_ik-tol"),
    _case(lambda n: solve_ik(ARM, POSE, max_evals=n), 1.5, ParameterError,
          "max_evals must be an integer >= 1, got 1.5", "solve_ik-max_evals"),
    _case(lambda n: solve_ik(ARM, POSE, n_solutions=n), "2", ParameterError,
          "n_solutions must be an integer >= 1, got '2'", "solve_ik-n_solutions"),
    _case(lambda s: solve_path(ARM, [POSE, POSE], seed=s), -1, ParameterError, SEED + "-1",
          "solve_path-seed"),
    _case(lambda path: solve_path(ARM, path), [{"x": 1}], TargetError,
          f"{TARGET_FORMS}; got a dict", "solve_path-dict"),
]


@pytest.mark.parametrize(("call", "bad", "error", "message"),
                         ROBOTS + TARGETS + PROBLEMS + ALGORITHMS + SOLVER)
def test_bad_input_raises_a_moik_error(call, bad, error, message):
    with pytest.raises(error, match=message) as info:
        call(bad)
    assert isinstance(info.value, MoikError)


DEGREES = [
    _case(lambda lim: _dh(lower=[-lim, -lim], upper=[lim, lim]), 180.0, DegreesWarning,
          r"robot 'arm': revolute lower limits reach 180 \(beyond 2 turns\)", "limits-180"),
    _case(lambda a: _dh(alpha=a), [90.0, 0.0], DegreesWarning,
          r"alpha reaches 90 \(beyond 2 pi\): these look like degrees", "dh-alpha-90"),
    _case(lambda t: _dh(theta=t), [0.0, -90.0], DegreesWarning, "theta reaches 90",
          "dh-theta-90"),
    _case(lambda up: Robot(name="g", origins=np.broadcast_to(np.eye(4), (2, 4, 4)), lower=[0.0],
                           upper=up), [360.0], DegreesWarning, "upper limits reach 360",
          "general-chain-limits"),
    _case(lambda r: replace(r, upper=np.degrees(r.upper)), get_robot("puma560"), DegreesWarning,
          "upper limits reach 180", "catalog-robot-in-degrees"),
]


@pytest.mark.parametrize(("call", "bad", "warning", "message"), DEGREES)
def test_angles_that_look_like_degrees_warn(call, bad, warning, message):
    with pytest.warns(warning, match=message):
        call(bad)


CLI = [
    pytest.param(["solve", "planar2", "--target", "0.3", "0.2", "0", "--seed", "-1"],
                 r"--seed must be an integer >= 0, got -1", id="cli-seed"),
    pytest.param(["solve", "planar2", "--target", "0.3", "0.2", "0", "--plot", "/nonexistent/p"],
                 r"--plot folder '/nonexistent' does not exist", id="cli-plot-folder"),
    pytest.param(["solve", "planar2", "--target", "0.3", "0.2", "0", "--plot", "p.jpeg"],
                 r"--plot file must end in .png, .pdf, .svg", id="cli-plot-format"),
    pytest.param(["solve", "planar2", "--target", "0.3", "0.2", "0", "--tol", "1", "2", "3"],
                 r"--tol takes 1 number", id="cli-tol"),
    pytest.param(["solve", "planar2", "--target", "0.3", "0.2", "0", "--max-evals", "0"],
                 r"--max-evals must be an integer >= 1, got 0", id="cli-max-evals"),
    pytest.param(["solve", "planar2", "--target", "0.3", "0.2", "0", "--q-current", "0"],
                 r"robot 'planar2' needs 2 joint values, got 1 \(--q-current\)", id="cli-q-cur"),
    pytest.param(["solve", "planar2", "--target", "0", "0", "90"], r"expected a position in m",
                 id="cli-unit"),
    pytest.param(["solve", "planar2", "--target", "0.3", "0.2", "0", "--euler", "90", "0", "0"],
                 r"--euler angles \[90.0, 0.0, 0.0\] exceed 2 pi in magnitude; they are radians: "
                 r"add --deg", id="cli-euler-degrees"),
    pytest.param(["solve", "planar2", "--base", "x", "--target", "0.3", "0.2", "0"],
                 r"--base/--tip select links of a URDF file", id="cli-base-on-catalog"),
    pytest.param(["solve", "missing.urdf", "--target", "0.3", "0.2", "0"],
                 r"cannot read URDF 'missing.urdf'", id="cli-urdf-missing"),
    pytest.param(["fk", "nope", "0"], r"unknown robot 'nope'; expected one of: .*; or a URDF",
                 id="cli-unknown-robot"),
    pytest.param(["fk", "planar2", "0"], r"robot 'planar2' needs 2 joint values, got 1",
                 id="cli-fk-short"),
    pytest.param(["fk", "planar2", "0", "inf"], r"must be finite", id="cli-fk-inf"),
    pytest.param(["robots", "nope"], r"unknown robot 'nope'", id="cli-robots-unknown"),
    pytest.param(["experiment", "run", "mpso-single", "--quick", "--out", "/dev/null/r"],
                 r"cannot (use|create).*/dev/null/r.*(Not a directory|is a file)",
                 id="cli-out-unwritable"),
]


@pytest.mark.parametrize(("argv", "message"), CLI)
def test_bad_command_lines_are_one_line_errors(capsys, argv, message):
    assert main(argv) == 2
    captured = capsys.readouterr()
    assert captured.err.startswith("moik: error: ") and captured.err.count("\n") == 1
    assert "Traceback" not in captured.err
    assert re.search(message, captured.err), captured.err


def _pose_weights(w):
    return PoseIK(ARM, POSE, weights=w)


def _minimize_seed(seed):
    return minimize(PositionIK(ARM, POSITION), get_algorithm("eosma"), ("n_gen", 2), seed=seed)


# moik's own algorithms check the seed in setup(); the registered pymoo algorithms (NSGA2,
# pymoo's GA and DE ...) are pymoo's and keep pymoo's behaviour
MINIMIZE_SEEDS = [
    _case(_minimize_seed, -1, ParameterError, SEED + "-1", "minimize-seed-negative"),
    _case(_minimize_seed, 1.5, ParameterError, SEED + "1.5", "minimize-seed-float"),
    _case(_minimize_seed, "a", ParameterError, SEED + "'a'", "minimize-seed-string"),
    _case(_minimize_seed, True, ParameterError, SEED + "True", "minimize-seed-bool"),
    _case(lambda s: minimize(BiObjectiveIK(ARM, POSE), get_algorithm("moeosma"), ("n_gen", 2),
                             seed=s), -3, ParameterError, SEED + "-3", "minimize-mo-seed"),
    _case(lambda s: minimize(PositionIK(ARM, POSITION), get_algorithm("eosma", seed=s),
                             ("n_gen", 2)), 2.0, ParameterError, SEED + "2.0",
          "constructor-seed-float"),
]


@pytest.mark.parametrize(("call", "bad", "error", "message"), MINIMIZE_SEEDS)
def test_minimize_checks_the_seed_of_moik_algorithms(call, bad, error, message):
    """moik's own algorithms (the array-state bases) check the seed in ``setup()``, before
    pymoo builds its Generator; the registered pymoo algorithms (NSGA2 ...) are pymoo's and
    not covered."""
    with pytest.raises(error, match=message):
        call(bad)


FIXED_IN_THE_SOLVER_AND_PROBLEMS = [
    _case(_pose_weights, ("a", "b"), ParameterError, "weights", "PoseIK-weights-strings"),
    _case(_pose_weights, (1j, 1.0), ParameterError, "weights", "PoseIK-weights-complex"),
    _case(lambda X: PositionIK(ARM, POSITION).evaluate(X), np.zeros((2, 6)), ShapeError,
          r"\(n, 7\)", "evaluate-wrong-width"),
    _case(lambda targets: solve_path(ARM, targets), "abc", TargetError, "sequence of targets",
          "solve_path-string"),
    _case(lambda targets: solve_ik_batch(ARM, targets), np.zeros((0, 3)), ShapeError,
          "empty batch", "solve_ik_batch-empty"),
    _case(lambda targets: solve_ik_batch(ARM, targets), [[1.0, "x", 2.0]], ShapeError,
          "real numbers", "solve_ik_batch-strings"),
]


@pytest.mark.parametrize(("call", "bad", "error", "message"), FIXED_IN_THE_SOLVER_AND_PROBLEMS)
def test_solver_and_problem_inputs(call, bad, error, message):
    with pytest.raises(error, match=message):
        call(bad)


def test_a_robot_name_is_accepted_where_a_robot_is_expected():
    assert solve_ik("eosma7", POSE).success
