"""The pymoo contract of ArrayAlgorithm: terminations, ask/tell, history, callbacks, output."""

import numpy as np
import pytest
from pymoo.core.callback import Callback
from pymoo.core.evaluator import Evaluator
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import EO, EOSMA, MPSO, PSO, SMA
from moik.exceptions import NonFiniteError, ParameterError, ShapeError


class Sphere(Problem):
    def __init__(self, n_var=7, n_ieq_constr=0, g=None):
        super().__init__(n_var=n_var, n_obj=1, n_ieq_constr=n_ieq_constr, xl=-5.0, xu=5.0)
        self.g = g

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = (X * X).sum(axis=1)
        if self.g is not None:
            out["G"] = self.g(X)


@pytest.mark.parametrize("cls", [EOSMA, EO, SMA, PSO, MPSO])
def test_terminations_and_result(cls):
    problem = Sphere()
    res = minimize(problem, cls(pop_size=20), ("n_gen", 15), seed=3)
    assert res.algorithm.convergence.shape == (15,)
    assert res.algorithm.best_x_history.shape == (15, 7)
    np.testing.assert_array_equal(res.algorithm.best_x_history[-1], res.X)
    assert np.all(np.diff(res.algorithm.convergence) <= 0)
    assert res.X.shape == (7,) and res.F.shape == (1,)
    assert res.F[0] == pytest.approx(float((res.X**2).sum()), rel=1e-12)
    assert res.F[0] == res.algorithm.convergence[-1] == res.opt[0].F[0]
    assert len(res.pop) == 20 and res.exec_time > 0
    assert np.all((res.pop.get("X") >= -5) & (res.pop.get("X") <= 5))
    res = minimize(problem, cls(pop_size=20), ("time", 0.2), seed=3)
    assert 0.2 <= res.exec_time < 1.0
    res = minimize(problem, cls(pop_size=20), seed=3)  # the default: the whole schedule of
    assert res.algorithm.t == res.algorithm.max_iter == 999 and res.F[0] < 1e-3  # pymoo's 1000
    assert res.algorithm.n_gen == 1001  # generations, the initial one included


def test_time_termination_string():
    res = minimize(Sphere(), EOSMA(pop_size=20), ("time", "00:00:01"), seed=3)
    assert 1.0 <= res.exec_time < 2.0  # T planned from the time spent (one rule, array_base.py)
    assert res.algorithm.t <= res.algorithm.max_iter < 2 * res.algorithm.t


@pytest.mark.parametrize("budget", [1000, 1037, 20])
@pytest.mark.parametrize("make", [lambda: EOSMA(pop_size=20, q=1.0), lambda: MPSO(pop_size=20),
                                  lambda: SMA(pop_size=20)])
def test_n_eval_budget_is_exact(make, budget):
    res = minimize(Sphere(), make(), ("n_eval", budget), seed=0)
    assert res.algorithm.evaluator.n_eval == budget
    assert np.isfinite(res.F[0])


def test_schedule_length_from_termination():
    algo = EOSMA(pop_size=10, q=1.0)
    res = minimize(Sphere(), algo, ("n_eval", 2010), seed=0)
    assert res.algorithm.max_iter == 100  # 10 initial + 100 iterations of 2N
    assert minimize(Sphere(), EO(pop_size=10), ("n_gen", 7), seed=0).algorithm.max_iter == 6
    assert minimize(Sphere(), EO(pop_size=10, max_iter=50), ("n_gen", 7),
                    seed=0).algorithm.max_iter == 50


def test_evaluations_per_generation():
    n_eval = {cls.__name__: minimize(Sphere(), cls(pop_size=10, **kw), ("n_gen", 3),
                                     seed=0).algorithm.evaluator.n_eval
              for cls, kw in [(EOSMA, {"q": 1.0}), (EOSMA, {"q": 0.0}), (MPSO, {}),
                              (MPSO, {"switch": "mean-fitness"}), (PSO, {})]}
    assert n_eval == {"EOSMA": 30, "MPSO": 30, "PSO": 30}  # the last of each kind
    assert minimize(Sphere(), EOSMA(pop_size=10, q=1.0), ("n_gen", 3),
                    seed=0).algorithm.evaluator.n_eval == 50
    assert minimize(Sphere(), MPSO(pop_size=10), ("n_gen", 3),
                    seed=0).algorithm.evaluator.n_eval == 32


