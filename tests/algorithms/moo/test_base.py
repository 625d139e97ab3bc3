"""MOArrayAlgorithm: the pymoo contract with array state and an external archive."""

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOEOSMA, MOMPSO
from moik.algorithms.archive import nondominated_mask
from moik.algorithms.moo.base import dominates, pareto_memory
from moik.exceptions import NonFiniteValuesWarning, ParameterError, ShapeError
from moik.metrics import closest_to_utopia, compromise


class Schaffer(Problem):
    """Two objectives x^2 and (x - 2)^2 on [-5, 5]^2 (first coordinate only)."""

    def __init__(self, n_ieq_constr=0, nan=False):
        super().__init__(n_var=2, n_obj=2, n_ieq_constr=n_ieq_constr, xl=-5.0, xu=5.0)
        self.nan = nan

    def _evaluate(self, X, out, *args, **kwargs):
        F = np.column_stack([X[:, 0] ** 2, (X[:, 0] - 2.0) ** 2])
        if self.nan:
            F[0, 0] = np.nan
        out["F"] = F
        if self.n_ieq_constr:
            out["G"] = X[:, :1]


def test_dominates_and_pareto_memory_on_tiny_arrays():
    A = np.array([[0.0, 1.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]])
    B = np.array([[1.0, 1.0], [1.0, 1.0], [0.0, 2.0], [1.0, 1.0]])
    np.testing.assert_array_equal(dominates(A, B), [True, False, False, False])
    PX, X = np.zeros((4, 3)), np.ones((4, 3))
    # memory A, new B: only row 0 keeps the memory (A_0 dominates B_0); equal and incomparable
    # new points replace it
    MX, MF = pareto_memory(X, B, PX, A)
    np.testing.assert_array_equal(MX[:, 0], [0.0, 1.0, 1.0, 1.0])
    np.testing.assert_array_equal(MF, np.vstack([A[0], B[1:]]))
    # an inf row (left unevaluated by the budget) never enters the memory
    MX, MF = pareto_memory(X, np.full((4, 2), np.inf), PX, A)
    np.testing.assert_array_equal(MF, A)


@pytest.mark.parametrize("cls", [MOEOSMA, MOMPSO])
def test_exact_n_eval_budget_and_result_is_the_archive(cls):
    res = minimize(get_problem("zdt1", n_var=5), cls(pop_size=10), ("n_eval", 1005), seed=1)
    alg = res.algorithm
    assert alg.evaluator.n_eval == 1005
    np.testing.assert_array_equal(res.F, alg.pareto_archive.F)
    np.testing.assert_array_equal(res.X, alg.pareto_archive.X)
    assert len(res.F) <= 10 and nondominated_mask(res.F).all()
    np.testing.assert_array_equal(res.opt.get("F"), res.F)
    assert res.pop.get("F").shape[1] == 2


@pytest.mark.parametrize("cls", [MOEOSMA, MOMPSO])
def test_ask_tell_gives_the_same_run_as_minimize(cls):
    problem = get_problem("zdt2", n_var=4)
    ref = minimize(problem, cls(pop_size=8), ("n_eval", 500), seed=4)
    alg = cls(pop_size=8)
    alg.setup(problem, termination=("n_eval", 500), seed=4)
    while alg.has_next():
        pop = alg.ask()
        alg.evaluator.eval(problem, pop)
        alg.tell(infills=pop)
    res = alg.result()
    assert alg.evaluator.n_eval == 500
    np.testing.assert_array_equal(res.F, ref.F)
    np.testing.assert_array_equal(res.X, ref.X)


def test_n_gen_time_verbose_and_callback(capsys):
    seen = []
    res = minimize(Schaffer(), MOEOSMA(pop_size=10), ("n_gen", 5), seed=0, verbose=True,
                   callback=lambda a: seen.append((a.t, len(a.pareto_archive), a.X.shape)))
    out = capsys.readouterr().out
    # pymoo's MultiObjectiveOutput: no known front here, so eps/indicator
    assert "n_nds" in out and "eps" in out and "indicator" in out
    assert [s[0] for s in seen] == [0, 1, 2, 3, 4] and res.algorithm.max_iter == 4
    assert all(s[2] == (10, 2) for s in seen)
    res = minimize(Schaffer(), MOEOSMA(pop_size=10), ("time", 0.2), seed=0)
    assert res.algorithm.n_gen > 2 and np.all(res.F[:, 0] < 5.0)


