"""Centroid opposition-based DE (moik.algorithms.soo.code): opposites, DE/rand/1/bin, runs."""

import numpy as np
import pytest

from moik.algorithms import CODE, get_algorithm
from moik.algorithms.soo.code import centroid_opposite, de_rand_1_bin, distinct_indices
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_centroid_opposite_and_resampling():
    X = np.array([[0.0], [2.0], [10.0]])  # M = 4: opposites 8, 6, -2
    out = centroid_opposite(X, np.array([0.0]), np.array([7.0]), rng=ScriptedRng(
        np.full((3, 1), 0.5)))
    # 8 > b = 7 -> 4 + 0.5 (7 - 4); -2 < a = 0 -> 0 + 0.5 (4 - 0)
    np.testing.assert_allclose(out, [[5.5], [6.0], [2.0]])


def test_distinct_indices_and_de_rand_1_bin():
    rng = np.random.default_rng(0)
    r = distinct_indices(6, 3, rng=rng)
    assert np.all(r != np.arange(6)) and np.all(r[0] != r[1]) and np.all(r[2] != r[1])
    X = np.arange(8.0).reshape(4, 2)
    U = de_rand_1_bin(X, F=0.5, Cr=1.0, xl=np.full(2, -100.0), xu=np.full(2, 100.0),
                      rng=np.random.default_rng(1))
    assert U.shape == X.shape and np.all(np.abs(U) <= 100.0)


def test_deterministic_in_bounds_and_budget(check, sphere):
    check.reproducible_exact_budget(lambda: CODE(pop_size=20), sphere(n_var=5, bound=10.0),
                                    n_eval=1037, seed=4, bound=10.0, other_seed=5)


def test_sphere_10d_below_1e_6_within_30k_evaluations(check):
    """Measured with the Table 3 defaults: about 1e-38."""
    check.solves_sphere(CODE, level=1e-6)


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("code"), ik.Q_45, ("n_gen", 200),
                                  level=20.0)


def test_evaluations_per_iteration(check, sphere):
    n_eval = check.n_eval_after(lambda: CODE(pop_size=10, Jr=0.0), sphere(), ("n_gen", 4))
    assert n_eval == 40  # 10 initial + 10 opposite + 2 x 10
    n_eval = check.n_eval_after(lambda: CODE(pop_size=10, Jr=1.0), sphere(), ("n_gen", 4))
    assert n_eval == 10 + 10 + 2 * 20


@pytest.mark.parametrize(("params", "message"), [
    ({"Jr": 1.5}, r"Jr must be a number in \[0.0, 1.0\]"),
    ({"pop_size": 3}, r"pop_size must be an integer >= 4"),
])
def test_bad_values_raise(params, message):
    with pytest.raises(ParameterError, match=message):
        get_algorithm("code", **params)
