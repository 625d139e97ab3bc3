"""MOSMA (moik.algorithms.moo.mosma): the elitist order, defaults, runs, ZDT1 against NSGA2."""

import numpy as np
import pytest
from pymoo.problems import get_problem

from moik.algorithms import MOSMA, get_algorithm
from moik.algorithms.moo.mosma import elitist_order
from moik.exceptions import ParameterError


def test_elitist_order_by_rank_then_crowding():
    F = np.array([[1.0, 1.0], [0.0, 1.0], [0.5, 0.5], [2.0, 2.0], [1.0, 0.0]])
    keep, rank = elitist_order(F, 4)
    assert set(keep[:3]) == {1, 2, 4} and keep[2] == 2 and keep[3] == 0  # ends first (cd = inf)
    np.testing.assert_array_equal(rank, [0, 0, 0, 1])


def test_table_defaults_and_bad_values():
    assert MOSMA().z == 0.03
    with pytest.raises(ParameterError, match=r"z must be a number in \[0.0, 1.0\]"):
        MOSMA(z=-1)


def test_evaluations_per_iteration(check):
    n_eval = check.n_eval_after(lambda: MOSMA(pop_size=10), get_problem("zdt1", n_var=5),
                                ("n_gen", 2))
    assert n_eval == 10 + 10


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mosma", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1200, seed=7)


def test_zdt1_hypervolume_against_nsga2_same_budget(check):
    """ZDT1 (30 variables), 6,000 evaluations, seed 0: NSGA2 0.741, MOSMA 0.865."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("mosma"), n_var=30, n_eval=6000)
    assert hv >= 0.95 * check.nsga2_zdt1_hypervolume(n_var=30, n_eval=6000, pop_size=100)
