"""Multi-trial vector DE (moik.algorithms.soo.mtde): schedules, the split, the matrix, runs."""

import numpy as np
import pytest

from moik.algorithms import MTDE, get_algorithm
from moik.algorithms.soo.mtde import (
    lehmer_mean,
    mtde_schedules,
    split_population,
    transformation_matrix,
)
from moik.exceptions import ParameterError


def test_mtde_schedules_split_matrix_lehmer():
    assert mtde_schedules(0, 100, 0.001, 2.0, 1.0) == (2.0, 2.0)
    ca1, ca2 = mtde_schedules(50, 100, 0.001, 2.0, 2.0)  # Eqs. 9, 11
    assert ca1 == 1.0 and ca2 == pytest.approx(0.001 - (0.001 - 2.0) * 0.25)
    groups = split_population(10, 2, rng=np.random.default_rng(0))
    assert [len(g) for g in groups] == [2, 2, 6]
    assert sorted(np.concatenate(groups)) == list(range(10))
    M = transformation_matrix(7, 3, rng=np.random.default_rng(0))
    assert sorted(M.sum(axis=1)) == [1, 1, 1, 2, 2, 3, 3]
    assert lehmer_mean(np.array([0.5, 1.0]), np.array([1.0, 1.0])) == pytest.approx(1.25 / 1.5)


def test_deterministic_in_bounds_and_budget(check, sphere):
    check.reproducible_exact_budget(lambda: MTDE(pop_size=20), sphere(n_var=5, bound=10.0),
                                    n_eval=1037, seed=4, bound=10.0, other_seed=5)


def test_sphere_10d_below_1e_6_within_30k_evaluations(check):
    """Measured with the Table 3 defaults: about 1e-16."""
    check.solves_sphere(MTDE, level=1e-6)


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("mtde"), ik.Q_45, ("n_gen", 200),
                                  level=20.0)


def test_evaluations_per_iteration(check, sphere):
    assert check.n_eval_after(lambda: MTDE(pop_size=10), sphere(), ("n_gen", 4)) == 40


@pytest.mark.parametrize(("params", "message"), [
    ({"WinIter": 0}, r"WinIter must be an integer >= 1"),
    ({"pr": 0}, r"pr must be a number in \(0.0, 1.0\]"),
])
def test_bad_values_raise(params, message):
    with pytest.raises(ParameterError, match=message):
        get_algorithm("mtde", **params)
