"""Modified tree-seed algorithm (moik.algorithms.soo.mtsa): kernels by hand, runs."""

import numpy as np
import pytest

from moik.algorithms import get_algorithm
from moik.algorithms.soo.mtsa import best_seed_per_tree, sow_seeds, tournament_partners
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_tree_seed_kernels():
    partners = tournament_partners(np.array([0, 1]), np.array([5.0, 1.0, 3.0]),
                                   rng=ScriptedRng([[0, 1], [1, 1]]))
    np.testing.assert_array_equal(partners, [1, 2])  # owners are skipped; lower rank wins
    T = np.array([[0.0], [1.0], [4.0]])
    seed = sow_seeds(T, np.array([0]), np.array([2]), np.array([1.0]), ST=0.1,
                     rng=ScriptedRng([[0.5]], [[0.05]]))
    np.testing.assert_allclose(seed, [[0.5 * (1.0 - 4.0)]])  # Eq. 1 (toward the best)
    seed = sow_seeds(T, np.array([1]), np.array([2]), np.array([1.0]), ST=0.1,
                     rng=ScriptedRng([[0.5]], [[0.5]]))
    np.testing.assert_allclose(seed, [[1.0 + 0.5 * (1.0 - 4.0)]])  # Eq. 2
    np.testing.assert_array_equal(
        best_seed_per_tree(np.array([0, 0, 1]), np.array([3.0, 1.0, 2.0]), 2), [1, 2])


def test_deterministic_in_bounds_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("mtsa", pop_size=12), sphere(n_var=3),
                                    n_eval=600, seed=4, bound=100.0)


def test_sphere_10d_within_30k(check):
    check.solves_sphere(lambda: get_algorithm("mtsa", pop_size=30), level=1e-6)


def test_classical_benchmark_f1(check):
    check.classical_benchmark(lambda: get_algorithm("mtsa", pop_size=30), "F1", level=1e-6)


def test_spring_best_design_is_feasible(check):
    check.spring_feasible(lambda: get_algorithm("mtsa", pop_size=30), n_eval=9_000)


def test_validation():
    with pytest.raises(ParameterError, match="s_max must be an integer >= 1"):
        get_algorithm("mtsa", s_max=0)
