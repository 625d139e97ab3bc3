"""BES and I-BES (moik.algorithms.soo.bes; Zhao et al. 2024): kernels on tiny arrays, runs,
the I-BES IK case.

``ScriptedRng`` hands out queued numbers in the order a kernel draws them, so
each expected value is worked out by hand from the equations of bes.py.
"""

import math

import numpy as np
import pytest
from pymoo.optimize import minimize

import moik
from moik.algorithms import BES, get_algorithm
from moik.algorithms.soo.bes import (
    levy_sigma,
    levy_step,
    random_replacement,
    select_space,
    spiral_search,
    swoop,
)
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_levy_sigma_eq10_and_step_eq9():
    sigma = (math.gamma(2.5) * math.sin(0.75 * math.pi)
             / (math.gamma(1.25) * 1.5 * 2**0.25)) ** (1 / 1.5)
    assert levy_sigma(1.5) == pytest.approx(sigma, rel=1e-14)
    assert sigma == pytest.approx(0.696575, abs=1e-6)
    L = levy_step((1, 2), 1.5, rng=ScriptedRng([[1.0, -2.0]], [[0.125, -1.0]]))
    np.testing.assert_allclose(L, [[0.01 * sigma * 4.0, -0.02 * sigma]], rtol=1e-14)


def test_levy_step_statistics_symmetric_heavy_tailed():
    L = levy_step((200_000,), 1.5, rng=np.random.default_rng(0)) / (0.01 * levy_sigma(1.5))
    assert abs(np.mean(np.sign(L))) < 0.01  # symmetric
    assert np.median(np.abs(L)) == pytest.approx(0.91, abs=0.05)  # numerator/denominator law
    assert np.quantile(np.abs(L), 0.999) > 30.0  # a normal law would give 3.3


def test_eq13_random_replacement_only_out_of_limit_joints():
    X = np.array([[-4.0, 0.5, 4.0]])
    out = random_replacement(X, np.full(3, -1.0), np.ones(3),
                             rng=ScriptedRng([[0.25, 0.9, 0.5]]))
    np.testing.assert_array_equal(out, [[-0.5, 0.5, 0.0]])


def test_select_eq5_and_spiral_eq6():
    X = np.array([[1.0], [3.0]])
    out = select_space(X, np.array([2.0]), np.array([2.0]), alpha=1.8,
                       rng=ScriptedRng([[0.5], [0.25]]))
    np.testing.assert_allclose(out, [[2.0 + 0.9], [2.0 - 0.45]])
    X = np.array([[1.0], [3.0], [0.0]])
    # lambda = 8 * (pi/16, pi/8) = (pi/2, pi); r = lambda + 1.4 * 0
    out = spiral_search(X, np.array([2.0]), a=8.0, R=1.4,
                        rng=ScriptedRng([math.pi / 16, math.pi / 8], [0.0, 0.0]))
    # row 0: m1 = 1, n1 = ~0 -> 1 + (1 - 2); row 1: m1 = ~0, n1 = -1 -> 3 - (3 - 0)
    np.testing.assert_allclose(out, [[0.0], [0.0]], atol=1e-12)


def test_swoop_eq7():
    X, best, mean = np.array([[1.0], [2.0]]), np.array([1.0]), np.array([2.0])
    out = swoop(X, best, mean, a=8.0, c1=1.5, c2=1.5, rng=ScriptedRng([0.5, 2.0]))
    lam = np.array([4.0, 16.0])
    m2 = lam * np.sinh(lam) / (16 * np.sinh(16.0))
    n2 = lam * np.cosh(lam) / (16 * np.cosh(16.0))
    expected = np.array([0.5, 2.0]) + m2 * (X[:, 0] - 3.0) + n2 * (X[:, 0] - 1.5)
    np.testing.assert_allclose(out[:, 0], expected, rtol=1e-14)


@pytest.mark.parametrize(("cls", "per_iteration"), [(BES, 29), (BES.ibes, 30)])
def test_evaluations_per_iteration_and_exact_budget(sphere, cls, per_iteration):
    res = minimize(sphere(), cls(pop_size=10), ("n_gen", 5), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 4 * per_iteration
    res = minimize(sphere(), cls(pop_size=10), ("n_eval", 1000), seed=0)
    assert res.algorithm.evaluator.n_eval == 1000


@pytest.mark.parametrize("name", ["bes", "ibes"])
def test_deterministic_in_bounds_greedy(sphere, name):
    runs = [minimize(sphere(n_var=3), get_algorithm(name, pop_size=12), ("n_gen", 20), seed=5)
            for _ in range(2)]
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    alg = runs[0].algorithm
    assert np.all(np.abs(alg.X) <= 100.0)
    assert np.all(np.diff(alg.convergence) <= 0.0)


def test_presets_and_validation():
    assert (BES().levy, BES().bounds, BES.ibes().levy, BES.ibes().bounds) == (
        False, "clip", True, "random")
    assert BES.ibes(bounds="clip").bounds == "clip"
    built = get_algorithm("ibes", pop_size=20)
    assert type(built) is BES and (built.levy, built.bounds, built.pop_size) == (
        True, "random", 20)
    b = BES.ibes()
    assert (b.pop_size, b.c1, b.c2, b.R, b.alpha, b.a, b.beta) == (150, 1.5, 1.5, 1.4, 1.8,
                                                                     8.0, 1.5)
    with pytest.raises(ParameterError, match=r"alpha must be a number in \[1.5, 2.0\]"):
        BES(alpha=3)
    with pytest.raises(ParameterError, match="bounds must be one of clip, random"):
        BES.ibes(bounds="wrap")
    with pytest.raises(ParameterError, match="levy must be True or False"):
        BES(levy="yes")


@pytest.mark.parametrize("cls", [BES, BES.ibes])
def test_sphere_10d_below_1e_6_within_30k(check, cls):
    check.solves_sphere(lambda: cls(pop_size=30), level=1e-6)


@pytest.mark.parametrize(("name", "level"), [("F1", 1e-6), ("F9", 40.0)])
def test_ibes_on_classical_benchmarks(check, name, level):
    """F9 (Rastrigin, 10-D): the greedy phases settle in a local basin; over seeds 0-4
    I-BES reaches 6-35 with 15,000 evaluations (BES 0-22), so the level is 40."""
    check.classical_benchmark(lambda: BES.ibes(pop_size=30), name, level=level)


@pytest.mark.parametrize("cls", [BES, BES.ibes])
def test_spring_best_design_is_feasible(check, cls):
    res = check.spring_feasible(lambda: cls(pop_size=30), n_eval=15_000)
    assert res.F[0] < 0.0135  # best known 0.012665


def test_ibes_planar2_position_target_below_1e_12_m():
    problem = moik.problems.PositionIK(moik.robots.get_robot("planar2"), [0.35, 0.35, 0.0])
    res = minimize(problem, BES.ibes(pop_size=30), ("n_gen", 100), seed=0)
    assert res.F[0] < 1e-12
    assert np.all(np.abs(res.X) <= math.pi)


def test_levy_scale_reading_multiplies_the_eq9_step():
    assert BES.ibes().levy_scale == 0.01  # Eq. 9 as printed
    L = levy_step((1, 2), 1.5, rng=ScriptedRng([[1.0, -2.0]], [[0.125, -1.0]]), scale=1.0)
    np.testing.assert_allclose(L, [[levy_sigma(1.5) * 4.0, -2.0 * levy_sigma(1.5)]], rtol=1e-14)
    with pytest.raises(ParameterError, match="levy_scale must be a positive finite number"):
        BES.ibes(levy_scale=0.0)
