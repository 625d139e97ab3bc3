"""solve_ik_pareto: exact members, mutually non-dominated, deterministic, bad input."""

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.optimize import minimize

from moik import solve_ik, solve_ik_pareto
from moik.exceptions import MoikError, NonFiniteError, ParameterError, ShapeError, UnknownNameError
from moik.kinematics.criteria import Criterion
from moik.problems import ParetoIK, random_reachable_targets
from moik.robots import fk_reference, get_robot
from moik.solver.pareto_search import ProjectionRepair, spread_subset

IIWA = get_robot("iiwa14")
POSE = random_reachable_targets(IIWA, 1, seed=11)[0]
Q_CURRENT = np.clip(POSE.q_source + np.random.default_rng(1).normal(scale=0.2, size=7),
                    IIWA.lower, IIWA.upper)


def _reference_errors(robot, target, X):
    T = fk_reference(robot, X)
    pos = np.linalg.norm(T[:, :3, 3] - target.position, axis=1)
    if target.rotation is None:
        return pos, np.zeros(len(X))
    M = np.einsum("nji,jk->nik", T[:, :3, :3], target.rotation)
    skew = np.stack([M[:, 2, 1] - M[:, 1, 2], M[:, 0, 2] - M[:, 2, 0], M[:, 1, 0] - M[:, 0, 1]])
    return pos, np.arctan2(np.linalg.norm(skew, axis=0), np.trace(M, axis1=1, axis2=2) - 1)


def _dominated(F_min):
    """Whether some row dominates another (minimisation)."""
    return bool(np.any(np.all(F_min[:, None] <= F_min[None], axis=2)
                       & np.any(F_min[:, None] < F_min[None], axis=2)))


@pytest.fixture(scope="module")
def iiwa_result():
    return solve_ik_pareto(IIWA, POSE, q_current=Q_CURRENT, seed=3)


def test_every_member_is_exact_within_limits_and_non_dominated(iiwa_result):
    res = iiwa_result
    assert res.redundant and len(res.X) >= 10 and res.F.shape == (len(res.X), 2)
    pos, ori = _reference_errors(IIWA, POSE, res.X)
    assert np.all(pos <= 1e-9 * IIWA.reach) and np.all(ori <= 1e-9)
    np.testing.assert_allclose(res.position_errors, pos, atol=1e-15)
    assert np.all(IIWA.within_limits(res.X))
    # criteria recomputed independently: joint motion in numpy, F_min's signs
    np.testing.assert_allclose(res.F[:, 0], np.linalg.norm(res.X - Q_CURRENT, axis=1),
                               rtol=1e-12)
    np.testing.assert_array_equal(res.F_min, res.F * [1.0, -1.0])
    assert not _dominated(res.F_min)
    assert np.all(np.diff(res.F[:, 0]) >= 0)  # sorted by the first criterion


def test_nearest_member_is_at_least_as_near_as_solve_ik_from_q_current(iiwa_result):
    res = iiwa_result
    local = solve_ik(IIWA, POSE, q_current=Q_CURRENT)
    assert res.F[0, 0] <= np.linalg.norm(local.q - Q_CURRENT) + 1e-12
    best = res.best("manipulability")
    assert res.F[best, 1] == res.F[:, 1].max()


def test_same_seed_same_result_bit_for_bit(iiwa_result):
    again = solve_ik_pareto(IIWA, POSE, q_current=Q_CURRENT, seed=3)
    np.testing.assert_array_equal(again.X, iiwa_result.X)
    np.testing.assert_array_equal(again.F, iiwa_result.F)
    assert again.n_eval == iiwa_result.n_eval


def test_compromise_is_a_member(iiwa_result):
    q, f = iiwa_result.compromise()
    i = iiwa_result.compromise_index()
    np.testing.assert_array_equal(iiwa_result.X[i], q)
    np.testing.assert_array_equal(iiwa_result.F[i], f)


def test_result_is_the_problem_evaluated_at_its_members(iiwa_result):
    problem = ParetoIK(IIWA, POSE, q_current=Q_CURRENT)
    out = problem.evaluate(iiwa_result.X, return_as_dictionary=True)
    np.testing.assert_array_equal(out["F"], iiwa_result.F_min)
    assert np.all(out["G"] <= 0)


