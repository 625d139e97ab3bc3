"""ParetoIK: criteria as objectives (minimisation form), the pose error as constraints."""

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.optimize import minimize

from moik.exceptions import NonFiniteError, ParameterError, ShapeError
from moik.kinematics.criteria import Criterion
from moik.problems import ParetoIK, random_reachable_targets
from moik.robots import get_robot

ROBOT = get_robot("iiwa14")
TARGET = random_reachable_targets(ROBOT, 1, seed=5)[0]
Q_CURRENT = TARGET.q_source + 0.05


def test_objectives_are_the_criteria_in_minimisation_form_and_g_the_pose_error():
    problem = ParetoIK(ROBOT, TARGET, q_current=Q_CURRENT)
    assert (problem.n_obj, problem.n_ieq_constr, problem.n_var) == (2, 2, 7)
    assert problem.names == ("joint_motion", "manipulability")
    assert problem.senses == ("min", "max")
    X = np.vstack([TARGET.q_source, ROBOT.random_q(3, rng=np.random.default_rng(0))])
    out = problem.evaluate(X, return_as_dictionary=True)
    natural = problem.natural(X)
    np.testing.assert_array_equal(out["F"], natural * [1.0, -1.0])
    np.testing.assert_allclose(natural[0, 0], 0.05 * np.sqrt(7), rtol=1e-12)
    assert natural[0, 1] > 0
    assert np.all(out["G"][0] < 0)  # the source configuration is exact
    assert np.all(out["G"][1:, 0] > 0)  # random ones miss the position
    pos, ori = problem.pose_errors(X[1:2])
    np.testing.assert_allclose(out["G"][1], [(pos[0] - 1e-9 * ROBOT.reach) / ROBOT.reach,
                                             ori[0] - 1e-9], rtol=1e-12)


def test_position_target_has_one_constraint_and_may_use_orientation():
    problem = ParetoIK(ROBOT, TARGET.position, objectives=("orientation", "limit_margin"),
                       rotation=TARGET.rotation, tol=(1e-6, 1e-6))
    assert problem.n_ieq_constr == 1 and (problem.tol_position, problem.tol_orientation) == (
        1e-6, 1e-6)
    out = problem.evaluate(TARGET.q_source[None], return_as_dictionary=True)
    assert out["F"][0, 0] == pytest.approx(0.0, abs=1e-12) and out["G"].shape == (1, 1)


def test_any_pymoo_algorithm_runs_on_it():
    problem = ParetoIK(ROBOT, TARGET, objectives=("manipulability", "limit_margin"), tol=0.5)
    res = minimize(problem, NSGA2(pop_size=20), ("n_gen", 3), seed=1)
    assert res.algorithm.evaluator.n_eval == 60
    if res.X is not None:  # a feasible front: every member meets the (loose) tolerance
        out = problem.evaluate(np.atleast_2d(res.X), return_as_dictionary=True)
        assert np.all(out["G"] <= 0)


def test_tolerances_are_solve_iks():
    """ParetoIK reads tol as solve_ik does (moik.kinematics.tolerance.Tolerance.of)."""
    target = ROBOT.fk(np.zeros(ROBOT.dof))
    assert ParetoIK(ROBOT, target, q_current=Q_CURRENT, tol=1e-6).tol == (1e-6 * ROBOT.reach, 1e-6)
    assert ParetoIK(ROBOT, target, q_current=Q_CURRENT, tol=(1e-3, 2e-3)).tol == (1e-3, 2e-3)
    for bad in (0.0, -1.0, True, "1e-9", (1e-3, 0.0), 1e-15, (1e-3, 1e-16)):
        with pytest.raises(ParameterError, match="tol"):
            ParetoIK(ROBOT, target, q_current=Q_CURRENT, tol=bad)
    with pytest.raises(ParameterError, match="tol must be a number or"):
        ParetoIK(ROBOT, target, q_current=Q_CURRENT, tol=(1.0, 2.0, 3.0))


def test_bad_input():
    with pytest.raises(ParameterError, match="moik Robot"):
        ParetoIK("iiwa14", TARGET)
    with pytest.raises(ParameterError, match="needs q_current"):
        ParetoIK(ROBOT, TARGET)
    with pytest.raises(ParameterError, match="one joint vector"):
        ParetoIK(ROBOT, TARGET, q_current=np.zeros((2, 7)))
    with pytest.raises(ShapeError):
        ParetoIK(ROBOT, TARGET, q_current=np.zeros(6))
    problem = ParetoIK(ROBOT, TARGET, objectives=(Criterion("bad", lambda Q: Q[:, 0] / 0.0),))
    with pytest.raises(NonFiniteError, match="criterion 'bad'"), np.errstate(all="ignore"):
        problem.evaluate(np.zeros((1, 7)))
