"""MOMPA (moik.algorithms.moo.mompa): reference-point selection, the Gaussian search,
defaults, runs, ZDT1 against NSGA2."""

import numpy as np
import pytest
from pymoo.problems import get_problem

from moik.algorithms import MOMPA, get_algorithm
from moik.algorithms.moo.mompa import front_numbers, gaussian_search, reference_point_selection
from moik.algorithms.moo.reference_directions import default_ref_dirs
from moik.exceptions import ParameterError


def test_front_numbers_rank_feasible_fronts_then_violations():
    F = np.array([[0.0, 1.0], [1.0, 0.0], [1.0, 1.0], [2.0, 2.0], [0.0, 0.0]])
    np.testing.assert_array_equal(front_numbers(F, None, 5), [1, 1, 2, 3, 0])
    np.testing.assert_array_equal(front_numbers(F, None, 1), [-1, -1, -1, -1, 0])
    CV = np.array([0.0, 0.0, 0.0, 0.5, 0.2])
    np.testing.assert_array_equal(front_numbers(F, CV, 5), [0, 0, 1, 3, 2])


def test_reference_point_selection_keeps_one_point_per_direction():
    Z = default_ref_dirs(2, 5)  # (0, 1), (0.25, 0.75), ..., (1, 0)
    f = np.linspace(0.0, 1.0, 21)
    F = np.column_stack([f, 1.0 - f])  # one front, 21 points, 5 to keep
    keep = reference_point_selection(F, None, 5, Z, F.min(axis=0), rng=np.random.default_rng(0))
    np.testing.assert_array_equal(keep, [0, 5, 10, 15, 20])  # the points on the directions


def test_gaussian_search_moves_one_coordinate_per_row_within_bounds():
    X = np.full((50, 4), 0.5)
    Y = gaussian_search(X, np.zeros(4), np.ones(4), rng=np.random.default_rng(1))
    assert np.all((Y != X).sum(axis=1) <= 1) and (Y != X).any()
    assert np.all((Y >= 0.0) & (Y <= 1.0))


def test_table_defaults_and_bad_values():
    assert (MOMPA().P, MOMPA().FADs) == (0.5, 0.2)
    with pytest.raises(ParameterError, match=r"P must be a number in \(0.0, 2.0\]"):
        MOMPA(P=0)


def test_evaluations_per_iteration_and_population_of_reference_points(check):
    n_eval = check.n_eval_after(lambda: MOMPA(pop_size=10), get_problem("zdt1", n_var=5),
                                ("n_gen", 2))
    assert n_eval == 10 + 30  # phase move, FADs and Gaussian search: 3N
    n_eval = check.n_eval_after(lambda: MOMPA(pop_size=100), get_problem("dtlz2"),
                                ("n_gen", 1))
    assert n_eval == 91  # 3 objectives: the 91 Das-Dennis points of 12 divisions


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mompa", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1200, seed=7)


def test_zdt1_hypervolume_against_nsga2_same_budget(check):
    """ZDT1 (30 variables), 6,000 evaluations, seed 0: NSGA2 0.741, MOMPA 0.490."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("mompa"), n_var=30, n_eval=6000)
    assert hv >= 0.5 * check.nsga2_zdt1_hypervolume(n_var=30, n_eval=6000, pop_size=100)
