"""Shared problems and checks of the algorithm tests (fixtures: ``sphere``, ``ik``, ``check``).

The checks are the properties each algorithm's test module asserts for its own
algorithm (same seed, same run; an exact evaluation budget; bounds respected;
feasibility first; a non-dominated front; a reference level on the sphere, on
IK and on the spring design), written once here and called with each module's
settings.
"""

from __future__ import annotations

import functools
from collections.abc import Callable

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.core.algorithm import Algorithm
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms.archive import nondominated_mask
from moik.metrics import compromise, hypervolume
from moik.problems import BiObjectiveIK, PositionIK, random_reachable_targets
from moik.problems.benchmarks import get_benchmark
from moik.robots import get_robot

Make = Callable[[], Algorithm]


class Sphere(Problem):
    """``f(x) = |x|^2`` on ``[-bound, bound]^n_var``; with ``g``, one constraint ``g(X) <= 0``."""

    def __init__(self, n_var: int = 10, bound: float = 100.0, g=None):
        super().__init__(n_var=n_var, n_obj=1, n_ieq_constr=0 if g is None else 1, xl=-bound,
                         xu=bound)
        self.g = g

    @staticmethod
    def x0_at_least_1(X: np.ndarray) -> np.ndarray:
        """The constraint ``x0 >= 1`` (``1 - x0 <= 0``): the constrained optimum is f = 1."""
        return 1.0 - X[:, :1]

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = (X * X).sum(axis=1)
        if self.g is not None:
            out["G"] = self.g(X)


class IKProblems:
    """The IK problems the algorithm tests run on (the EOSMA paper's 7-DOF arm, cm)."""

    Q_GENERAL = np.array([0.3, -0.5, 0.4, 1.0, -0.2, 0.6, 0.1])
    """A joint vector away from singularities (target about 50 cm from the initial best)."""
    Q_45 = np.deg2rad([45.0, 0.0, 45.0, 0.0, 45.0, 0.0, 0.0])
    """Joints 1, 3 and 5 at 45 degrees."""

    @staticmethod
    def position(q) -> PositionIK:
        """Position IK whose target is the arm's position at the joint vector ``q``."""
        robot = get_robot("eosma7")
        return PositionIK(robot, robot.fk_position(np.asarray(q, dtype=float)[None])[0])

    @staticmethod
    def biobjective() -> BiObjectiveIK:
        """Position and orientation errors to a random reachable pose (seed 0)."""
        robot = get_robot("eosma7")
        return BiObjectiveIK(robot, random_reachable_targets(robot, 1, seed=0)[0].pose)


