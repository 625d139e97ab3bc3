"""Firefly algorithm (moik.algorithms.soo.fa): Eqs. 1-2 by hand, runs, an honest level."""

import math

import numpy as np
import pytest
from pymoo.optimize import minimize

from moik.algorithms import FA, get_algorithm
from moik.algorithms.soo.fa import firefly_move
from moik.exceptions import ParameterError


def test_firefly_moves_toward_brighter_only():
    X = np.array([[0.0], [1.0]])
    out = firefly_move(X, np.array([1.0, 0.0]), alpha=0.0, beta0=2.0, gamma=1.0,
                       scale=np.array([2.0]), rng=np.random.default_rng(0))
    np.testing.assert_allclose(out, [[2.0 * math.exp(-1.0)], [1.0]])  # Eqs. 1-2


def test_deterministic_in_bounds_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("fa", pop_size=12), sphere(n_var=3),
                                    n_eval=600, seed=4, bound=100.0)


def test_fa_sphere_honest_level(sphere):
    """gamma = 1 removes the attraction beyond a few units and alpha = 0.2 of the box
    stays constant, so FA only random-walks on [-100, 100]^10 (docstring): it improves
    on the initial swarm but stays above 100 (about 4e3 after 30,000 evaluations)."""
    res = minimize(sphere(), FA(pop_size=30), ("n_eval", 6_000), seed=1)
    conv = res.algorithm.convergence
    assert 100.0 < res.F[0] < conv[0]


def test_validation():
    with pytest.raises(ParameterError, match=r"gamma must be a number"):
        FA(gamma=-1)


def test_yangs_settings_converge_on_pymoos_sphere():
    """With the settings of Yang's own code (beta0 = 1, alpha damped by 0.97 per iteration)
    FA converges on pymoo's 10-D sphere (its quality test wants 1e-5; measured 1e-28 on
    seeds 0-2 with the default termination, 8e-8 after 200 generations here); at the I-BES
    paper's settings (beta0 = 2, constant alpha) it stalls near 1e-2 (0.031 after 200):
    beta0 = 2 jumps past the brighter firefly and the constant alpha keeps the random steps
    at 0.2 of the box (a known failure of tests/algorithms/test_pymoo_contract.py)."""
    from pymoo.problems import get_problem

    problem = get_problem("sphere")
    res = minimize(problem, get_algorithm("fa", beta0=1.0, theta=0.97), ("n_gen", 200), seed=1)
    assert res.F[0] < 1e-5
    assert minimize(problem, get_algorithm("fa"), ("n_gen", 200), seed=1).F[0] > 1e-5
