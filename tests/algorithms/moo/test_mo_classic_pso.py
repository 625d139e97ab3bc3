"""MO-PSO, classical PSO per objective (moik.algorithms.moo.mo_classic_pso): defaults, runs."""

import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOClassicPSO, get_algorithm
from moik.exceptions import ParameterError


def test_defaults_and_bad_values():
    assert (MOClassicPSO().w, MOClassicPSO().c1, MOClassicPSO().c2) == (0.8, 1.493, 1.493)
    with pytest.raises(ParameterError, match=r"c1 must be a number in \[0.0, 4.0\]"):
        MOClassicPSO(c1=5)


def test_evaluations_per_iteration(check):
    n_eval = check.n_eval_after(lambda: MOClassicPSO(pop_size=10), get_problem("zdt1", n_var=5),
                                ("n_gen", 2))
    assert n_eval == 20 + 20


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mo-pso", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1200, seed=7)


def test_zdt1_own_objective_end():
    """ZDT1 (30 variables), 6,000 evaluations, seed 0: the per-objective swarms cover
    little of the front (HV 0.075), so only the f1 swarm's end is checked."""
    res = minimize(get_problem("zdt1", n_var=30), get_algorithm("mo-pso"), ("n_eval", 6000),
                   seed=0)
    assert res.F[:, 0].min() < 1e-3  # the f1 swarm drives x1 to its bound
