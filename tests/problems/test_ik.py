"""IK problems: zero at the generating joint vector, formulas, bad input."""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pymoo.optimize import minimize
from scipy.spatial.transform import Rotation

from moik.algorithms import EOSMA
from moik.exceptions import NonFiniteError, ParameterError, ShapeError, TargetError
from moik.kinematics.orientation import (
    available_metrics,
    eosma_euler,
    orientation_error,
    orientation_metric,
)
from moik.kinematics.rotation_metrics import metric_target
from moik.kinematics.target_spec import target_spec
from moik.problems import BiObjectiveIK, PoseIK, PositionIK, Target, random_reachable_targets
from moik.problems.ik_kernels import WEIGHTED_POSE, ik_objectives
from moik.robots import available_robots, fk_reference, get_robot


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


def _numpy_errors(robot, target, metric, X, R_fk=None):
    """Position and orientation errors the plain-numpy way: fk_reference + the
    metric functions of moik.kinematics.orientation."""
    T = fk_reference(robot, X)
    pos = np.linalg.norm(T[:, :3, 3] - target.position, axis=1)
    if metric is None:
        return pos, None
    target_repr, error = orientation_metric(metric)
    with warnings.catch_warnings():  # scipy's gimbal-lock warning for the ZYX angles
        warnings.simplefilter("ignore", UserWarning)
        ori = error(T[:, :3, :3], target_repr(target.rotation))
        if R_fk is not None:
            # The ZYX metrics are discontinuous where an angle crosses +-pi (they
            # are not wrapped, as in MO-m-PSO): there one ulp of FK rounding moves
            # the error by up to 2 pi / 3, so such rows are compared on the
            # kernel's own rotation.
            ori_fk = error(R_fk, target_repr(target.rotation))
            cut = np.abs(ori_fk - ori) > 1e-9
            assert not cut.any() or metric.startswith("zyx"), metric
            ori = np.where(cut, ori_fk, ori)
    return pos, ori


ULP_TURN = 16 * np.finfo(float).eps  # rad: a rotation a few ulps of FK rounding make


def _rounding_slack(metric, target, R):
    """Per row, how far ``metric``'s error moves when ``R`` turns by :data:`ULP_TURN` about
    each axis (either way): the rounding amplification of the metric at that rotation.

    Two correct implementations of one metric (the kernel's and numpy's) may differ by
    this much. Near gimbal lock an Euler metric amplifies a 1e-14 rad turn to 1.6e-10
    (anthropomorphic3, ZYX pitch 3e-5 rad from 90 deg, seed 6): there a few ulps of
    rounding give 3e-12; the geodesic and Frobenius metrics amplify nothing."""
    target_repr, error = orientation_metric(metric)
    t = target_repr(target.rotation)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        base = error(R, t)
        slack = np.zeros(len(R))
        for turn in np.vstack([np.eye(3), -np.eye(3)]) * ULP_TURN:
            moved = error(np.einsum("ij,njk->nik", Rotation.from_rotvec(turn).as_matrix(), R), t)
            slack = np.maximum(slack, np.abs(moved - base))
    return np.where(slack < 1e-3, slack, 0.0)  # a jump across +-pi is _numpy_errors' case


def _assert_close(actual, desired, atol):
    """``|actual - desired| <= atol`` elementwise (``atol`` per row or one number)."""
    off = np.abs(actual - desired)
    bad = off > atol
    assert not bad.any(), (f"rows {np.flatnonzero(bad)} off by {off[bad]}, more than "
                           f"{np.broadcast_to(atol, off.shape)[bad]}")


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(available_robots()), st.sampled_from(available_metrics()),
       st.integers(0, 2**32 - 1), st.integers(1, 150), st.sampled_from([0.0, 0.25]))
def test_fused_objectives_equal_numpy(name, metric, seed, n, w_disp):
    """FK + metric + Eq. 31 in one compiled call equals the numpy computation."""
    robot = get_robot(name)
    rng = np.random.default_rng(seed)
    target = random_reachable_targets(robot, 1, seed=seed % 1000)[0]
    X = robot.random_q(n, rng=rng)
    q0 = robot.random_q(1, rng=rng)[0]
    disp = w_disp * np.linalg.norm(X - q0, axis=1)
    common = {"displacement_weight": w_disp, "q_start": q0}
    R_fk = robot.fk_parts(X)[0]
    pos, ori = _numpy_errors(robot, target, metric, X, R_fk)
    scale = max(1.0, robot.reach)
    tol = 1e-12 * scale
    tol_ori = 1e-12 + _rounding_slack(metric, target, R_fk)  # the metric's conditioning

    F = PositionIK(robot, target.position, **common).evaluate(X)
    np.testing.assert_allclose(F[:, 0], pos + disp, rtol=0, atol=tol)
    F = PoseIK(robot, target, weights=(0.3, 0.7), orientation=metric, **common).evaluate(X)
    _assert_close(F[:, 0], 0.3 * pos + 0.7 * ori + disp, tol + 0.7 * tol_ori)
    F = BiObjectiveIK(robot, target, orientation=metric, **common).evaluate(X)
    np.testing.assert_allclose(F[:, 0], pos + disp, rtol=0, atol=tol)
    _assert_close(F[:, 1], ori + disp, tol + tol_ori)
    problem = BiObjectiveIK(robot, target, orientation=metric, **common)
    p_err, o_err = problem.errors(X)
    np.testing.assert_allclose(p_err, pos, rtol=0, atol=tol)
    _assert_close(o_err, ori, tol_ori)
    np.testing.assert_allclose(problem.position_error(X), pos, rtol=0, atol=tol)


