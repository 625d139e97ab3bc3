"""Mirjalili's MO baselines of the EOSMA paper (Table 4): MSSA, MOALO, MODA, MOMVO, MOGWO."""

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MODA, MOGWO, MOMVO, get_algorithm
from moik.algorithms.archive import GridArchive, nondominated_mask
from moik.algorithms.moo.moalo import shrink_ratio, walk_around, walk_at
from moik.algorithms.moo.moda import dragonfly_step, swarm_weights
from moik.algorithms.moo.mogwo import distinct_grid_leaders
from moik.algorithms.moo.momvo import mvo_roulette, mvo_schedule, tunnels
from moik.algorithms.moo.mssa import salp_chain, ssa_c1
from moik.algorithms.soo.igwo import gwo_move
from moik.exceptions import ParameterError
from moik.metrics import hypervolume
from moik.problems import BiObjectiveIK, random_reachable_targets
from moik.robots import get_robot

NAMES = ["mssa", "moalo", "moda", "momvo", "mogwo"]


def ik_problem():
    robot = get_robot("eosma7")
    return BiObjectiveIK(robot, random_reachable_targets(robot, 1, seed=0)[0].pose)


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_deterministic_within_bounds_nondominated_exact_budget(name, problem_name):
    problem = ik_problem() if problem_name == "ik" else get_problem("zdt1", n_var=10)
    xl, xu = problem.bounds()
    runs = [minimize(problem, get_algorithm(name, pop_size=20), ("n_eval", 1000), seed=3)
            for _ in range(2)]
    np.testing.assert_array_equal(runs[0].F, runs[1].F)
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    res = runs[0]
    assert res.algorithm.evaluator.n_eval == 1000
    assert 1 <= len(res.F) <= 20 and res.F.shape[1] == 2
    assert np.array_equal(np.clip(res.X, xl, xu), res.X)
    assert nondominated_mask(res.F).all()


@pytest.mark.parametrize(("name", "per_iteration"),
                         [("mssa", 10), ("moalo", 10), ("moda", 10), ("momvo", 9), ("mogwo", 10)])
def test_evaluations_per_iteration_and_archive_default(name, per_iteration):
    alg = get_algorithm(name, pop_size=10)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 6), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 5 * per_iteration
    assert alg.archive_size == 10


def test_mogwo_uses_the_table4_grid_with_power_pressures():
    res = minimize(get_problem("zdt1", n_var=5), MOGWO(pop_size=10), ("n_gen", 3), seed=0)
    A = res.algorithm.pareto_archive
    assert (A.n_grid, A.inflation, A.beta, A.gamma, A.pressure) == (10, 0.1, 4.0, 2.0, "power")
    np.testing.assert_allclose(A.leader_weights(np.array([1, 2])), [1.0, 2.0**-4])
    with pytest.raises(ParameterError, match="pressure must be one of exp, power"):
        GridArchive(5, pressure="linear")


def test_bad_parameters():
    with pytest.raises(ParameterError, match=r"w_end must be a number in \[0.0, 1.0\]"):
        MODA(w_end=1.5)
    with pytest.raises(ParameterError, match=r"wep_max must be a number in \[0.5, 1.0\]"):
        MOMVO(wep_min=0.5, wep_max=0.2)
    with pytest.raises(ParameterError, match=r"p must be a number in \(0.0, 100.0\]"):
        MOMVO(p=0)
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        get_algorithm("mssa", pop_size=1)


def test_salp_chain_leaders_around_food_and_followers_average_predecessor():
    rng = np.random.default_rng(0)
    X = np.array([[0.0, 0.0], [1.0, 1.0], [0.2, 0.4], [0.6, 0.8]])
    xl, xu = np.zeros(2), np.ones(2)
    out = salp_chain(X, np.array([0.5, 0.5]), 0.0, xl, xu, rng=rng)  # c1 = 0: leaders on food
    np.testing.assert_allclose(out[:2], 0.5)
    np.testing.assert_allclose(out[2], (X[2] + out[1]) / 2)  # Eq. 3.4 with the moved predecessor
    np.testing.assert_allclose(out[3], (X[3] + out[2]) / 2)
    out = salp_chain(X, np.array([0.5, 0.5]), 0.3, xl, xu, rng=rng)
    assert np.all(np.abs(out[:2] - 0.5) <= 0.3 + 1e-12)
    assert ssa_c1(0, 10) == 2.0 and ssa_c1(10, 10) == pytest.approx(2 * np.exp(-16))


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


def test_dragonfly_swarm_and_lone_levy_step():
    assert swarm_weights(0, 100, 0.9, 0.7) == (0.9, 0.1)
    assert swarm_weights(50, 100, 0.9, 0.7) == (pytest.approx(0.8), 0.0)
    X = np.array([[0.1, 0.1], [0.2, 0.3], [0.4, 0.2]])
    dX = np.zeros((3, 2))
    food, enemy = np.array([0.3, 0.3]), np.array([0.9, 0.9])
    r, vmax = np.full(2, 1.0), np.full(2, 10.0)
    new_X, new_dX = dragonfly_step(X, dX, food, enemy, r, 0.5, 0.1, 1.0, vmax,
                                   rng=np.random.default_rng(0))
    nb = X[[1, 2]]
    S = -(nb - X[0]).sum(axis=0)
    C = nb.mean(axis=0) - X[0]
    expected = 0.1 * S + 0.1 * C + 1.0 * (food - X[0]) + 0.1 * (enemy + X[0])  # Eq. 3.6, A = 0
    np.testing.assert_allclose(new_dX[0], expected)
    np.testing.assert_allclose(new_X[0], X[0] + expected)
    lone = np.array([[0.0, 0.0], [0.9, 0.9]])  # no neighbours, food far: Levy, dX = 0
    new_X, new_dX = dragonfly_step(lone, np.ones((2, 2)), np.array([0.5, 0.5]), enemy,
                                   np.full(2, 0.1), 0.5, 0.1, 1.0, vmax,
                                   rng=np.random.default_rng(0))
    np.testing.assert_array_equal(new_X[0], [0.0, 0.0])  # X + Levy * X with X = 0
    np.testing.assert_array_equal(new_dX, 0.0)


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
    X = np.zeros((4, 2))
    L = (np.ones(2), 2 * np.ones(2), 3 * np.ones(2))
    np.testing.assert_allclose(gwo_move(X, L, 0.0, rng=np.random.default_rng(0)), 2.0)


def test_zdt1_hypervolume_sanity_against_nsga2():
    """ZDT1 (10 variables), 5,000 evaluations, N = 50, reference (1.1, 1.1), seed 0.

    Measured HV / NSGA2's HV: MOGWO 0.944, MOMVO 0.921, MOALO 0.878, MSSA 0.821,
    MODA 0.516. The bounds leave a margin; they check that each algorithm
    converges at all, not that it matches NSGA2.
    """
    problem, ref = get_problem("zdt1", n_var=10), [1.1, 1.1]
    hv_nsga2 = hypervolume(minimize(problem, NSGA2(pop_size=50), ("n_eval", 5000),
                                    seed=0).F, ref)
    ratios = {}
    for name in NAMES:
        res = minimize(problem, get_algorithm(name, pop_size=50), ("n_eval", 5000), seed=0)
        ratios[name] = hypervolume(res.F, ref) / hv_nsga2
    assert ratios["mogwo"] >= 0.9 and ratios["momvo"] >= 0.85 and ratios["moalo"] >= 0.8
    assert ratios["mssa"] >= 0.75 and ratios["moda"] >= 0.45
