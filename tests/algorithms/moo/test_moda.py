"""Multi-objective dragonfly algorithm (moik.algorithms.moo.moda): the swarm step, runs, ZDT1."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MODA, get_algorithm
from moik.algorithms.moo.moda import dragonfly_step, swarm_weights
from moik.exceptions import ParameterError


def test_dragonfly_swarm_and_lone_levy_step():
    assert swarm_weights(0, 100, 0.9, 0.7) == (0.9, 0.1)
    assert swarm_weights(50, 100, 0.9, 0.7) == (pytest.approx(0.8), 0.0)
    X = np.array([[0.1, 0.1], [0.2, 0.3], [0.4, 0.2]])
    dX = np.zeros((3, 2))
    food, enemy = np.array([0.3, 0.3]), np.array([0.9, 0.9])
    r, vmax = np.full(2, 1.0), np.full(2, 10.0)
    new_X, new_dX = dragonfly_step(X, dX, food, enemy, r, 0.5, 0.1, 1.0, vmax,
                                   rng=np.random.default_rng(0))
    nb = X[[1, 2]]
    S = -(nb - X[0]).sum(axis=0)
    C = nb.mean(axis=0) - X[0]
    expected = 0.1 * S + 0.1 * C + 1.0 * (food - X[0]) + 0.1 * (enemy + X[0])  # Eq. 3.6, A = 0
    np.testing.assert_allclose(new_dX[0], expected)
    np.testing.assert_allclose(new_X[0], X[0] + expected)
    lone = np.array([[0.0, 0.0], [0.9, 0.9]])  # no neighbours, food far: Levy, dX = 0
    new_X, new_dX = dragonfly_step(lone, np.ones((2, 2)), np.array([0.5, 0.5]), enemy,
                                   np.full(2, 0.1), 0.5, 0.1, 1.0, vmax,
                                   rng=np.random.default_rng(0))
    np.testing.assert_array_equal(new_X[0], [0.0, 0.0])  # X + Levy * X with X = 0
    np.testing.assert_array_equal(new_dX, 0.0)


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_deterministic_within_bounds_nondominated_exact_budget(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("moda", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1000, seed=3)


def test_evaluations_per_iteration_and_archive_default():
    alg = get_algorithm("moda", pop_size=10)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 6), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 5 * 10
    assert alg.archive_size == 10


def test_zdt1_hypervolume_sanity_against_nsga2(check):
    """ZDT1 (10 variables), 5,050 evaluations (N = 50 and 100 iterations of N), seed 0:
    measured HV / NSGA2's HV 0.516; the bound checks that MODA converges at all, not that
    it matches NSGA2."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("moda", pop_size=50), n_var=10,
                                n_eval=5050)
    assert hv / check.nsga2_zdt1_hypervolume(n_var=10, n_eval=5050, pop_size=50) >= 0.45


def test_bad_parameters():
    with pytest.raises(ParameterError, match=r"w_end must be a number in \[0.0, 1.0\]"):
        MODA(w_end=1.5)
