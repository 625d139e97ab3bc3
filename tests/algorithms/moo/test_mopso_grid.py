"""MOPSO with an adaptive grid (moik.algorithms.moo.mopso_grid): mutation, acceptance,
defaults, runs, ZDT1 against NSGA2."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOPSO, get_algorithm
from moik.algorithms.archive import GridArchive
from moik.algorithms.moo.mopso_grid import (
    mopso_mutation,
    mutation_rate,
    pareto_accept,
    reflect_velocity,
)
from moik.exceptions import ParameterError


def test_mopso_mutation_schedule_and_operator():
    assert mutation_rate(1, 100, 0.1) == 1.0 and mutation_rate(100, 100, 0.1) == 0.0
    assert mutation_rate(51, 101, 0.5) == pytest.approx(0.25)
    assert mutation_rate(1, 1, 0.1) == 1.0
    xl, xu = np.zeros(4), np.full(4, 2.0)
    X = np.full((50, 4), 1.0)
    Xm = mopso_mutation(X, 0.1, xl, xu, rng=np.random.default_rng(0))
    changed = Xm != X
    assert np.all(changed.sum(axis=1) == 1)
    assert np.all(np.abs(Xm - X) <= 0.1 * 2.0)


def test_pareto_accept_and_velocity_reflection():
    old = np.array([[1.0, 1.0]] * 3)
    new = np.array([[0.5, 1.0], [2.0, 1.0], [0.5, 2.0]])
    takes = np.array([pareto_accept(new, old, rng=np.random.default_rng(s)) for s in range(40)])
    assert takes[:, 0].all() and not takes[:, 1].any() and 0 < takes[:, 2].sum() < 40
    X, V = reflect_velocity(np.array([[0.9, 0.5]]), np.array([[0.3, -0.1]]), np.zeros(2),
                            np.ones(2))
    np.testing.assert_allclose(X, [[1.0, 0.4]])
    np.testing.assert_allclose(V, [[-0.3, -0.1]])


def test_table_defaults_archive_and_bad_values():
    p = MOPSO()
    assert (p.pop_size, p.archive_size, p.w, p.wdamp, p.c1, p.c2, p.mu) == (
        100, 100, 0.5, 0.99, 1.0, 2.0, 0.1)
    prob = get_problem("zdt1", n_var=4)
    assert isinstance(minimize(prob, MOPSO(pop_size=6), ("n_gen", 2), seed=0)
                      .algorithm.pareto_archive, GridArchive)
    with pytest.raises(ParameterError, match=r"mu must be a number in \(0.0, 1.0\]"):
        MOPSO(mu=0)
    with pytest.raises(ParameterError, match="wdamp must be a number"):
        MOPSO(wdamp=1.5)


def test_evaluations_per_iteration(check):
    """pm = 1 in the first iteration, so every particle is mutated once."""
    n_eval = check.n_eval_after(lambda: MOPSO(pop_size=10), get_problem("zdt1", n_var=5),
                                ("n_gen", 2))
    assert n_eval == 10 + 20


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mopso", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1200, seed=7)


def test_zdt1_hypervolume_against_nsga2_same_budget(check):
    """ZDT1 (30 variables), 6,100 evaluations (N = 100 and 60 iterations of N), seed 0:
    NSGA2 0.749, MOPSO 0.413 (its
    schedule, inferred from the budget, is short here; at 25,000 evaluations see the
    report)."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("mopso"), n_var=30, n_eval=6100)
    assert hv >= 0.4 * check.nsga2_zdt1_hypervolume(n_var=30, n_eval=6100, pop_size=100)
