"""Multi-objective ant lion optimizer (moik.algorithms.moo.moalo): walks, runs, ZDT1."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import get_algorithm
from moik.algorithms.moo.moalo import shrink_ratio, walk_around, walk_at


def test_antlion_walks_shrink_and_stay_in_the_trap():
    assert shrink_ratio(5, 100) == 1.0
    assert shrink_ratio(20, 100) == pytest.approx(1 + 100 * 0.2)
    assert shrink_ratio(96, 100) == pytest.approx(1 + 1e6 * 0.96)
    rng = np.random.default_rng(1)
    u = walk_at(200, 50, 1, rng=rng)  # step 0 of a walk that starts at 0
    assert np.all((u >= 0) & (u <= 1)) and np.ptp(u) > 0
    centres = np.full((50, 3), 0.5)
    xl, xu = -np.ones(3), np.ones(3)
    R = walk_around(centres, 99, 100, xl, xu, rng=rng)  # I = 1 + 1e5 * 0.99
    assert np.all(np.abs(R - 0.5) <= 1.0 / (1 + 1e5 * 0.99) + 1e-15)


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_deterministic_within_bounds_nondominated_exact_budget(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("moalo", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1000, seed=3)


def test_evaluations_per_iteration_and_archive_default():
    alg = get_algorithm("moalo", pop_size=10)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 6), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 5 * 10
    assert alg.archive_size == 10


def test_zdt1_hypervolume_sanity_against_nsga2(check):
    """ZDT1 (10 variables), 5,000 evaluations, N = 50, seed 0: measured HV / NSGA2's HV
    0.878; the bound checks that MOALO converges at all, not that it matches NSGA2."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("moalo", pop_size=50), n_var=10,
                                n_eval=5000)
    assert hv / check.nsga2_zdt1_hypervolume(n_var=10, n_eval=5000, pop_size=50) >= 0.8


def test_antlion_rule_of_malo_m_walks_around_the_first_member(monkeypatch):
    import moik.algorithms.moo.moalo as moalo
    from moik.algorithms import MOALO
    from moik.exceptions import UnknownNameError

    centres, first = [], []
    walk = moalo.walk_around

    def spy(c, *args, **kwargs):
        centres.append(np.array(c))
        return walk(c, *args, **kwargs)

    monkeypatch.setattr(moalo, "walk_around", spy)
    alg = MOALO(pop_size=8, antlion="first")
    alg.setup(get_problem("zdt1", n_var=4), termination=("n_gen", 4), seed=1)
    while alg.has_next():
        if alg.is_initialized:
            first.append(alg.pareto_archive.X[0].copy())
        alg.next()
    assert len(first) == 3 and len(centres) == 6  # antlions, then the elite, per iteration
    for x0, antlions in zip(first, centres[::2], strict=True):
        np.testing.assert_array_equal(antlions, np.repeat(x0[None], 8, axis=0))
    with pytest.raises(UnknownNameError, match="antlion"):
        MOALO(antlion="nearest")