def test_fused_kernel_is_one_call_per_population():
    """The kernel itself, as the problems call it (one call, preallocated output)."""
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=2)[0]
    X = robot.random_q(100, rng=np.random.default_rng(0))
    out = np.empty((100, 1))
    spec = target_spec(target.position, target.rotation, metric="geodesic")
    ik_objectives(robot.chain_model, spec, X, (WEIGHTED_POSE, np.array([0.5, 0.5, 0.0]),
                                               np.zeros(7)), out)
    np.testing.assert_array_equal(out, PoseIK(robot, target).evaluate(X))


def test_pose_ik_default_metric_is_geodesic():
    robot = get_robot("puma560")
    target = random_reachable_targets(robot, 1, seed=4)[0]
    X = robot.random_q(10, rng=np.random.default_rng(1))
    assert PoseIK(robot, target).orientation == "geodesic"
    np.testing.assert_array_equal(PoseIK(robot, target).evaluate(X),
                                  PoseIK(robot, target, orientation="geodesic").evaluate(X))


def test_objectives_accept_any_array_layout():
    """Strided, read-only, float32 and list inputs give the same numbers."""
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=3)[0]
    problem = BiObjectiveIK(robot, target)
    X = robot.random_q(20, rng=np.random.default_rng(2))
    F = problem.evaluate(X)
    wide = np.zeros((20, 14))
    wide[:, ::2] = X
    frozen = X.copy()
    frozen.setflags(write=False)
    np.testing.assert_array_equal(problem.evaluate(wide[:, ::2]), F)
    np.testing.assert_array_equal(problem.evaluate(frozen), F)
    np.testing.assert_array_equal(problem.errors(X.tolist())[0], F[:, 0])


def _special_rotations() -> np.ndarray:
    """Rotations where the Euler conventions are delicate: half turns, ZYX gimbal
    lock (beta = +-pi/2) and a hair away from it, angles at +-pi."""
    rng = np.random.default_rng(0)
    axes = rng.normal(size=(200, 3))
    half_turns = Rotation.from_rotvec(np.pi * axes / np.linalg.norm(axes, axis=1)[:, None])
    beta = rng.choice([-1, 1], 200) * (np.pi / 2 - 10.0 ** rng.uniform(-15, -3, 200))
    lock = np.column_stack([rng.uniform(-3, 3, 200), beta, rng.uniform(-3, 3, 200)])
    grid = rng.choice([-np.pi, -np.pi / 2, 0.0, np.pi / 2, np.pi], size=(200, 3))
    return np.concatenate([half_turns.as_matrix(), Rotation.from_euler("ZYX", lock).as_matrix(),
                           Rotation.from_euler("ZYX", grid).as_matrix(), [np.eye(3)],
                           Rotation.random(500, random_state=1).as_matrix()])


@pytest.mark.parametrize("metric", available_metrics())
def test_compiled_metrics_equal_numpy_on_delicate_rotations(metric):
    """The compiled metric (as the fused objectives use it) against the numpy
    formula, including scipy's gimbal-lock rule for the ZYX angles."""
    R = _special_rotations()
    R_t = Rotation.random(1, random_state=3).as_matrix()[0]
    target_repr, error = orientation_metric(metric)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        expected = error(R, target_repr(R_t))
        angles = np.zeros(3) if metric in ("frobenius", "geodesic") else target_repr(R_t)
    np.testing.assert_allclose(metric_target(metric, R_t), angles, rtol=0, atol=1e-15)
    np.testing.assert_allclose(orientation_error(R, R_t, metric), expected, rtol=0, atol=1e-14)


@pytest.mark.parametrize("metric", ["eosma-euler", "zyx-euler", "zyx-euler-free-gamma"])
def test_euler_target_angles_make_the_source_exact(metric):
    """Target angles come from the same compiled code as the candidates' angles, so
    the joint vector that generated a target scores exactly 0."""
    robot = get_robot("eosma7")
    for target in random_reachable_targets(robot, 5, seed=9):
        F = BiObjectiveIK(robot, target, orientation=metric).evaluate(target.q_source[None])
        assert F[0, 1] == 0.0


@pytest.mark.parametrize("make", [
    lambda r, t: PositionIK(r, t.position),
    lambda r, t: PoseIK(r, t, orientation="eosma-euler"),
    lambda r, t: BiObjectiveIK(r, t, orientation="zyx-euler"),
    lambda r, t: PoseIK(r, t, displacement_weight=0.1, q_start=np.zeros(r.dof)),
])
def test_batch_objectives_equal_pymoos_evaluate_bit_for_bit(make):
    robot = get_robot("eosma7")
    problem = make(robot, random_reachable_targets(robot, 1, seed=3)[0])
    X = robot.random_q(9, rng=np.random.default_rng(0))
    assert np.array_equal(problem.batch_objectives(X), problem.evaluate(X))


def test_batch_objectives_step_aside_for_a_subclass_that_evaluates_differently():
    class Shifted(PositionIK):
        def _evaluate(self, X, out, *args, **kwargs):
            super()._evaluate(X, out, *args, **kwargs)
            out["F"] = out["F"] + 1.0

    robot = get_robot("eosma7")
    problem = Shifted(robot, np.array([30.0, 20.0, 40.0]))
    assert problem.batch_objectives(robot.random_q(3, rng=np.random.default_rng(0))) is None
    res = minimize(problem, EOSMA(pop_size=10), ("n_gen", 3), seed=1)
    assert res.F[0] >= 1.0  # the subclass's own objective was used
