"""MO-CSA, one crow flock per objective (moik.algorithms.moo.mo_csa): the crow move, runs."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOCSA, get_algorithm
from moik.algorithms.moo.mo_csa import crow_move, inside_box
from moik.exceptions import ParameterError


def test_crow_move_follows_memory_or_flies_randomly():
    xl, xu = np.zeros(3), np.ones(3)
    X = np.full((4, 3), 0.2)
    M = np.full((4, 3), 0.6)
    new = crow_move(X, M, AP=0.0, fl=2.0, xl=xl, xu=xu, rng=np.random.default_rng(1))
    step = (new - X) / (M - X)  # one r * fl per crow, in [0, 2]
    assert np.allclose(step, step[:, :1]) and np.all((step >= 0) & (step <= 2))
    new = crow_move(X, M, AP=1.0, fl=2.0, xl=xl, xu=xu, rng=np.random.default_rng(1))
    assert inside_box(new, xl, xu).all() and not np.allclose(new, X + 0.0 * M)
    np.testing.assert_array_equal(inside_box(np.array([[0.0, 1.0, 0.5], [0.0, 1.1, 0.5]]),
                                             xl, xu), [True, False])


def test_defaults_and_bad_values():
    assert (MOCSA().AP, MOCSA().fl) == (0.1, 2.0)
    with pytest.raises(ParameterError, match=r"AP must be a number in \[0.0, 1.0\]"):
        MOCSA(AP=2)
    with pytest.raises(ParameterError, match="fl must be a number"):
        MOCSA(fl=0)


def test_csa_evaluates_only_positions_inside_the_box():
    res = minimize(get_problem("zdt1", n_var=5), MOCSA(pop_size=10), ("n_gen", 11), seed=0)
    a = res.algorithm
    assert 20 + 10 * 5 <= a.evaluator.n_eval <= 20 + 10 * 20  # fl = 2 overshoots sometimes
    assert inside_box(a.X, a.xl, a.xu).all()


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mo-csa", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1200, seed=7)


def test_zdt1_own_objective_end():
    """ZDT1 (30 variables), 6,000 evaluations, seed 0: MO-CSA's HV is 0.0; only the f1
    flock's end is checked."""
    res = minimize(get_problem("zdt1", n_var=30), get_algorithm("mo-csa"), ("n_eval", 6000),
                   seed=0)
    assert res.F[:, 0].min() < 1e-3
