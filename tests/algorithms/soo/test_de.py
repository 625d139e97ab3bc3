"""DE/rand/1/bin (moik.algorithms.soo.de): Eqs. 1-3 on hand-computed arrays, runs, validation."""

import numpy as np
import pytest

from moik.algorithms import DE, get_algorithm
from moik.algorithms.soo.de import binomial_crossover, distinct_partners, rand_1_mutation
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_de_rand_1_bin_eqs_1_to_3():
    X = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 5.0], [4.0, 4.0]])
    R = np.array([[1, 2, 3], [0, 2, 3], [3, 0, 1], [2, 1, 0]])
    V = rand_1_mutation(X, R, 0.5)
    np.testing.assert_allclose(V[0], [1.0 + 0.5 * (3 - 4), 2.0 + 0.5 * (5 - 4)])
    rng = ScriptedRng([[0.95, 0.95], [0.1, 0.95], [0.95, 0.95], [0.95, 0.95]], [1, 0, 0, 0])
    U = binomial_crossover(X, V, 0.9, rng=rng)
    np.testing.assert_array_equal(U[0], [X[0, 0], V[0, 1]])  # only j = rnbr(i) = 1
    np.testing.assert_array_equal(U[1], [V[1, 0], X[1, 1]])  # randb <= CR and rnbr at j=0
    np.testing.assert_array_equal(U[2], [V[2, 0], X[2, 1]])
    P = distinct_partners(6, 3, rng=np.random.default_rng(0))
    assert all(len(set(row)) == 3 and i not in row for i, row in enumerate(P))


def test_deterministic_in_bounds_and_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("de", pop_size=20),
                                    sphere(n_var=7, bound=10.0), n_eval=1037, seed=11,
                                    bound=10.0, other_seed=12)


def test_evaluations_per_iteration_as_documented(check, sphere):
    assert check.n_eval_after(lambda: DE(pop_size=10), sphere(n_var=5), ("n_gen", 4)) == 10 + 3 * 10


def test_sphere_10d_below_1e_6_within_30000_evaluations(check):
    check.solves_sphere(lambda: get_algorithm("de", pop_size=30), level=1e-6)


def test_constrained_feasibility_first(check):
    check.feasibility_first(lambda: get_algorithm("de", pop_size=20))


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("de", pop_size=30), ik.Q_GENERAL,
                                  ("n_eval", 3000), level=5.0)  # cm; ~50 at start


@pytest.mark.parametrize(("params", "message"), [
    ({"F": 0}, r"F must be a number in \(0.0, 2.0\]"),
    ({"CR": 1.5}, r"CR must be a number in \[0.0, 1.0\]"),
    ({"pop_size": 3}, r"pop_size must be an integer >= 4"),
])
def test_bad_parameters_raise(params, message):
    with pytest.raises(ParameterError, match=message):
        DE(**params)