def test_six_dof_arm_returns_the_non_dominated_branches():
    robot = get_robot("ur5")
    target = random_reachable_targets(robot, 1, seed=4)[0]
    res = solve_ik_pareto(robot, target, q_current=target.q_source + 0.1,
                          objectives=("joint_motion", "manipulability", "limit_margin"))
    assert not res.redundant and 1 <= len(res.X) <= res.n_exact <= 16
    pos, ori = _reference_errors(robot, target, res.X)
    assert np.all(pos <= 1e-9 * robot.reach) and np.all(ori <= 1e-9)
    assert not _dominated(res.F_min)
    assert res.F[0, 0] == pytest.approx(0.1 * np.sqrt(6), rel=1e-6)  # the source branch


def test_position_target_with_a_preferred_orientation():
    target = random_reachable_targets(IIWA, 1, seed=6)[0]
    res = solve_ik_pareto(IIWA, target.position, objectives=("orientation", "manipulability"),
                          rotation=target.rotation, generations=5)
    assert res.redundant and np.all(res.orientation_errors == 0.0)
    assert res.F[0, 0] < 1e-9  # the preferred rotation is reachable: its solutions are found
    pos, _ = _reference_errors(IIWA, target, res.X)
    assert np.all(pos <= 1e-9 * IIWA.reach)


def test_user_callable_and_other_algorithms():
    elbow = Criterion("elbow", lambda Q: np.abs(Q[:, 3]), sense="max")
    for method in ("nsga2", "mopso"):
        res = solve_ik_pareto(IIWA, POSE, objectives=(elbow, lambda Q: Q[:, 0] ** 2),
                              method=method, generations=4, n_solutions=5)
        assert res.objectives == ("elbow", "criterion_2") and 1 <= len(res.X) <= 5
        assert not _dominated(res.F_min)
        np.testing.assert_allclose(res.F[:, 0], np.abs(res.X[:, 3]))


def test_unreachable_target_gives_an_empty_set():
    res = solve_ik_pareto(IIWA, [2.0, 0.0, 0.0], objectives=("manipulability",),
                          generations=2, starts=8)
    assert res.X.shape == (0, 7) and res.F.shape == (0, 1)
    with pytest.raises(ShapeError, match="no exact solution"):
        res.compromise()


def test_spread_subset_keeps_each_criterions_best():
    F = np.column_stack([np.linspace(0, 1, 50), np.linspace(1, 0, 50) ** 2])
    idx = spread_subset(F, 6)
    assert len(set(idx)) == 6 and {0, 49} <= set(idx)
    np.testing.assert_array_equal(spread_subset(F[:4], 6), np.arange(4))


@pytest.mark.parametrize(("kwargs", "error", "match"), [
    ({"objectives": ("speed",)}, UnknownNameError, "unknown criterion 'speed'"),
    ({"objectives": ("joint_motion",)}, ParameterError, "needs q_current"),
    ({"objectives": (lambda Q: Q[:, :2],)}, ShapeError, r"must return shape \(\d+,\)"),
    ({"objectives": (lambda Q: np.full(len(Q), np.nan),)}, NonFiniteError, "non-finite"),
    ({"method": "eosma"}, ParameterError, "multi-objective algorithm"),
    ({"method": "nope"}, UnknownNameError, "unknown algorithm"),
    ({"n_solutions": 2.0}, ParameterError, "n_solutions"),
    ({"pop_size": 1}, ParameterError, "pop_size"),
    ({"local_step": 0.0}, ParameterError, "local_step"),
    ({"tol": -1.0}, ParameterError, "tol"),
    ({"seed": -1}, ParameterError, "seed"),
    ({"q_current": np.zeros(3)}, ShapeError, "q_current"),
])
def test_bad_input_raises_a_moik_error(kwargs, error, match):
    options = {"objectives": ("manipulability",), "generations": 1, "starts": 4, **kwargs}
    with pytest.raises(error, match=match) as info:
        solve_ik_pareto(IIWA, POSE, **options)
    assert isinstance(info.value, MoikError)


def test_projection_repair_makes_a_pymoo_algorithm_memetic():
    problem = ParetoIK(IIWA, POSE, q_current=Q_CURRENT)
    run = minimize(problem, NSGA2(pop_size=20, repair=ProjectionRepair(problem)), ("n_gen", 3),
                   seed=2)
    assert run.F is not None and np.all(np.atleast_2d(run.CV) <= 0)  # every member exact