def test_front_of_a_known_problem_and_compromise():
    res = minimize(Schaffer(), MOEOSMA(pop_size=20), ("n_gen", 60), seed=2)
    x0 = res.X[:, 0]
    assert np.all((x0 > -0.05) & (x0 < 2.05))  # Pareto set: 0 <= x <= 2
    x, f = compromise(res)
    np.testing.assert_array_equal(f, res.F[closest_to_utopia(res.F)])
    assert abs(x[0] - 1.0) < 0.2


def test_bad_problems_and_parameters():
    with pytest.raises(ParameterError, match="multi-objective; the problem has n_obj=1"):
        minimize(get_problem("sphere"), MOEOSMA(), ("n_gen", 2))
    res = minimize(Schaffer(n_ieq_constr=1), MOEOSMA(pop_size=10), ("n_gen", 5), seed=0)
    assert np.all(res.X[:, 0] <= 0.0) and np.all(res.CV == 0.0)  # G = x0 <= 0: feasible only
    with pytest.warns(NonFiniteValuesWarning, match="Schaffer returned NaN"):  # a row, not a run
        res = minimize(Schaffer(nan=True), MOEOSMA(pop_size=5), ("n_gen", 2))
    assert np.isfinite(res.F).all()
    with pytest.raises(ParameterError, match="archive_size must be an integer >= 1"):
        MOEOSMA(archive_size=0)
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 3"):
        MOEOSMA(pop_size=2)
    with pytest.raises(ParameterError, match="max_iter must be a positive integer"):
        MOEOSMA(max_iter=0)
    with pytest.raises(ShapeError, match=r"X0 must have shape \(k, 2\) with k >= 1"):
        minimize(Schaffer(), MOEOSMA(pop_size=5, X0=np.zeros((6, 3))), ("n_gen", 2))
    res = minimize(Schaffer(), MOEOSMA(pop_size=5, X0=np.zeros((6, 2))), ("n_gen", 1))
    assert res.algorithm.evaluator.n_eval == 6  # more rows than pop_size: all evaluated
    with pytest.raises(ParameterError, match="outside the problem bounds"):
        minimize(Schaffer(), MOEOSMA(pop_size=5, X0=np.full((1, 2), 9.0)), ("n_gen", 2))


def test_x0_rows_are_used_and_archive_size_is_honoured():
    X0 = np.array([[1.0, 0.0], [0.5, 0.5]])
    alg = MOEOSMA(pop_size=6, archive_size=4, X0=X0)
    res = minimize(Schaffer(), alg, ("n_gen", 1), seed=0)
    np.testing.assert_array_equal(res.algorithm.pbest_X[:2], X0)
    res = minimize(Schaffer(), MOEOSMA(pop_size=6, archive_size=4), ("n_gen", 20), seed=0)
    assert len(res.F) == 4


def test_verbose_prints_pymoos_multi_objective_columns(capsys):
    minimize(get_problem("zdt1", n_var=5), MOEOSMA(pop_size=10), ("n_gen", 3), seed=0,
             verbose=True)
    header = capsys.readouterr().out.splitlines()[1]
    assert [c.strip() for c in header.split("|")] == ["n_gen", "n_eval", "n_nds", "igd", "gd",
                                                      "hv"]
    minimize(Schaffer(n_ieq_constr=1), MOEOSMA(pop_size=10), ("n_gen", 3), seed=0, verbose=True)
    assert "cv_min" in capsys.readouterr().out


# ask/tell rounds one generation takes (docs/algorithms.md, "Ask/tell rounds per generation")
ROUNDS = {"moeosma": (2, 2), "mo-m-pso": (2, 2), "mopso": (1, 2), "mosma": (1, 1),
          "mompa": (1, 1), "mogwo": (1, 1), "moalo": (1, 1), "moda": (1, 1), "momvo": (1, 1),
          "mssa": (1, 1), "mo-pso": (1, 1), "mo-jaya": (1, 1), "mo-csa": (1, 1),
          "moead": (10, 10)}  # one offspring per round: N = 10 directions


@pytest.mark.parametrize("name", sorted(ROUNDS))
def test_ask_tell_rounds_per_generation_are_the_documented_ones(name):
    from moik.algorithms import get_algorithm

    problem = get_problem("zdt1", n_var=5)
    alg = get_algorithm(name, pop_size=10)
    alg.setup(problem, termination=("n_gen", 12), seed=0)
    rounds = {}
    while alg.has_next():
        gen = alg.n_gen
        pop = alg.ask()
        alg.evaluator.eval(problem, pop)
        alg.tell(infills=pop)
        rounds[gen] = rounds.get(gen, 0) + 1
    counts = [rounds[g] for g in sorted(k for k in rounds if k is not None) if g > 1]
    lo, hi = ROUNDS[name]
    assert all(lo <= c <= hi for c in counts) and lo in counts and hi in counts
