"""MO baselines (b): MOSMA, MOPSO, MOMPA (EOSMA Table 4) and MO-PSO, MO-JAYA, MO-CSA (MO-m-PSO)."""

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOCSA, MOJAYA, MOMPA, MOPSO, MOSMA, MOClassicPSO, get_algorithm
from moik.algorithms.archive import CrowdingArchive, GridArchive, nondominated_mask
from moik.algorithms.moo.mo_csa import crow_move, inside_box
from moik.algorithms.moo.mompa import top_predator
from moik.algorithms.moo.mopso_grid import (
    mopso_mutation,
    mutation_rate,
    pareto_accept,
    reflect_velocity,
)
from moik.algorithms.moo.mosma import elitist_order
from moik.algorithms.moo.objective_swarms import swarm_extreme, swarm_partners
from moik.algorithms.soo.jaya import jaya_update as jaya_move
from moik.exceptions import ParameterError
from moik.metrics import compromise, hypervolume
from moik.problems import BiObjectiveIK, random_reachable_targets
from moik.robots import get_robot

NAMES = ["mosma", "mopso", "mompa", "mo-pso", "mo-jaya", "mo-csa"]


def ik_problem():
    robot = get_robot("eosma7")
    return BiObjectiveIK(robot, random_reachable_targets(robot, 1, seed=0)[0].pose)


