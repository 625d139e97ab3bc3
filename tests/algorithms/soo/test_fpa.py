"""Flower pollination (moik.algorithms.soo.fpa): Eqs. 1-3 on hand-computed arrays, runs."""

import numpy as np
import pytest

from moik.algorithms import FPA, get_algorithm
from moik.algorithms.mechanics import mantegna_sigma
from moik.algorithms.soo.fpa import pollinate
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_pollination_eqs_1_to_3():
    X, g = np.array([[1.0], [2.0], [4.0]]), np.array([0.0])
    # global?, u, v (Levy), eps, j, k offset
    rng = ScriptedRng([0.1, 0.9, 0.9], [[1.0], [1.0], [1.0]], [[1.0], [1.0], [1.0]],
                      [0.5, 0.5, 0.25], [1, 2, 0], [1, 1, 2])
    out = pollinate(X, g, p=0.2, beta=1.5, levy_scale=0.01, rng=rng)
    L = 0.01 * mantegna_sigma(1.5)
    # local: k = (j + offset) % 3, so (j, k) = (2, 0) and (0, 2)
    np.testing.assert_allclose(out, [[1.0 + L * 1.0], [2.0 + 0.5 * (4 - 1)],
                                     [4.0 + 0.25 * (1 - 4)]])


def test_deterministic_in_bounds_and_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("fpa", pop_size=20),
                                    sphere(n_var=7, bound=10.0), n_eval=1037, seed=11,
                                    bound=10.0, other_seed=12)


def test_evaluations_per_iteration_as_documented(check, sphere):
    assert check.n_eval_after(lambda: FPA(pop_size=10), sphere(n_var=5), ("n_gen", 4)) == 40


def test_sphere_10d_below_1e_6_within_30000_evaluations(check):
    """N=30: with N=50 FPA stops near 1e-3 at this budget."""
    check.solves_sphere(lambda: get_algorithm("fpa", pop_size=30), level=1e-6)


def test_constrained_feasibility_first(check):
    check.feasibility_first(lambda: get_algorithm("fpa", pop_size=20))


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("fpa", pop_size=30), ik.Q_GENERAL,
                                  ("n_eval", 3000), level=5.0)


@pytest.mark.parametrize(("params", "message"), [
    ({"p": -0.1}, r"p must be a number in \[0.0, 1.0\]"),
    ({"beta": 2.5}, r"beta must be a number in \(0.0, 2.0\]"),
    ({"levy_scale": 0}, r"levy_scale must be a number in \(0.0, inf\)"),
])
def test_bad_parameters_raise(params, message):
    with pytest.raises(ParameterError, match=message):
        FPA(**params)
