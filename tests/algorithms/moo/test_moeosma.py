"""MOEOSMA (moik.algorithms.moo.moeosma): kernels, evaluation count, parameters, and HV
sanity against ZDT1's analytic front."""

import copy

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOEOSMA
from moik.algorithms.archive import CrowdingArchive
from moik.algorithms.mechanics import midpoint_repair, ranking_fitness
from moik.algorithms.moo.dominance import pareto_memory
from moik.algorithms.moo.moeosma import equilibrium_pool, rotation_objective
from moik.algorithms.soo.eo import eo_schedule
from moik.algorithms.soo.eosma import eosma_update, random_difference_mutation
from moik.algorithms.soo.sma import sma_schedule, sma_weights
from moik.exceptions import ParameterError, UnknownNameError
from moik.metrics import hypervolume
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots import get_robot


def test_rotation_objective_cycles_as_eq_21():
    # O = rem(t, M) + 1 (1-based); the first iteration is t = 1 -> second objective
    assert [rotation_objective(t, 2) for t in range(1, 5)] == [1, 0, 1, 0]
    assert [rotation_objective(t, 3) for t in range(1, 5)] == [1, 2, 0, 1]


def test_equilibrium_pool_is_the_least_crowded_members():
    X = np.arange(5.0)[:, None]
    np.testing.assert_array_equal(equilibrium_pool(X, np.array([2, 1, 3, 1, 2])), [[1.0], [3.0]])
    archive = CrowdingArchive.moeosma(10)
    F = np.array([[0.0, 1.0], [0.01, 0.99], [0.5, 0.5], [1.0, 0.0]])
    archive.add(F, F, rng=np.random.default_rng(0))
    pool = equilibrium_pool(archive.X, archive.counts)
    assert {tuple(p) for p in pool} == {(0.5, 0.5), (1.0, 0.0)}


def test_table4_defaults_and_bad_values():
    alg = MOEOSMA()
    assert (alg.pop_size, alg.archive_size, alg.z, alg.q, alg.V, alg.GP, alg.a1, alg.a2) == (
        100, 100, 0.5, 1.0, 1.0, 0.5, 2.0, 2.0)
    for kwargs, msg in [({"z": 2}, r"z must be a number in \[0.0, 1.0\]"),
                        ({"q": -0.1}, r"q must be a number in \[0.0, 1.0\]"),
                        ({"V": 0}, r"V must be a number in \(0.0, inf\)"),
                        ({"GP": "x"}, "GP must be a number"),
                        ({"a2": 11}, r"a2 must be a number in \(0.0, 10.0\]")]:
        with pytest.raises(ParameterError, match=msg):
            MOEOSMA(**kwargs)


