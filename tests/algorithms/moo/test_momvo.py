"""Multi-objective multi-verse optimizer (moik.algorithms.moo.momvo): tunnels, runs, ZDT1."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOMVO, get_algorithm
from moik.algorithms.moo.momvo import mvo_roulette, mvo_schedule, tunnels
from moik.exceptions import ParameterError


def test_multiverse_tunnels_roulette_and_schedule():
    assert mvo_schedule(0, 10, 0.2, 1.0, 6) == (0.2, 1.0)
    wep, tdr = mvo_schedule(10, 10, 0.2, 1.0, 6)
    assert wep == pytest.approx(1.0) and tdr == pytest.approx(0.0)
    np.testing.assert_array_equal(mvo_roulette(np.array([1.0, 1.0, 2.0]),
                                               np.array([0.1, 0.3, 0.6, 0.99])), [0, 1, 2, 2])
    X_s = np.arange(8.0).reshape(4, 2)
    I_s = np.array([0.0, 1.0, 2.0, 3.0])
    rng = np.random.default_rng(0)
    np.testing.assert_array_equal(tunnels(X_s[1:], np.zeros(3), X_s, I_s, rng=rng), X_s[1:])
    out = tunnels(X_s[1:], np.ones(3), X_s, I_s, rng=rng)
    assert set(out[:, 0]) <= set(X_s[:, 0]) and set(out[:, 1]) <= set(X_s[:, 1])


def test_white_hole_is_the_best_universe_when_rates_are_non_negative():
    """MOMVO.m's roulette on -I: with I >= 0 the cumulative sums only fall, so every draw
    (u in [0, 1), including u = 0 and draws past the total) gives the first universe."""
    rng = np.random.default_rng(1)
    I_sorted = np.sort(rng.random(50) * 10.0)
    I_sorted[:3] = 0.0
    u = np.concatenate([[0.0, 1.0 - 1e-12], rng.random(1000)])
    np.testing.assert_array_equal(mvo_roulette(-I_sorted, u), 0)
    np.testing.assert_array_equal(mvo_roulette(-np.sort(rng.random(50)) - 1.0, u), 0)


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_deterministic_within_bounds_nondominated_exact_budget(check, problem_name):
    check.mo_reproducible_front(lambda: get_algorithm("momvo", pop_size=20),
                                check.mo_problem(problem_name), n_eval=1000, seed=3)


def test_evaluations_per_iteration_and_archive_default():
    alg = get_algorithm("momvo", pop_size=10)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 6), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 5 * 9
    assert alg.archive_size == 10


def test_zdt1_hypervolume_sanity_against_nsga2(check):
    """ZDT1 (10 variables), 5,000 evaluations, N = 50, seed 0: measured HV / NSGA2's HV
    0.921; the bound checks that MOMVO converges at all, not that it matches NSGA2."""
    hv = check.zdt1_hypervolume(lambda: get_algorithm("momvo", pop_size=50), n_var=10,
                                n_eval=5000)
    assert hv / check.nsga2_zdt1_hypervolume(n_var=10, n_eval=5000, pop_size=50) >= 0.85


def test_bad_parameters():
    with pytest.raises(ParameterError, match=r"wep_max must be a number in \[0.5, 1.0\]"):
        MOMVO(wep_min=0.5, wep_max=0.2)
    with pytest.raises(ParameterError, match=r"p must be a number in \(0.0, 100.0\]"):
        MOMVO(p=0)