# ---- kernels on tiny arrays -------------------------------------------------------------------
def test_swarm_extremes_and_partners():
    P = np.arange(8.0).reshape(4, 2)
    S = np.array([5.0, 1.0, 3.0, 4.0])
    np.testing.assert_array_equal(swarm_extreme(P, S, 2), [[2, 3], [2, 3], [4, 5], [4, 5]])
    np.testing.assert_array_equal(swarm_extreme(P, S, 2, worst=True),
                                  [[0, 1], [0, 1], [6, 7], [6, 7]])
    j = swarm_partners(3, 4, rng=np.random.default_rng(0))
    np.testing.assert_array_equal(j // 4, np.repeat([0, 1, 2], 4))


def test_jaya_move_is_eq_1():
    X = np.array([[-1.0, 2.0], [0.5, -0.5]])
    best, worst = np.array([1.0, 1.0]), np.array([-2.0, 3.0])
    r = np.random.default_rng(4)
    r1, r2 = r.random(X.shape), r.random(X.shape)
    expected = X + r1 * (best - np.abs(X)) - r2 * (worst - np.abs(X))
    np.testing.assert_allclose(jaya_move(X, best, worst, rng=np.random.default_rng(4)), expected)


def test_crow_move_follows_memory_or_flies_randomly():
    xl, xu = np.zeros(3), np.ones(3)
    X = np.full((4, 3), 0.2)
    M = np.full((4, 3), 0.6)
    new = crow_move(X, M, AP=0.0, fl=2.0, xl=xl, xu=xu, rng=np.random.default_rng(1))
    step = (new - X) / (M - X)  # one r * fl per crow, in [0, 2]
    assert np.allclose(step, step[:, :1]) and np.all((step >= 0) & (step <= 2))
    new = crow_move(X, M, AP=1.0, fl=2.0, xl=xl, xu=xu, rng=np.random.default_rng(1))
    assert inside_box(new, xl, xu).all() and not np.allclose(new, X + 0.0 * M)
    np.testing.assert_array_equal(inside_box(np.array([[0.0, 1.0, 0.5], [0.0, 1.1, 0.5]]),
                                             xl, xu), [True, False])


def test_mopso_mutation_schedule_and_operator():
    assert mutation_rate(1, 100, 0.1) == 1.0 and mutation_rate(100, 100, 0.1) == 0.0
    assert mutation_rate(51, 101, 0.5) == pytest.approx(0.25)
    assert mutation_rate(1, 1, 0.1) == 1.0
    xl, xu = np.zeros(4), np.full(4, 2.0)
    X = np.full((50, 4), 1.0)
    Xm = mopso_mutation(X, 0.1, xl, xu, rng=np.random.default_rng(0))
    changed = Xm != X
    assert np.all(changed.sum(axis=1) == 1)
    assert np.all(np.abs(Xm - X) <= 0.1 * 2.0)


def test_pareto_accept_and_velocity_reflection():
    old = np.array([[1.0, 1.0]] * 3)
    new = np.array([[0.5, 1.0], [2.0, 1.0], [0.5, 2.0]])
    takes = np.array([pareto_accept(new, old, rng=np.random.default_rng(s)) for s in range(40)])
    assert takes[:, 0].all() and not takes[:, 1].any() and 0 < takes[:, 2].sum() < 40
    X, V = reflect_velocity(np.array([[0.9, 0.5]]), np.array([[0.3, -0.1]]), np.zeros(2),
                            np.ones(2))
    np.testing.assert_allclose(X, [[1.0, 0.4]])
    np.testing.assert_allclose(V, [[-0.3, -0.1]])


def test_elitist_order_by_rank_then_crowding():
    F = np.array([[1.0, 1.0], [0.0, 1.0], [0.5, 0.5], [2.0, 2.0], [1.0, 0.0]])
    keep, rank = elitist_order(F, 4)
    assert set(keep[:3]) == {1, 2, 4} and keep[2] == 2 and keep[3] == 0  # ends first (cd = inf)
    np.testing.assert_array_equal(rank, [0, 0, 0, 1])


def test_top_predator_is_an_archive_member():
    A = CrowdingArchive.mirjalili(10)
    F = np.array([[0.0, 1.0], [0.5, 0.5], [1.0, 0.0]])
    A.add(F, F, rng=np.random.default_rng(0))
    assert any(np.array_equal(top_predator(A, rng=np.random.default_rng(1)), f) for f in F)


# ---- classes ----------------------------------------------------------------------------------
def test_table_defaults_archives_and_bad_values():
    p = MOPSO()
    assert (p.pop_size, p.archive_size, p.w, p.wdamp, p.c1, p.c2, p.mu) == (
        100, 100, 0.5, 0.99, 1.0, 2.0, 0.1)
    assert MOSMA().z == 0.03 and (MOMPA().P, MOMPA().FADs) == (0.5, 0.2)
    assert (MOClassicPSO().w, MOClassicPSO().c1, MOClassicPSO().c2) == (0.8, 1.493, 1.493)
    assert (MOCSA().AP, MOCSA().fl) == (0.1, 2.0) and MOJAYA(pop_size=7).archive_size == 7
    prob = get_problem("zdt1", n_var=4)
    assert isinstance(minimize(prob, MOPSO(pop_size=6), ("n_gen", 2), seed=0)
                      .algorithm.pareto_archive, GridArchive)
    for bad, msg in [(lambda: MOPSO(mu=0), r"mu must be a number in \(0.0, 1.0\]"),
                     (lambda: MOPSO(wdamp=1.5), "wdamp must be a number"),
                     (lambda: MOSMA(z=-1), r"z must be a number in \[0.0, 1.0\]"),
                     (lambda: MOMPA(P=0), r"P must be a number in \(0.0, 2.0\]"),
                     (lambda: MOCSA(AP=2), r"AP must be a number in \[0.0, 1.0\]"),
                     (lambda: MOCSA(fl=0), "fl must be a number"),
                     (lambda: MOClassicPSO(c1=5), r"c1 must be a number in \[0.0, 4.0\]"),
                     (lambda: MOJAYA(pop_size=1), "pop_size must be an integer >= 2")]:
        with pytest.raises(ParameterError, match=msg):
            bad()


@pytest.mark.parametrize(("cls", "initial", "per_iteration"),
                         [(MOSMA, 10, 10), (MOMPA, 10, 20), (MOClassicPSO, 20, 20),
                          (MOJAYA, 20, 20), (MOPSO, 10, 20)])
def test_evaluations_per_iteration(cls, initial, per_iteration):
    # MOPSO: pm = 1 in the first iteration, so every particle is mutated once
    res = minimize(get_problem("zdt1", n_var=5), cls(pop_size=10), ("n_gen", 2), seed=0)
    assert res.algorithm.evaluator.n_eval == initial + per_iteration


def test_csa_evaluates_only_positions_inside_the_box():
    res = minimize(get_problem("zdt1", n_var=5), MOCSA(pop_size=10), ("n_gen", 11), seed=0)
    a = res.algorithm
    assert 20 + 10 * 5 <= a.evaluator.n_eval <= 20 + 10 * 20  # fl = 2 overshoots sometimes
    assert inside_box(a.X, a.xl, a.xu).all()


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(name, problem_name):
    problem = ik_problem() if problem_name == "ik" else get_problem("zdt1", n_var=10)
    xl, xu = problem.bounds()
    runs = [minimize(problem, get_algorithm(name, pop_size=20), ("n_eval", 1200), seed=7)
            for _ in range(2)]
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    np.testing.assert_array_equal(runs[0].F, runs[1].F)
    res = runs[0]
    assert res.F.shape[1] == 2 and 1 <= len(res.F) <= 20
    assert np.array_equal(np.clip(res.X, xl, xu), res.X)
    assert nondominated_mask(res.F).all()
    assert res.algorithm.evaluator.n_eval == 1200
    x, f = compromise(res)
    assert any(np.array_equal(f, row) for row in res.F)


def test_zdt1_hypervolume_against_nsga2_same_budget():
    """ZDT1 (30 variables), 6,000 evaluations, seed 0, reference (1.1, 1.1).

    Measured (this budget, seed 0): NSGA2 0.741; MOSMA 0.865, MOMPA 0.490, MOPSO
    0.405 (their schedules, inferred from the budget, are short here; at 25,000
    evaluations see the report). The per-objective swarms cover little of the
    front (MO-PSO 0.075, MO-JAYA 0.375, MO-CSA 0.0; MO-m-PSO itself 0.075), so
    only their own-objective end is checked.
    """
    problem, ref = get_problem("zdt1", n_var=30), np.array([1.1, 1.1])
    budget = ("n_eval", 6000)
    hv_nsga2 = hypervolume(minimize(problem, NSGA2(pop_size=100), budget, seed=0).F, ref)
    hv = {name: hypervolume(minimize(problem, get_algorithm(name), budget, seed=0).F, ref)
          for name in ["mosma", "mompa", "mopso"]}
    assert hv["mosma"] >= 0.95 * hv_nsga2
    assert hv["mompa"] >= 0.5 * hv_nsga2
    assert hv["mopso"] >= 0.4 * hv_nsga2
    for name in ["mo-pso", "mo-jaya", "mo-csa"]:
        res = minimize(problem, get_algorithm(name), budget, seed=0)
        assert res.F[:, 0].min() < 1e-3  # the f1 swarm drives x1 to its bound
