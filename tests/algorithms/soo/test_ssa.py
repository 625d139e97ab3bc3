"""Salp swarm (moik.algorithms.soo.ssa): leader and followers by hand, runs."""

import math

import numpy as np
import pytest

from moik.algorithms import SSA, get_algorithm
from moik.algorithms.soo.ssa import salp_update, ssa_c1
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_salp_leader_and_followers():
    assert ssa_c1(0, 3) == 2.0 * math.exp(-1.0)  # l = 1 of L = 4
    assert ssa_c1(3, 3) == 2.0 * math.exp(-16.0)  # the last iteration: l = L
    X = np.array([[0.0], [4.0], [8.0]])
    out = salp_update(X, np.array([1.0]), 0.5, 1, np.array([-2.0]), np.array([2.0]),
                      rng=ScriptedRng([[0.75]], [[0.7]]))
    np.testing.assert_allclose(out, [[1.5], [2.75], [5.375]])  # Eqs. 3.1, 3.4


def test_deterministic_in_bounds_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("ssa", pop_size=12), sphere(n_var=3),
                                    n_eval=600, seed=4, bound=100.0)


@pytest.mark.parametrize(("params", "level"), [
    ({"n_leaders": 15}, 1e-6),
    # One leader (the paper): the food source moves only through the single leader,
    # so after 30,000 evaluations SSA is at ~5e-6 (seed 1).
    ({}, 1e-4),
])
def test_sphere_10d_within_30k(check, params, level):
    check.solves_sphere(lambda: get_algorithm("ssa", pop_size=30, **params), level=level)


def test_spring_best_design_is_feasible(check):
    check.spring_feasible(lambda: get_algorithm("ssa", pop_size=30), n_eval=9_000)


def test_validation():
    with pytest.raises(ParameterError, match="n_leaders must be an integer"):
        SSA(pop_size=10, n_leaders=10)
