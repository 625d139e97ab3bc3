"""Gradient-based optimizer (moik.algorithms.soo.gbo): schedule, GSR, a fixed point, runs."""

import math

import numpy as np
import pytest

from moik.algorithms import GBO, get_algorithm
from moik.algorithms.soo.gbo import gbo_alpha, gbo_update, gradient_search_rule
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_gbo_schedule_gsr_and_fixed_point():
    beta = 1.2  # Eq. 14 at t = 0
    alpha = abs(beta * math.sin(1.5 * math.pi + math.sin(1.5 * math.pi * beta)))
    assert gbo_alpha(0, 10) == pytest.approx(alpha)
    X, xr1, xm = np.array([[1.0]]), np.array([[0.0]]), np.array([[1.0]])
    best, worst = np.array([2.0]), np.array([0.0])
    # delta rand, dx rand, randn, yp rands, yq rands, randn
    rng = ScriptedRng([[0.5]], [[1.0]], [[1.0]], [[1.0]], [[1.0]], [[1.0]], [[1.0]], [[1.0]])
    out = gradient_search_rule(X, xr1, xm, best, worst, X, np.zeros((1, 1)), 1.0, 0.0, rng=rng)
    # dx = |(2 - 0) + 0| / 2 = 1; GSR1 = 2*1*1/2 = 1; xs = 0; yp - yq = 2 dx = 2 -> GSR = 1
    np.testing.assert_allclose(out, [[1.0]])
    same = np.full((6, 2), 0.5)  # a collapsed population is a fixed point without LEO
    out = gbo_update(same, same[0], same[0], 0.7, pr=0.0, xl=np.zeros(2), xu=np.ones(2),
                     rng=np.random.default_rng(0))
    np.testing.assert_allclose(out, same, atol=1e-15)


def test_deterministic_in_bounds_and_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("gbo", pop_size=20),
                                    sphere(n_var=7, bound=10.0), n_eval=1037, seed=11,
                                    bound=10.0, other_seed=12)


def test_evaluations_per_iteration_as_documented(check, sphere):
    assert check.n_eval_after(lambda: GBO(pop_size=10), sphere(n_var=5), ("n_gen", 4)) == 40


def test_sphere_10d_below_1e_6_within_30000_evaluations(check):
    check.solves_sphere(lambda: get_algorithm("gbo", pop_size=30), level=1e-6)


def test_constrained_feasibility_first(check):
    check.feasibility_first(lambda: get_algorithm("gbo", pop_size=20))


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("gbo", pop_size=30), ik.Q_GENERAL,
                                  ("n_eval", 3000), level=5.0)


@pytest.mark.parametrize(("params", "message"), [
    ({"pr": 2}, r"pr must be a number in \[0.0, 1.0\]"),
    ({"pop_size": 4}, r"pop_size must be an integer >= 5"),
])
def test_bad_parameters_raise(params, message):
    with pytest.raises(ParameterError, match=message):
        GBO(**params)
