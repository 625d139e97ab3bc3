"""Chaotic PSO with arctangent coefficients (moik.algorithms.soo.cpso_at): kernels, runs."""

import numpy as np
import pytest

from moik.algorithms import get_algorithm
from moik.algorithms.soo.cpso_at import chaotic_local_search, logistic_sequence
from moik.exceptions import ParameterError


def test_cpso_chaotic_kernels():
    np.testing.assert_allclose(logistic_sequence(np.array([0.25]), 2), [[0.75], [0.75]])
    np.testing.assert_allclose(chaotic_local_search(np.array([1.0]), np.array([[0.75]]),
                                                    np.array([2.0])), [[2.0]])


def test_deterministic_in_bounds_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("cpso-at", pop_size=12),
                                    sphere(n_var=3), n_eval=600, seed=4, bound=100.0)


def test_sphere_10d_within_30k(check):
    check.solves_sphere(lambda: get_algorithm("cpso-at", pop_size=30), level=1e-6)


def test_classical_benchmark_f9(check):
    """F9 (Rastrigin, 10-D, 15,000 evaluations): CPSO-AT stops in a local basin."""
    check.classical_benchmark(lambda: get_algorithm("cpso-at", pop_size=30), "F9", level=30.0)


def test_spring_best_design_is_feasible(check):
    check.spring_feasible(lambda: get_algorithm("cpso-at", pop_size=30), n_eval=9_000)


def test_validation():
    with pytest.raises(ParameterError, match=r"w_min must be a number in \[0.0, 0.9\]"):
        get_algorithm("cpso-at", w_min=0.95)