class Checks:
    """Assertions shared by the algorithm test modules; each returns the run it checked."""

    @staticmethod
    def reproducible_exact_budget(make: Make, problem: Problem, *, n_eval: int, seed: int,
                                  bound: float, other_seed: int | None = None):
        """Same seed -> the same X and F bit for bit; exactly ``n_eval`` evaluations; the
        result, the reported population and the current state within ``|x| <= bound``;
        another seed -> another X."""
        runs = [minimize(problem, make(), ("n_eval", n_eval), seed=seed) for _ in range(2)]
        np.testing.assert_array_equal(runs[0].X, runs[1].X)
        np.testing.assert_array_equal(runs[0].F, runs[1].F)
        res = runs[0]
        assert res.algorithm.evaluator.n_eval == n_eval
        assert np.all(np.abs(res.X) <= bound) and np.all(np.abs(res.pop.get("X")) <= bound)
        assert np.all(np.abs(res.algorithm.X) <= bound)
        if other_seed is not None:
            other = minimize(problem, make(), ("n_eval", n_eval), seed=other_seed)
            assert not np.array_equal(other.X, res.X)
        return res

    @staticmethod
    def solves_sphere(make: Make, *, level: float, n_eval: int = 30_000, seed: int = 1):
        """The 10-D sphere on [-100, 100]^10 below ``level`` within exactly ``n_eval``
        evaluations."""
        res = minimize(Sphere(), make(), ("n_eval", n_eval), seed=seed)
        assert res.algorithm.evaluator.n_eval == n_eval and res.F[0] < level
        return res

    @staticmethod
    def improves_on_position_ik(make: Make, q, termination, *, level: float, seed: int = 2):
        """Position IK to the arm's position at ``q``: an answer within the joint limits,
        below ``level`` (cm) and below the initial population's best."""
        problem = IKProblems.position(q)
        res = minimize(problem, make(), termination, seed=seed)
        xl, xu = problem.bounds()
        assert np.all(np.clip(res.X, xl, xu) == res.X)
        assert np.isfinite(res.F[0]) and res.F[0] < level
        assert res.F[0] < res.algorithm.convergence[0]
        return res

    @staticmethod
    def feasibility_first(make: Make, *, n_eval: int = 4000, seed: int = 2):
        """min |x|^2 subject to x0 >= 1 on [-5, 5]^3: a feasible answer near f = 1."""
        problem = Sphere(n_var=3, bound=5.0, g=Sphere.x0_at_least_1)
        res = minimize(problem, make(), ("n_eval", n_eval), seed=seed)
        assert res.X is not None and res.X[0] >= 1.0 and res.F[0] < 1.1
        return res

    @staticmethod
    def ask_tell_matches_minimize(make: Make, problem: Problem, termination, *, seed: int):
        """``ask()``/``tell()`` with the algorithm's own evaluator gives minimize's run."""
        ref = minimize(problem, make(), termination, seed=seed)
        algo = make()
        algo.setup(problem, termination=termination, seed=seed)
        while algo.has_next():  # the algorithm's own evaluator counts n_eval for the termination
            pop = algo.ask()
            algo.evaluator.eval(problem, pop)
            algo.tell(infills=pop)
        np.testing.assert_array_equal(algo.result().X, ref.X)
        assert algo.evaluator.n_eval == ref.algorithm.evaluator.n_eval
        return ref

    @staticmethod
    def n_eval_after(make: Make, problem: Problem, termination, *, seed: int = 0) -> int:
        """Evaluations a run used (to check the documented evaluations per iteration)."""
        return minimize(problem, make(), termination, seed=seed).algorithm.evaluator.n_eval

    @staticmethod
    def spring_feasible(make: Make, *, n_eval: int, seed: int = 3):
        """The tension/compression spring design: the best design is feasible."""
        problem = get_benchmark("spring")
        res = minimize(problem, make(), ("n_eval", n_eval), seed=seed)
        G = problem.evaluate(res.X[None], return_values_of=["G"])
        assert np.all(G <= 0.0) and res.CV[0] == 0.0
        return res

    @staticmethod
    def classical_benchmark(make: Make, name: str, *, level: float, n_eval: int = 15_000,
                            seed: int = 2):
        """A classical benchmark (10-D) below ``level`` above its optimum."""
        problem = get_benchmark(name, n_var=10)
        res = minimize(problem, make(), ("n_eval", n_eval), seed=seed)
        assert res.F[0] < level + problem.f_opt
        return res

    @staticmethod
    def mo_problem(name: str) -> Problem:
        """``"zdt1"`` (10 variables) or ``"ik"`` (:meth:`IKProblems.biobjective`)."""
        return IKProblems.biobjective() if name == "ik" else get_problem("zdt1", n_var=10)

    @staticmethod
    def mo_reproducible_front(make: Make, problem: Problem, *, n_eval: int, seed: int,
                              pop_size: int = 20):
        """Same seed -> the same front bit for bit; exactly ``n_eval`` evaluations; 1 to
        ``pop_size`` two-objective rows, within the bounds, non-dominated; the compromise
        is one of them."""
        xl, xu = problem.bounds()
        runs = [minimize(problem, make(), ("n_eval", n_eval), seed=seed) for _ in range(2)]
        np.testing.assert_array_equal(runs[0].X, runs[1].X)
        np.testing.assert_array_equal(runs[0].F, runs[1].F)
        res = runs[0]
        assert res.algorithm.evaluator.n_eval == n_eval
        assert res.F.shape[1] == 2 and 1 <= len(res.F) <= pop_size
        assert np.array_equal(np.clip(res.X, xl, xu), res.X)
        assert nondominated_mask(res.F).all()
        _, f = compromise(res)
        assert any(np.array_equal(f, row) for row in res.F)
        return res

    @staticmethod
    def zdt1_hypervolume(make: Make, *, n_var: int, n_eval: int, seed: int = 0) -> float:
        """Hypervolume (reference (1.1, 1.1)) of the front on ZDT1 with ``n_var`` variables."""
        res = minimize(get_problem("zdt1", n_var=n_var), make(), ("n_eval", n_eval), seed=seed)
        return hypervolume(res.F, [1.1, 1.1])

    @staticmethod
    @functools.cache
    def nsga2_zdt1_hypervolume(*, n_var: int, n_eval: int, pop_size: int,
                               seed: int = 0) -> float:
        """pymoo NSGA2's :meth:`zdt1_hypervolume` (the reference of the MO tests), cached."""
        return Checks.zdt1_hypervolume(lambda: NSGA2(pop_size=pop_size), n_var=n_var,
                                       n_eval=n_eval, seed=seed)


@pytest.fixture
def sphere() -> type[Sphere]:
    """The :class:`Sphere` problem class."""
    return Sphere


@pytest.fixture
def ik() -> type[IKProblems]:
    """The IK problems (:class:`IKProblems`)."""
    return IKProblems


@pytest.fixture
def check() -> type[Checks]:
    """The shared assertions (:class:`Checks`)."""
    return Checks
