"""Compromise picks (moik.metrics.compromise): the member closest to the utopia point."""

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOEOSMA
from moik.exceptions import ShapeError
from moik.metrics import closest_to_utopia, compromise, normalized_front


def test_closest_to_utopia_scales_each_objective_over_the_front():
    F = np.array([[0.0, 100.0], [0.4, 30.0], [1.0, 0.0]])
    np.testing.assert_allclose(normalized_front(F), [[0.0, 1.0], [0.4, 0.3], [1.0, 0.0]])
    assert closest_to_utopia(F) == 1
    assert closest_to_utopia(F, normalize=False) == 2


def test_compromise_of_a_result_and_of_its_algorithm_agree():
    res = minimize(get_problem("zdt1", n_var=5), MOEOSMA(pop_size=20), ("n_gen", 20), seed=0)
    x, f = compromise(res)
    i = closest_to_utopia(res.F)
    np.testing.assert_array_equal(x, res.X[i])
    np.testing.assert_array_equal(f, res.F[i])
    x2, f2 = compromise(res.algorithm)
    np.testing.assert_array_equal(x2, x)
    np.testing.assert_array_equal(f2, f)
    f[0] = -1.0  # copies: the archive is untouched
    assert res.algorithm.pareto_archive.F.min() >= 0.0


def test_compromise_of_pymoos_own_algorithms():
    res = minimize(get_problem("zdt1", n_var=5), NSGA2(pop_size=20), ("n_gen", 10), seed=0)
    x, f = compromise(res)
    np.testing.assert_array_equal(f, res.F[closest_to_utopia(res.F)])
    np.testing.assert_array_equal(compromise(res.algorithm)[1], f)


def test_no_front_before_a_run():
    with pytest.raises(ShapeError, match="no archive yet"):
        compromise(MOEOSMA())
