"""Constraint handling of every multi-objective algorithm: constraint-domination in the
archives, memories and rankings; only feasible members reported (moik.algorithms.moo)."""

from __future__ import annotations

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import available, get_algorithm
from moik.algorithms.archive import CrowdingArchive, GridArchive, constrained_nondominated_mask
from moik.algorithms.moo.dominance import constrained_dominates, dominance_memory
from moik.algorithms.moo.mosma import elitist_order
from moik.exceptions import ShapeError
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots import get_robot

MO_NAMES = available("multi-objective")


def test_constrained_dominates_by_hand():
    F = np.array([[0.0, 0.0], [5.0, 5.0], [1.0, 2.0], [2.0, 1.0], [1.0, 1.0]])
    a = np.array([0, 0, 2, 2, 4])
    b = np.array([1, 2, 3, 0, 2])
    CV = np.array([0.5, 0.2, 0.0, 0.0, 0.0])
    # infeasible 0.5 vs 0.2: the smaller violation wins although F is better
    # infeasible vs feasible: the feasible wins; feasible pair: Pareto dominance
    got = constrained_dominates(F[a], CV[a], F[b], CV[b])
    np.testing.assert_array_equal(got, [False, False, False, True, True])
    np.testing.assert_array_equal(constrained_dominates(F[b], CV[b], F[a], CV[a]),
                                  [True, True, False, False, False])
    np.testing.assert_array_equal(constrained_dominates(F[a], None, F[b], None),
                                  [True, True, False, False, True])  # unconstrained: Eq. 11


def test_dominance_memory_keeps_only_a_constraint_dominating_old_point():
    PX, X = np.zeros((3, 1)), np.ones((3, 1))
    PF = np.array([[1.0, 1.0], [3.0, 3.0], [9.0, 9.0]])
    F = np.array([[0.0, 0.0], [2.0, 2.0], [0.0, 0.0]])
    PCV, CV = np.array([0.0, 0.0, 0.0]), np.array([0.1, 0.0, np.inf])
    MX, MF, MCV = dominance_memory(X, F, CV, PX, PF, PCV)
    # feasible old points beat an infeasible (and an unevaluated) new one; (2, 2) replaces (3, 3)
    np.testing.assert_array_equal(MX[:, 0], [0.0, 1.0, 0.0])
    np.testing.assert_array_equal(MCV, [0.0, 0.0, 0.0])
    np.testing.assert_array_equal(MF, [[1.0, 1.0], [2.0, 2.0], [9.0, 9.0]])
    MX, MF, MCV = dominance_memory(PX, PF, PCV, X, F, CV)  # roles swapped
    np.testing.assert_array_equal(MX[:, 0], [0.0, 1.0, 0.0])
    np.testing.assert_array_equal(MCV, [0.0, 0.0, 0.0])


def test_constrained_nondominated_mask():
    F = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 1.0], [3.0, 3.0], [0.5, 0.5]])
    CV = np.array([1.0, 0.0, 0.0, 0.0, 0.3])
    np.testing.assert_array_equal(constrained_nondominated_mask(F, CV),
                                  [False, True, True, False, False])
    CV = np.array([1.0, 0.3, 0.3, 0.9, 0.3])  # no feasible row: the least violation, then F
    np.testing.assert_array_equal(constrained_nondominated_mask(F, CV),
                                  [False, False, False, False, True])


@pytest.mark.parametrize("make", [CrowdingArchive.moeosma, CrowdingArchive.mirjalili,
                                  GridArchive.mopso, GridArchive.mogwo])
