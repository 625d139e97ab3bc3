"""Improved grey wolf optimizer (moik.algorithms.soo.igwo): GWO move, dimension learning, runs."""

import numpy as np
import pytest

from moik.algorithms import IGWO, get_algorithm
from moik.algorithms.soo.igwo import dimension_learning, gwo_move
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_gwo_move_mean_of_leaders():
    X, leaders = np.array([[0.0]]), [np.array([1.0]), np.array([2.0]), np.array([3.0])]
    half = np.full((1, 1), 0.5)  # A = 2 a 0.5 - a = 0, C = 1
    out = gwo_move(X, leaders, 1.0, rng=ScriptedRng(*[half] * 6))
    np.testing.assert_allclose(out, [[2.0]])


def test_gwo_move_with_a_zero_lands_on_the_leaders_mean():
    X = np.zeros((4, 2))
    L = (np.ones(2), 2 * np.ones(2), 3 * np.ones(2))
    np.testing.assert_allclose(gwo_move(X, L, 0.0, rng=np.random.default_rng(0)), 2.0)


def test_dimension_learning_eqs_10_12():
    X = np.array([[0.0, 0.0], [1.0, 0.0], [5.0, 5.0]])
    X_gwo = np.array([[1.5, 0.0], [1.0, 0.1], [5.0, 5.0]])
    # wolf 0: radius 1.5 -> neighbours {0, 1}; wolf 1: radius 0.1 -> {1}; wolf 2: radius 0 -> {2}
    rng = ScriptedRng([[0.9, 0.1], [0.0, 0.0], [0.0, 0.0]], [2, 0, 1], np.full((3, 2), 0.5))
    out = dimension_learning(X, X_gwo, rng=rng)
    # wolf 0, d0: neighbour 1 (x=1), X_r = wolf 2 (5): 0 + 0.5 (1 - 5) = -2
    # wolf 0, d1: neighbour 0 (0), X_r = wolf 2 (5): 0 + 0.5 (0 - 5) = -2.5
    np.testing.assert_allclose(out[0], [-2.0, -2.5])
    np.testing.assert_allclose(out[1], [1.0 + 0.5 * (1.0 - 0.0), 0.0])
    np.testing.assert_allclose(out[2], [5.0 + 0.5 * (5.0 - 1.0), 5.0 + 0.5 * 5.0])


def test_deterministic_in_bounds_and_budget(check, sphere):
    check.reproducible_exact_budget(lambda: IGWO(pop_size=20), sphere(n_var=5, bound=10.0),
                                    n_eval=1037, seed=4, bound=10.0, other_seed=5)


def test_sphere_10d_below_1e_6_within_30k_evaluations(check):
    """Measured with the Table 3 defaults: about 1e-48."""
    check.solves_sphere(IGWO, level=1e-6)


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("igwo"), ik.Q_45, ("n_gen", 200),
                                  level=20.0)


def test_evaluations_per_iteration(check, sphere):
    assert check.n_eval_after(lambda: IGWO(pop_size=10), sphere(), ("n_gen", 4)) == 10 + 3 * 20


def test_bad_values_raise():
    with pytest.raises(ParameterError, match=r"pop_size must be an integer >= 3"):
        get_algorithm("igwo", pop_size=2)
