"""The generation driver both array-state bases share (moik.algorithms.array_state):
strict keywords, sizes, the schedule from the termination, the evaluation budget."""

import numpy as np
import pytest
from pymoo.core.evaluator import Evaluator
from pymoo.core.population import Population
from pymoo.core.problem import Problem
from pymoo.core.variable import Integer, Real
from pymoo.operators.sampling.rnd import FloatRandomSampling
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.termination import get_termination
from pymoo.termination.default import DefaultSingleObjectiveTermination

from moik.algorithms import EOSMA, MOEOSMA, PSO, available, entry, get_algorithm
from moik.algorithms.array_state import (
    PYMOO_OPTIONS,
    budget_left,
    check_sizes,
    constructor_keywords,
    find_limit,
    planned_iterations,
    refuse_unknown_keywords,
)
from moik.exceptions import ParameterError, ShapeError

MOIK = [name for name in available() if entry(name).cls.__module__.startswith("moik.")]


def test_pymoo_options_are_those_of_algorithm_init():
    assert {"termination", "output", "display", "callback", "archive",
                             "return_least_infeasible", "save_history", "verbose", "seed",
                             "evaluator"} == PYMOO_OPTIONS


def test_constructor_keywords_follow_the_mro():
    names = constructor_keywords(EOSMA)
    assert {"pop_size", "X0", "max_iter", "q", "z", "a1"} <= names and names >= PYMOO_OPTIONS
    assert {"archive_size", "pop_size"} <= constructor_keywords(MOEOSMA)
    refuse_unknown_keywords(EOSMA, {"seed": 1, "verbose": False})


def test_misspelled_keyword_is_refused_naming_the_right_one():
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) pop_sise for EOSMA; "
                                             r"accepted: .*\bpop_size\b"):
        EOSMA(pop_sise=50)


@pytest.mark.parametrize("name", MOIK)
def test_every_moik_algorithm_refuses_an_unknown_keyword(name):
    cls = entry(name).cls
    with pytest.raises(ParameterError, match=rf"unknown parameter\(s\) pop_sise for "
                                             rf"{cls.__name__}; accepted: .*\bpop_size\b"):
        cls(pop_sise=50)


@pytest.mark.parametrize("name", MOIK)
def test_every_moik_algorithm_takes_pymoo_options(name):
    """pymoo's options pass through ``minimize`` (to ``setup``) and through the constructor."""
    cls = entry(name).cls
    multi = entry(name).kind == "multi-objective"
    problem = get_problem("zdt1", n_var=5) if multi else get_problem("sphere", n_var=5)
    res = minimize(problem, cls(), ("n_gen", 3), seed=1, verbose=False, save_history=True)
    assert len(res.history) == 3 and res.algorithm.seed == 1
    again = minimize(problem, cls(seed=1, verbose=False, save_history=True), ("n_gen", 3))
    np.testing.assert_array_equal(again.F, res.F)


def test_sizes_are_integers_under_moiks_rule():
    assert check_sizes(np.int64(5), 2, None) == (5, None)
    assert check_sizes(5, 2, np.int32(7)) == (5, 7)
    for bad in (True, 5.0, "5"):
        with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
            check_sizes(bad, 2, None)
    for bad in (0, 2.0, True):
        with pytest.raises(ParameterError, match="max_iter must be a positive integer or None"):
            check_sizes(5, 2, bad)


def test_schedule_length_and_limits_from_the_termination():
    assert find_limit(get_termination("n_gen", 7), "n_max_gen") == 7
    assert find_limit(get_termination("n_eval", 500), "n_max_gen") == np.inf
    assert find_limit(DefaultSingleObjectiveTermination(n_max_gen=40), "n_max_gen") == 40
    plan = {"t": 1, "n_eval": 10, "elapsed": 0.0, "per_iteration": 20.0}
    assert planned_iterations(get_termination("n_gen", 7), plans={}, **plan) == 6
    assert planned_iterations(get_termination("n_eval", 2010), plans={}, **plan) == 100
    assert planned_iterations(get_termination("time", 1.0), plans={}, **plan) == np.inf


def test_budget_left_cuts_the_last_batch():
    assert budget_left(np.inf, 100, 30) == 30
    assert budget_left(120, 100, 30) == 20
    assert budget_left(100, 100, 30) == 0


def _sphere4():
    return get_problem("sphere", n_var=4)


@pytest.mark.parametrize("name", ["pso", "eo", "mosma"])
def test_pymoo_sampling_forms_are_accepted(name):
    problem = get_problem("zdt1", n_var=4) if name == "mosma" else _sphere4()
    res = minimize(problem, get_algorithm(name, pop_size=10, sampling=FloatRandomSampling()),
                   ("n_gen", 1), seed=1)
    assert res.algorithm.X.shape == (10, 4)
    X = np.full((3, 4), 0.25)
    res = minimize(problem, get_algorithm(name, pop_size=10, sampling=X), ("n_gen", 1), seed=1)
    np.testing.assert_array_equal(res.algorithm.X[:3], X)  # as X0: the first rows
    same = minimize(problem, get_algorithm(name, pop_size=10, X0=X), ("n_gen", 1), seed=1)
    np.testing.assert_array_equal(res.F, same.F)
    pop = Population.new("X", X)
    Evaluator().eval(problem, pop)
    res = minimize(problem, get_algorithm(name, pop_size=10, sampling=pop), ("n_gen", 1),
                   seed=1)
    assert res.algorithm.evaluator.n_eval == 7  # the evaluated individuals are not re-evaluated
    np.testing.assert_array_equal(res.algorithm.X[:3], X)


def test_bad_sampling_is_a_clear_error():
    with pytest.raises(ParameterError, match="X0 or as sampling, not both"):
        PSO(X0=np.zeros((1, 4)), sampling=np.zeros((1, 4)))
    with pytest.raises(ParameterError, match="sampling must be a pymoo Sampling"):
        minimize(_sphere4(), PSO(sampling="lhs"), ("n_gen", 2))
    with pytest.raises(ShapeError, match=r"sampling must have shape \(k, 4\) with k >= 1"):
        minimize(_sphere4(), PSO(pop_size=5, sampling=np.zeros((6, 3))), ("n_gen", 2))
    with pytest.raises(ShapeError, match=r"sampling must have shape \(k, 4\) with k >= 1"):
        minimize(_sphere4(), PSO(pop_size=5, sampling=np.zeros((0, 4))), ("n_gen", 2))


def test_a_mixed_variable_problem_is_a_clear_error():
    class Mixed(Problem):
        def __init__(self):
            super().__init__(vars={"a": Real(bounds=(0, 1)), "b": Integer(bounds=(0, 5))},
                             n_obj=1)

        def _evaluate(self, X, out, *args, **kwargs):
            out["F"] = np.zeros(len(X))

    with pytest.raises(ParameterError, match="PSO works on real-valued vectors; the problem "
                                             "has mixed variables"):
        minimize(Mixed(), PSO(), ("n_gen", 2))