@pytest.mark.parametrize(("q", "per_iteration"), [(1.0, 20), (0.0, 10)])
def test_evaluations_per_iteration(q, per_iteration):
    res = minimize(get_problem("zdt1", n_var=5), MOEOSMA(pop_size=10, q=q), ("n_gen", 11), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 10 * per_iteration


def test_reachable_ik_pose_p2_reaches_both_errors():
    """P2 = (50, -25, 75, 0, 0, 0) is reachable (EOSMA paper): the front's ends go to ~0."""
    target = Target.from_euler((50, -25, 75), (0, 0, 0), convention="eosma-euler", degrees=True)
    problem = BiObjectiveIK(get_robot("eosma7"), target, orientation="eosma-euler")
    res = minimize(problem, MOEOSMA(), ("n_gen", 300), seed=0)
    assert res.F[:, 0].min() < 1e-3 and res.F[:, 1].min() < 1e-3
    xl, xu = problem.bounds()
    assert np.array_equal(np.clip(res.X, xl, xu), res.X)


ZDT1_OPTIMAL_HV = 0.1 + 2.0 / 3.0 + 0.11
"""HV of ZDT1's Pareto front f2 = 1 - sqrt(f1), f1 in [0, 1], for the reference (1.1, 1.1):
the integral of 0.1 + sqrt(f1) over [0, 1] plus the 0.1 x 1.1 strip beyond f1 = 1."""


def test_zdt1_hv_within_5_percent_of_the_optimum():
    """ZDT1 (30 variables), 25,000 evaluations, reference (1.1, 1.1), mean of 5 seeds: at
    least 95 % of the front's analytic HV (a stated tolerance: the front is reached, not
    merely approached; pymoo's NSGA-II gets 99.2 % here).

    Measured: MOEOSMA 0.8463 (96.5 % of 0.8767) vs NSGA2 0.8695; about 3 s on 2 busy cores.
    """
    problem, ref = get_problem("zdt1"), [1.1, 1.1]
    # pymoo's sampled front (100 points) falls short of the analytic value by its gaps
    assert ZDT1_OPTIMAL_HV - 0.01 < hypervolume(problem.pareto_front(), ref) < ZDT1_OPTIMAL_HV
    hv = []
    for seed in range(5):
        res = minimize(problem, MOEOSMA(), ("n_eval", 25_000), seed=seed)
        assert res.algorithm.evaluator.n_eval == 25_000
        hv.append(hypervolume(res.F, ref))
    assert np.mean(hv) >= 0.95 * ZDT1_OPTIMAL_HV


def _numpy_generation(alg, rng, problem):
    """One MOEOSMA generation with EOSMA's numpy operators (the oracle of the kernels)."""
    n, A = alg.pop_size, alg.pareto_archive
    pool = equilibrium_pool(A.X, A.counts)
    g_best = pool[rng.integers(len(pool), size=n)]
    S = ranking_fitness(alg.pbest_F[:, rotation_objective(alg.t, 2)], alg.pbest_CV)
    W = sma_weights(S, alg.problem.n_var, rng=rng)
    t1, (a, _) = eo_schedule(alg.t, alg.max_iter, alg.a2), sma_schedule(alg.t, alg.max_iter)
    X = eosma_update(alg.pbest_X, g_best, pool, W, t1, a, z=alg.z, a1=alg.a1, GP=alg.GP,
                     V=alg.V, rng=rng)
    X = midpoint_repair(X, alg.pbest_X, alg.xl, alg.xu)
    F = problem.evaluate(X, return_values_of=["F"])
    P, _ = pareto_memory(X, F, alg.pbest_X, alg.pbest_F)
    assert rng.random() < alg.q
    return X, F, midpoint_repair(random_difference_mutation(P, rng=rng), P, alg.xl, alg.xu)


def test_compiled_generation_equals_the_numpy_operators_bit_for_bit():
    problem = get_problem("zdt1", n_var=7)
    alg = MOEOSMA(pop_size=12)
    alg.setup(problem, termination=("n_gen", 10), seed=8)
    for _ in range(4):
        alg.next()
    alg._begin_iteration()
    oracle_rng = copy.deepcopy(alg.random_state)
    X_ref, F_ref, M_ref = _numpy_generation(alg, oracle_rng, problem)
    step = alg._generation()
    X = next(step)
    np.testing.assert_array_equal(X, X_ref)
    M = step.send((F_ref, None))
    np.testing.assert_array_equal(M, M_ref)
    np.testing.assert_array_equal(alg.random_state.random(3), oracle_rng.random(3))


def test_diversity_option_keeps_an_elitist_memory_and_searches_the_mutants():
    problem = get_problem("zdt2", n_var=6)
    res = minimize(problem, MOEOSMA(pop_size=10, diversity="nsga2-gaussian"), ("n_gen", 6),
                   seed=1)
    alg = res.algorithm
    assert alg.diversity == "nsga2-gaussian" and alg.evaluator.n_eval == 10 + 5 * 20
    # the memory is the NSGA-II survival of memory and batches: sorted by rank
    from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

    rank = NonDominatedSorting().do(alg.pbest_F, return_rank=True)[1]
    assert np.all(np.diff(rank) >= 0) and rank.max() >= 1  # dominated members kept too
    paper = minimize(problem, MOEOSMA(pop_size=10), ("n_gen", 6), seed=1)
    assert not np.array_equal(paper.F, res.F)
    with pytest.raises(UnknownNameError, match="diversity"):
        MOEOSMA(diversity="crowding")
