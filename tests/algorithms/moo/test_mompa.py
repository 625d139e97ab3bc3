"""MOMPA (moik.algorithms.moo.mompa): the top predator, defaults, runs, ZDT1 against NSGA2."""

import numpy as np
import pytest
from pymoo.problems import get_problem

from moik.algorithms import MOMPA, get_algorithm
from moik.algorithms.archive import CrowdingArchive
from moik.algorithms.moo.mompa import top_predator
from moik.exceptions import ParameterError


def test_top_predator_is_an_archive_member():
    A = CrowdingArchive.mirjalili(10)
    F = np.array([[0.0, 1.0], [0.5, 0.5], [1.0, 0.0]])
    A.add(F, F, rng=np.random.default_rng(0))
    assert any(np.array_equal(top_predator(A, rng=np.random.default_rng(1)), f) for f in F)


def test_table_defaults_and_bad_values():
    assert (MOMPA().P, MOMPA().FADs) == (0.5, 0.2)
    with pytest.raises(ParameterError, match=r"P must be a number in \(0.0, 2.0\]"):
        MOMPA(P=0)


def test_evaluations_per_iteration(check):
    n_eval = check.n_eval_after(lambda: MOMPA(pop_size=10), get_problem("zdt1", n_var=5),
                                ("n_gen", 2))
    assert n_eval == 10 + 20


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mompa", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1200, seed=7)


def test_zdt1_hypervolume_against_nsga2_same_budget(check):
    """ZDT1 (30 variables), 6,000 evaluations, seed 0: NSGA2 0.741, MOMPA 0.490."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("mompa"), n_var=30, n_eval=6000)
    assert hv >= 0.5 * check.nsga2_zdt1_hypervolume(n_var=30, n_eval=6000, pop_size=100)
