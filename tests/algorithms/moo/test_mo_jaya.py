"""MO-JAYA, one JAYA population per objective (moik.algorithms.moo.mo_jaya): defaults, runs."""

import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOJAYA, get_algorithm
from moik.exceptions import ParameterError


def test_defaults_and_bad_values():
    assert MOJAYA(pop_size=7).archive_size == 7
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        MOJAYA(pop_size=1)


def test_evaluations_per_iteration(check):
    n_eval = check.n_eval_after(lambda: MOJAYA(pop_size=10), get_problem("zdt1", n_var=5),
                                ("n_gen", 2))
    assert n_eval == 20 + 20


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mo-jaya", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1200, seed=7)


def test_zdt1_own_objective_end():
    """ZDT1 (30 variables), 6,000 evaluations, seed 0: MO-JAYA's HV is 0.375; only the f1
    population's end is checked."""
    res = minimize(get_problem("zdt1", n_var=30), get_algorithm("mo-jaya"), ("n_eval", 6000),
                   seed=0)
    assert res.F[:, 0].min() < 1e-3
