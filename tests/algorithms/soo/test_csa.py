"""Crow search (moik.algorithms.soo.csa): Eq. 3 and the feasibility rule by hand, runs."""

import numpy as np
import pytest

from moik.algorithms import CSA, get_algorithm
from moik.algorithms.soo.csa import crow_flight
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_crow_flight_eq3_and_feasibility_rule():
    X, M = np.array([[0.0], [1.0]]), np.array([[2.0], [-1.0]])
    xl, xu = np.array([-1.5]), np.array([1.5])
    rng = ScriptedRng([1, 0], [0.5, 0.05], [[0.5], [0.5]], [[0.9], [0.5]])
    out = crow_flight(X, M, xl, xu, AP=0.1, fl=2.0, rng=rng)
    np.testing.assert_allclose(out, [[-1.0], [0.0]])  # follows crow 1; crow 1 relocates
    rng = ScriptedRng([1, 0], [0.5, 0.5], [[1.0], [1.0]], [[0.9], [0.5]])
    out = crow_flight(X, M, xl, xu, AP=0.1, fl=2.0, rng=rng)
    np.testing.assert_allclose(out, [[-2.0 + 2.0], [1.0]])  # crow 1 would leave: stays


def test_deterministic_in_bounds_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("csa", pop_size=12), sphere(n_var=3),
                                    n_eval=600, seed=4, bound=100.0)


def test_sphere_10d_within_30k(check):
    """10 % random relocations and fl = 2 overshooting keep CSA at ~6e-6 (seed 1)."""
    check.solves_sphere(lambda: get_algorithm("csa", pop_size=30), level=1e-4)


def test_spring_best_design_is_feasible(check):
    check.spring_feasible(lambda: get_algorithm("csa", pop_size=30), n_eval=9_000)


def test_validation():
    with pytest.raises(ParameterError, match=r"AP must be a number in \[0.0, 1.0\]"):
        CSA(AP=2)