@pytest.mark.parametrize("make", [lambda: EOSMA(pop_size=15, q=1.0), lambda: MPSO(pop_size=15),
                                  lambda: SMA(pop_size=15)])
def test_ask_tell_matches_minimize(make):
    problem = Sphere()
    ref = minimize(problem, make(), ("n_gen", 12), seed=5)
    algo = make()
    algo.setup(problem, termination=("n_gen", 12), seed=5)
    evaluator = Evaluator()
    while algo.has_next():
        pop = algo.ask()
        evaluator.eval(problem, pop)
        algo.tell(infills=pop)
    res = algo.result()
    np.testing.assert_array_equal(res.X, ref.X)
    np.testing.assert_array_equal(algo.convergence, ref.algorithm.convergence)
    assert evaluator.n_eval == ref.algorithm.evaluator.n_eval


def test_save_history_and_callback_read_arrays():
    seen = []

    class Record(Callback):
        def notify(self, algorithm):
            seen.append((algorithm.n_gen, algorithm.best_f, algorithm.pbest_F.min(),
                         algorithm.X.shape))

    res = minimize(Sphere(), EOSMA(pop_size=10), ("n_gen", 6), seed=1, save_history=True,
                   callback=Record())
    assert [s[0] for s in seen] == [1, 2, 3, 4, 5, 6]
    assert [s[1] for s in seen] == list(res.algorithm.convergence)
    assert all(s[1] == s[2] and s[3] == (10, 7) for s in seen)
    assert len(res.history) == 6
    hist_best = [h.opt[0].F[0] for h in res.history]
    assert hist_best == list(res.algorithm.convergence)
    np.testing.assert_array_equal(res.history[0].pop.get("F")[:, 0], res.history[0].pbest_F)


def test_verbose_prints_columns(capsys):
    minimize(Sphere(), PSO(pop_size=10), ("n_gen", 3), seed=1, verbose=True)
    out = capsys.readouterr().out
    assert "n_gen" in out and "n_eval" in out and "f_best" in out
    assert len([line for line in out.splitlines() if "|" in line]) == 4  # header + 3 rows


def test_initial_population_x0():
    X0 = np.full((3, 7), 0.5)
    res = minimize(Sphere(), PSO(pop_size=10, X0=X0), ("n_gen", 1), seed=1)
    np.testing.assert_array_equal(res.pop.get("X")[:3], X0)
    with pytest.raises(ShapeError, match=r"X0 must have shape \(k, 7\)"):
        minimize(Sphere(), PSO(pop_size=10, X0=np.zeros((3, 6))), ("n_gen", 1))
    with pytest.raises(ParameterError, match="outside the problem bounds"):
        minimize(Sphere(), PSO(pop_size=10, X0=np.full((1, 7), 9.0)), ("n_gen", 1))
    with pytest.raises(NonFiniteError, match="NaN"):
        minimize(Sphere(), PSO(pop_size=10, X0=np.full((1, 7), np.nan)), ("n_gen", 1))


def test_bad_problem_and_size():
    with pytest.raises(ParameterError, match="single-objective"):
        minimize(get_problem("zdt1"), EO(), ("n_gen", 2))
    with pytest.raises(ParameterError, match=r"pop_size must be an integer >= 3"):
        EOSMA(pop_size=2)
    with pytest.raises(ParameterError, match="max_iter"):
        SMA(max_iter=0)


@pytest.mark.parametrize("cls", [EOSMA, EO, SMA, PSO, MPSO])
def test_constraints_feasibility_first(cls):
    # min |x|^2 s.t. x0 >= 1: the unconstrained optimum is infeasible
    problem = Sphere(n_var=3, n_ieq_constr=1, g=lambda X: (1.0 - X[:, 0])[:, None])
    res = minimize(problem, cls(pop_size=30), ("n_gen", 150), seed=2)
    assert res.X is not None and res.X[0] >= 1.0 and res.CV[0] == 0.0
    assert res.F[0] == pytest.approx(1.0, abs=1e-2)


def test_never_reports_infeasible_as_feasible():
    problem = Sphere(n_var=2, n_ieq_constr=1, g=lambda X: np.ones((len(X), 1)))
    res = minimize(problem, EOSMA(pop_size=10), ("n_gen", 5), seed=0)
    assert res.X is None and res.F is None
    res = minimize(problem, EOSMA(pop_size=10, return_least_infeasible=True), ("n_gen", 5), seed=0)
    assert res.CV[0] == 1.0
