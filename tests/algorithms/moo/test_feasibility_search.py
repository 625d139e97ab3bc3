"""The feasibility search of the multi-objective algorithms (moo.feasibility_search):
DE/rand/1/bin by hand, its selection, when it starts and stops, and every registered
multi-objective algorithm reaching a feasible region that random sampling misses."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

import moik.algorithms.moo.base as mo_base
import moik.algorithms.moo.mopso_cd as mopso_cd
from moik.algorithms import available, get_algorithm
from moik.algorithms.moo.feasibility_search import FeasibilitySearch, de_trials, start_search

MO_NAMES = available("multi-objective")


def test_de_trial_is_a_difference_of_three_other_rows():
    """Eq. (1) with distinct r1, r2, r3 != i: in one dimension the trial is always the
    mutant (j_rand), so it is x_r1 + 0.5 (x_r2 - x_r3) over the other three rows."""
    X = np.array([[0.0], [1.0], [10.0], [100.0]])
    lo, hi = np.array([-1e3]), np.array([1e3])
    for seed in range(20):
        U = de_trials(X, lo, hi, np.random.default_rng(seed))
        for i in range(4):
            others = [X[j, 0] for j in range(4) if j != i]
            allowed = {a + 0.5 * (b - c) for a, b, c in itertools.permutations(others)}
            assert U[i, 0] in allowed


def test_de_trial_past_a_bound_goes_midway_to_it():
    X = np.array([[0.9], [0.0], [1.0], [0.95]])
    lo, hi = np.zeros(1), np.ones(1)
    rng = np.random.default_rng(3)
    U = de_trials(X, lo, hi, rng, scale=10.0)  # every mutant leaves [0, 1] or lands exactly
    for i in range(4):
        assert U[i, 0] in (0.5 * (X[i, 0] + 0.0), 0.5 * (X[i, 0] + 1.0)) or 0 <= U[i, 0] <= 1


@given(st.integers(4, 12), st.integers(1, 6), st.integers(0, 2**32 - 1))
def test_de_trials_stay_in_the_bounds_and_keep_a_mutant_component(n, d, seed):
    rng = np.random.default_rng(seed)
    lo, hi = -rng.random(d), rng.random(d) + 0.1
    X = lo + rng.random((n, d)) * (hi - lo)
    trials = de_trials(X, lo, hi, rng)
    assert trials.shape == X.shape
    assert np.all(trials >= lo)
    assert np.all(trials <= hi)
    assert np.all(np.any(trials != X, axis=1))  # j_rand: one component from the mutant


def test_select_keeps_the_trial_unless_its_violation_is_larger():
    search = FeasibilitySearch(np.zeros((4, 2)), np.array([1.0, 1.0, 1.0, 1.0]))
    U = np.ones((4, 2))
    search.select(U, np.array([0.5, 1.0, 2.0, np.inf]))  # better, tie, worse, unevaluated
    np.testing.assert_array_equal(search.CV, [0.5, 1.0, 1.0, 1.0])
    np.testing.assert_array_equal(search.X[:, 0], [1.0, 1.0, 0.0, 0.0])
    assert search.n_eval == 3


def test_start_only_for_a_constrained_start_with_nothing_feasible():
    X = np.zeros((5, 2))
    assert start_search(X, None, 5) is None  # unconstrained
    assert start_search(X, np.array([1.0, 1.0, 0.0, 1.0, 1.0]), 5) is None  # one feasible
    assert start_search(X, np.ones(5), 3) is None  # DE/rand/1 needs 4 rows
    search = start_search(X, np.ones(5), 4)
    assert search is not None and len(search.X) == 4


class SmallBall(Problem):
    """ZDT1's objectives on 10 variables with the feasible region a ball of radius 0.1
    around x_1..x_9 = 0.9 (a share of about 3e-9 of the box: the initial population and
    plain sampling never hit it; the front is ZDT1's with g = 1 + 9 * 0.9)."""

    def __init__(self) -> None:
        super().__init__(n_var=10, n_obj=2, n_ieq_constr=1, xl=0.0, xu=1.0)

    def _evaluate(self, X, out, *args, **kwargs):
        g = 1 + 9 * X[:, 1:].mean(axis=1)
        out["F"] = np.column_stack([X[:, 0], g * (1 - np.sqrt(X[:, 0] / g))])
        out["G"] = (np.sum((X[:, 1:] - 0.9) ** 2, axis=1) - 0.01)[:, None]


@pytest.mark.parametrize("name", MO_NAMES)
def test_every_algorithm_reaches_a_feasible_region_random_sampling_misses(name):
    problem = SmallBall()
    sample = np.random.default_rng(0).random((10_000, 10))
    assert np.all(problem.evaluate(sample, return_values_of=["G"]) > 0)
    res = minimize(problem, get_algorithm(name, pop_size=40), ("n_evals", 8000), seed=1)
    assert res.X is not None, f"{name} returned nothing feasible"
    G = problem.evaluate(np.atleast_2d(res.X), return_values_of=["G"])
    assert np.all(G <= 0)


def test_the_search_is_what_reaches_it():
    """Without the search (start_search replaced) a method that converges slowly misses
    the ball in the same budget, so the test above measures the search."""
    original = mo_base.start_search
    mo_base.start_search = lambda *args: None
    try:
        res = minimize(SmallBall(), get_algorithm("mo-pso", pop_size=40), ("n_evals", 8000),
                       seed=1)
    finally:
        mo_base.start_search = original
    assert res.X is None


def _run(name, problem, **kwargs):
    return minimize(problem, get_algorithm(name, pop_size=20), ("n_evals", 2000), seed=5,
                    **kwargs)


@pytest.mark.parametrize("name", ["mogwo", "mo-m-pso", "mopso-cd"])
def test_a_run_that_starts_feasible_never_starts_it(name, monkeypatch):
    problem = get_problem("bnh")  # about 90 % of the box is feasible
    plain = _run(name, problem)
    monkeypatch.setattr(mo_base, "start_search", lambda *args: None)
    monkeypatch.setattr(mopso_cd, "start_search", lambda *args: None)
    off = _run(name, problem)
    np.testing.assert_array_equal(plain.F, off.F)


@pytest.mark.parametrize("name", ["mogwo", "moeosma", "mo-jaya"])
def test_ask_tell_equals_minimize_while_it_runs(name):
    problem = SmallBall()
    res = _run(name, problem)
    algorithm = get_algorithm(name, pop_size=20)
    algorithm.setup(problem, termination=("n_evals", 2000), seed=5)
    while algorithm.has_next():
        pop = algorithm.ask()
        algorithm.evaluator.eval(problem, pop)
        algorithm.tell(infills=pop)
    assert algorithm.evaluator.n_eval == res.algorithm.evaluator.n_eval == 2000
    opt = algorithm.result().opt
    np.testing.assert_array_equal(opt.get("X"), res.opt.get("X"))