def test_archives_hold_feasible_members_once_one_is_seen(make):
    rng = np.random.default_rng(0)
    archive = make(5)
    F = rng.random((20, 2))
    archive.add(np.arange(20.0)[:, None], F, rng=rng, CV=np.linspace(1.0, 0.05, 20),
                extra=-np.ones((20, 1)))
    # none feasible: the capacity's least infeasible rows (NSGA-II's constrained survival)
    np.testing.assert_array_equal(np.sort(archive.X[:, 0]), [15.0, 16.0, 17.0, 18.0, 19.0])
    np.testing.assert_allclose(np.sort(archive.CV), np.linspace(1.0, 0.05, 20)[-5:][::-1])
    archive.add(50 + np.arange(2.0)[:, None], F[:2], rng=rng, CV=[0.01, 2.0],
                extra=-np.ones((2, 1)))  # a better infeasible row replaces the worst
    assert 50.0 in archive.X[:, 0] and 15.0 not in archive.X[:, 0] and len(archive) == 5
    CV = np.where(np.arange(20) % 2 == 0, 0.0, 1.0)
    archive.add(100 + np.arange(20.0)[:, None], F, rng=rng, CV=CV, extra=np.zeros((20, 1)))
    assert np.all(archive.CV == 0.0) and np.all(archive.extra == 0.0)
    assert np.all(archive.X[:, 0] % 2 == 0) and 1 <= len(archive) <= 5
    with pytest.raises(ShapeError, match="CV must be given on every add"):
        archive.add(np.zeros((1, 1)), np.zeros((1, 2)), rng=rng)
    with pytest.raises(ShapeError, match="one entry per row"):
        archive.add(np.zeros((2, 1)), np.zeros((2, 2)), rng=rng, CV=[0.0], extra=np.zeros((2, 1)))


def test_elitist_order_puts_feasible_rows_first():
    F = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 1.0], [3.0, 3.0], [0.5, 0.5]])
    CV = np.array([1.0, 0.0, 0.0, 0.0, 0.3])
    index, rank = elitist_order(F, 5, CV)
    assert set(index[:2]) == {1, 2} and index[2] == 3 and index[3:].tolist() == [4, 0]
    np.testing.assert_array_equal(rank, [0, 0, 1, 2, 3])


class JointMotionIK(Problem):
    """The EOSMA arm's bi-objective IK with a joint-motion limit: ``|q_j - q0_j| <= 0.5``."""

    def __init__(self):
        robot = get_robot("eosma7-m")
        self.q0 = np.deg2rad([45.0, 0.0, 45.0, 0.0, 45.0, 0.0, 0.0])
        target = Target.from_euler((0.5, -0.25, 0.75), (0, 0, 0), convention="eosma-euler",
                                   degrees=True)
        self.ik = BiObjectiveIK(robot, target, orientation="eosma-euler")
        super().__init__(n_var=robot.dof, n_obj=2, n_ieq_constr=robot.dof,
                         xl=robot.lower, xu=robot.upper)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = self.ik.evaluate(X, return_values_of=["F"])
        out["G"] = np.abs(X - self.q0) - 0.5


def _feasible_members(problem, res) -> None:
    assert res.F is not None and len(res.F) >= 1
    F, G = problem.evaluate(res.X, return_values_of=["F", "G"])
    assert np.all(G <= 0.0)  # re-evaluated: every reported member is feasible
    np.testing.assert_allclose(res.F, F)
    np.testing.assert_array_equal(res.CV, 0.0)
    np.testing.assert_allclose(res.G, G)


@pytest.mark.parametrize("name", MO_NAMES)
@pytest.mark.parametrize("problem_name", ["bnh", "tnk", "osy"])
def test_only_feasible_members_on_pymoos_constrained_problems(name, problem_name):
    problem = get_problem(problem_name)
    res = minimize(problem, get_algorithm(name, pop_size=20), ("n_eval", 1500), seed=1)
    _feasible_members(problem, res)


@pytest.mark.parametrize("name", MO_NAMES)
def test_ik_with_a_joint_motion_constraint(name):
    problem = JointMotionIK()
    res = minimize(problem, get_algorithm(name, pop_size=20), ("n_eval", 1000), seed=2)
    _feasible_members(problem, res)
    assert np.all(np.abs(res.X - problem.q0) <= 0.5)


class NeverFeasible(Problem):
    """Two objectives and one constraint no point satisfies: g = 1 + x0^2 > 0."""

    def __init__(self):
        super().__init__(n_var=2, n_obj=2, n_ieq_constr=1, xl=-1.0, xu=1.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = np.column_stack([X[:, 0], -X[:, 0]])
        out["G"] = 1.0 + X[:, :1] ** 2


@pytest.mark.parametrize("name", MO_NAMES)
def test_an_infeasible_archive_is_never_reported_as_feasible(name):
    res = minimize(NeverFeasible(), get_algorithm(name, pop_size=10), ("n_eval", 300), seed=0)
    assert res.X is None and res.F is None
    alg = get_algorithm(name, pop_size=10, return_least_infeasible=True)
    least = minimize(NeverFeasible(), alg, ("n_eval", 300), seed=0)
    assert least.X is not None and np.all(least.CV > 0.0)
