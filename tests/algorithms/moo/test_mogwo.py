"""Multi-objective grey wolf optimizer (moik.algorithms.moo.mogwo): leaders, the grid, runs."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOGWO, get_algorithm
from moik.algorithms.archive import GridArchive
from moik.algorithms.moo.mogwo import distinct_grid_leaders


@pytest.mark.parametrize("m", [1, 2, 3, 6])
def test_grey_wolf_leaders_are_distinct_when_the_archive_allows(m):
    archive = GridArchive.mogwo(10)
    t = np.linspace(0.0, 1.0, m)
    archive.add(np.c_[t, t], np.c_[t, 1.0 - t], rng=np.random.default_rng(0))
    idx = distinct_grid_leaders(archive, 500, rng=np.random.default_rng(1))
    assert idx.shape == (500, 3) and idx.min() >= 0 and idx.max() < m
    if m >= 2:
        assert np.all(idx[:, 0] != idx[:, 1])
    if m >= 3:
        assert all(len(set(row)) == 3 for row in idx.tolist())


def test_mogwo_uses_the_table4_grid_with_power_pressures():
    res = minimize(get_problem("zdt1", n_var=5), MOGWO(pop_size=10), ("n_gen", 3), seed=0)
    A = res.algorithm.pareto_archive
    assert (A.n_grid, A.inflation, A.beta, A.gamma, A.pressure) == (10, 0.1, 4.0, 2.0, "power")
    np.testing.assert_allclose(A.leader_weights(np.array([1, 2])), [1.0, 2.0**-4])


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_deterministic_within_bounds_nondominated_exact_budget(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("mogwo", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1000, seed=3)


def test_evaluations_per_iteration_and_archive_default():
    alg = get_algorithm("mogwo", pop_size=10)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 6), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 5 * 10
    assert alg.archive_size == 10


def test_zdt1_hypervolume_sanity_against_nsga2(check):
    """ZDT1 (10 variables), 5,050 evaluations (N = 50 and 100 iterations of N), seed 0:
    measured HV / NSGA2's HV 0.944; the bound checks that MOGWO converges at all, not
    that it matches NSGA2."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("mogwo", pop_size=50), n_var=10,
                                n_eval=5050)
    assert hv / check.nsga2_zdt1_hypervolume(n_var=10, n_eval=5050, pop_size=50) >= 0.9
