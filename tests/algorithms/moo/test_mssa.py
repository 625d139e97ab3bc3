"""Multi-objective salp swarm (moik.algorithms.moo.mssa): the salp chain, runs, ZDT1."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import get_algorithm
from moik.algorithms.moo.mssa import salp_chain, ssa_c1
from moik.exceptions import ParameterError


def test_salp_chain_leaders_around_food_and_followers_average_predecessor():
    rng = np.random.default_rng(0)
    X = np.array([[0.0, 0.0], [1.0, 1.0], [0.2, 0.4], [0.6, 0.8]])
    xl, xu = np.zeros(2), np.ones(2)
    out = salp_chain(X, np.array([0.5, 0.5]), 0.0, xl, xu, rng=rng)  # c1 = 0: leaders on food
    np.testing.assert_allclose(out[:2], 0.5)
    np.testing.assert_allclose(out[2], (X[2] + out[1]) / 2)  # Eq. 3.4 with the moved predecessor
    np.testing.assert_allclose(out[3], (X[3] + out[2]) / 2)
    out = salp_chain(X, np.array([0.5, 0.5]), 0.3, xl, xu, rng=rng)
    assert np.all(np.abs(out[:2] - 0.5) <= 0.3 + 1e-12)
    assert ssa_c1(0, 10) == 2.0 and ssa_c1(10, 10) == pytest.approx(2 * np.exp(-16))


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_deterministic_within_bounds_nondominated_exact_budget(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mssa", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1000, seed=3)


def test_evaluations_per_iteration_and_archive_default():
    alg = get_algorithm("mssa", pop_size=10)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 6), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 5 * 10
    assert alg.archive_size == 10


def test_zdt1_hypervolume_sanity_against_nsga2(check):
    """ZDT1 (10 variables), 5,000 evaluations, N = 50, seed 0: measured HV / NSGA2's HV
    0.821; the bound checks that MSSA converges at all, not that it matches NSGA2."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("mssa", pop_size=50), n_var=10,
                                n_eval=5000)
    assert hv / check.nsga2_zdt1_hypervolume(n_var=10, n_eval=5000, pop_size=50) >= 0.75


def test_bad_parameters():
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        get_algorithm("mssa", pop_size=1)
