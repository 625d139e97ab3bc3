"""Self-adaptive spherical search (moik.algorithms.soo.sass): kernels, the shrinking population."""

import numpy as np
import pytest
from pymoo.optimize import minimize

from moik.algorithms import SASS, get_algorithm
from moik.algorithms.soo.sass import pair_rotation, planned_size, spherical_step
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_sass_kernels():
    A = pair_rotation(5, 1e-12, rng=np.random.default_rng(0))
    np.testing.assert_allclose(A @ A.T, np.eye(5), atol=1e-12)
    Z = np.array([[1.0, 2.0], [3.0, 4.0]])
    rng = ScriptedRng(np.full((2, 2), 0.9), [1, 0])  # rd = 0: only the forced coordinate
    step = spherical_step(Z, np.eye(2), np.array([0.5, 1.0]), np.zeros(2), rng=rng)
    np.testing.assert_allclose(step, [[0.0, 1.0], [3.0, 0.0]])
    assert planned_size(0, 1000, 126) == 126 and planned_size(1000, 1000, 126) == 4
    assert planned_size(500, 1000, 126) == 65


def test_deterministic_in_bounds_and_budget(check, sphere):
    check.reproducible_exact_budget(lambda: SASS(pop_size=20), sphere(n_var=5, bound=10.0),
                                    n_eval=1037, seed=4, bound=10.0, other_seed=5)


def test_sphere_10d_below_1e_6_within_30k_evaluations(check):
    """Measured with the Table 3 defaults: about 1e-26."""
    check.solves_sphere(SASS, level=1e-6)


def test_runs_on_position_ik(check, ik):
    """200 iterations, 18 D agents."""
    check.improves_on_position_ik(lambda: get_algorithm("sass"), ik.Q_45, ("n_gen", 200),
                                  level=20.0)


def test_sass_population_shrinks_to_four(sphere):
    algo = SASS()
    res = minimize(sphere(n_var=3), algo, ("n_eval", 3000), seed=0)
    assert res.algorithm.pop_size == 54 and len(res.algorithm.X) == 4
    assert res.algorithm.evaluator.n_eval == 3000
    algo = minimize(sphere(n_var=3), SASS(), ("n_gen", 200), seed=0).algorithm
    assert len(algo.convergence) == 200 and len(algo.X) <= 6  # the schedule ends near 4 at T
    assert len(algo.archive_X) <= round(1.4 * len(algo.X))


@pytest.mark.parametrize(("params", "message"), [
    ({"Ms": 0}, r"Ms must be an integer >= 1"),
    ({"c": 0}, r"c must be a number in \(0.0, 1.0\]"),
])
def test_bad_values_raise(params, message):
    with pytest.raises(ParameterError, match=message):
        get_algorithm("sass", **params)
