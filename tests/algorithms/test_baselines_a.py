"""EOSMA-paper baselines MRFO, MPA, PFA, FPA, DE, GBO, TLBO: kernels and runs.

Kernel checks use ``ScriptedRng``, which hands out queued numbers in the order a
kernel draws them, so each expected value is worked out by hand from the
equations cited in the module docstrings.
"""

import math

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize

import moik
from moik.algorithms import DE, FPA, GBO, MPA, MRFO, PFA, TLBO, get_algorithm
from moik.algorithms.mechanics import mantegna_levy, mantegna_sigma
from moik.algorithms.soo.de import binomial_crossover, distinct_partners, rand_1_mutation
from moik.algorithms.soo.fpa import pollinate
from moik.algorithms.soo.gbo import gbo_alpha, gbo_update, gradient_search_rule
from moik.algorithms.soo.mpa import fads_effect, mpa_cf, mpa_phase, predator_move
from moik.algorithms.soo.mrfo import chain_and_cyclone, somersault
from moik.algorithms.soo.pfa import follower_move, pathfinder_move
from moik.algorithms.soo.tlbo import learner_phase, random_partners, teacher_phase
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng

NAMES = ["mrfo", "mpa", "pfa", "fpa", "de", "gbo", "tlbo"]
PER_ITERATION = {"mrfo": 2, "mpa": 2, "pfa": 1, "fpa": 1, "de": 1, "gbo": 1, "tlbo": 2}


class Sphere(Problem):
    def __init__(self, n_var=10, bound=100.0, n_ieq_constr=0):
        super().__init__(n_var=n_var, n_obj=1, n_ieq_constr=n_ieq_constr, xl=-bound, xu=bound)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = (X * X).sum(axis=1)
        if self.n_ieq_constr:
            out["G"] = 1.0 - X[:, :1]  # x0 >= 1: optimum f = 1


# ---- kernels ---------------------------------------------------------------------------
def test_de_rand_1_bin_eqs_1_to_3():
    X = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 5.0], [4.0, 4.0]])
    R = np.array([[1, 2, 3], [0, 2, 3], [3, 0, 1], [2, 1, 0]])
    V = rand_1_mutation(X, R, 0.5)
    np.testing.assert_allclose(V[0], [1.0 + 0.5 * (3 - 4), 2.0 + 0.5 * (5 - 4)])
    rng = ScriptedRng([[0.95, 0.95], [0.1, 0.95], [0.95, 0.95], [0.95, 0.95]], [1, 0, 0, 0])
    U = binomial_crossover(X, V, 0.9, rng=rng)
    np.testing.assert_array_equal(U[0], [X[0, 0], V[0, 1]])  # only j = rnbr(i) = 1
    np.testing.assert_array_equal(U[1], [V[1, 0], X[1, 1]])  # randb <= CR and rnbr at j=0
    np.testing.assert_array_equal(U[2], [V[2, 0], X[2, 1]])
    P = distinct_partners(6, 3, rng=np.random.default_rng(0))
    assert all(len(set(row)) == 3 and i not in row for i, row in enumerate(P))


def test_tlbo_teacher_and_learner_phases():
    X = np.array([[0.0], [2.0]])  # mean 1
    rng = ScriptedRng([1, 2], [[0.5], [0.25]])  # T_F, r
    out = teacher_phase(X, np.array([0.0]), rng=rng)
    np.testing.assert_allclose(out, [[0.0 + 0.5 * (0 - 1)], [2.0 + 0.25 * (0 - 2)]])
    rng = ScriptedRng([[0.5], [0.5]])
    out = learner_phase(X, np.array([True, False]), np.array([1, 0]), rng=rng)
    np.testing.assert_allclose(out, [[0.0 + 0.5 * (0 - 2)], [2.0 + 0.5 * (0 - 2)]])
    j = random_partners(5, rng=np.random.default_rng(1))
    assert np.all(j != np.arange(5)) and np.all((j >= 0) & (j < 5))


def test_fpa_levy_and_pollination_eqs_1_to_3():
    assert mantegna_sigma(1.5) == pytest.approx(0.696574502, rel=1e-8)
    step = mantegna_levy((1, 1), 1.5, rng=ScriptedRng([[1.0]], [[-4.0]]))
    assert step[0, 0] == pytest.approx(mantegna_sigma(1.5) / 4.0 ** (2 / 3))
    X, g = np.array([[1.0], [2.0], [4.0]]), np.array([0.0])
    # global?, u, v (Levy), eps, j, k offset
    rng = ScriptedRng([0.1, 0.9, 0.9], [[1.0], [1.0], [1.0]], [[1.0], [1.0], [1.0]],
                      [0.5, 0.5, 0.25], [1, 2, 0], [1, 1, 2])
    out = pollinate(X, g, p=0.2, beta=1.5, levy_scale=0.01, rng=rng)
    L = 0.01 * mantegna_sigma(1.5)
    # local: k = (j + offset) % 3, so (j, k) = (2, 0) and (0, 2)
    np.testing.assert_allclose(out, [[1.0 + L * 1.0], [2.0 + 0.5 * (4 - 1)],
                                     [4.0 + 0.25 * (1 - 4)]])


def test_mrfo_chain_cyclone_and_somersault_eqs_1_to_8():
    X, best = np.array([[1.0], [2.0]]), np.array([0.0])
    r = [[0.5], [0.5]]
    e = math.exp(-1.0)  # alpha = 2 * 0.5 * sqrt(|log e^-1|) = 1
    rng = ScriptedRng([0.9, 0.1], r, [[0.5], [0.5]], [[e], [e]], [0.25, 0.25], [0.1, 0.9],
                      [[0.8], [0.8]])  # cyclone?, r, alpha draws, r1, explore?, x_rand = 3
    out = chain_and_cyclone(X, best, 1, 2, xl=np.array([-5.0]), xu=np.array([5.0]), rng=rng)
    chain = 1.0 + 0.5 * (0 - 1) + 1.0 * (0 - 1)  # Eq. 1, ray 1 follows x_best
    beta = 2.0 * math.exp(0.25 * (2 - 1 + 1) / 2) * math.sin(2 * math.pi * 0.25)  # Eq. 5
    cyclone = 3.0 + 0.5 * (1.0 - 2.0) + beta * (3.0 - 2.0)  # Eq. 7 (explores: 0.9 > t/T)
    np.testing.assert_allclose(out, [[chain], [cyclone]])
    rng = ScriptedRng([0.5, 1.0], [0.25, 0.0])
    out = somersault(X, np.array([4.0]), 2.0, rng=rng)
    np.testing.assert_allclose(out, [[1.0 + 2 * (0.5 * 4 - 0.25 * 1)], [2.0 + 2 * 4.0]])


def test_mpa_phases_and_moves_eqs_12_to_16():
    assert [mpa_phase(t, 9) for t in (0, 2, 3, 5, 6, 8)] == [1, 1, 2, 2, 3, 3]
    assert mpa_cf(5, 10) == 0.5**1.0 and mpa_cf(0, 10) == 1.0
    prey, elite = np.array([[1.0], [2.0]]), np.array([3.0])
    draws = ([[0.0], [0.0]], [[1.0], [1.0]], [[2.0], [1.0]], [[0.5], [0.5]])  # u, v, RB, R
    out = predator_move(prey, elite, 1, 0.5, P=0.5, rng=ScriptedRng(*draws))
    expected = [1.0 + 0.25 * 2.0 * (3 - 2.0 * 1), 2.0 + 0.25 * (3 - 2)]  # Eq. 12
    np.testing.assert_allclose(out[:, 0], expected)
    out = predator_move(prey, elite, 2, 0.5, P=0.5, rng=ScriptedRng(*draws))
    # Eq. 13 with R_L = 0 for the first half; Eq. 14 for the second
    np.testing.assert_allclose(out[:, 0], [1.0, 3.0 + 0.25 * 1.0 * (1.0 * 3 - 2)])
    rng = ScriptedRng(0.1, [[0.1], [0.5]], [[0.5], [0.5]])  # FADs branch, U draw, R
    out = fads_effect(prey, 0.5, FADs=0.2, xl=np.array([0.0]), xu=np.array([4.0]), rng=rng)
    np.testing.assert_allclose(out, [[1.0 + 0.5 * 2.0], [2.0]])
    rng = ScriptedRng(0.9, 0.5, [1, 0], [0, 1])
    out = fads_effect(prey, 0.5, FADs=0.2, xl=np.array([0.0]), xu=np.array([4.0]), rng=rng)
    np.testing.assert_allclose(out, [[1.0 + 0.6 * 1.0], [2.0 - 0.6 * 1.0]])


def test_pfa_pathfinder_and_followers():
    rng = ScriptedRng([0.5], [0.5])
    out = pathfinder_move(np.array([1.0]), np.array([0.0]), 1, 2, rng=rng)
    np.testing.assert_allclose(out, [1.0 + 2 * 0.5 * 1.0 + 0.5 * math.exp(-1.0)])
    X = np.array([[0.0, 0.0], [3.0, 4.0]])  # row 0: pathfinder; D = 5
    rng = ScriptedRng([1], [[0.5, 0.5]], [[0.5, 0.5]], [[0.1, -0.1]])  # j offset, r1, r2, u1
    out = follower_move(X, X[0], 1, 2, 2.0, 1.0, rng=rng)
    eps = 0.5 * np.array([0.1, -0.1]) * 5.0
    np.testing.assert_allclose(out, [[3.0, 4.0] + 1.0 * -X[1] + 0.5 * -X[1] + eps])


def test_gbo_schedule_gsr_and_fixed_point():
    beta = 1.2  # Eq. 14 at t = 0
    alpha = abs(beta * math.sin(1.5 * math.pi + math.sin(1.5 * math.pi * beta)))
    assert gbo_alpha(0, 10) == pytest.approx(alpha)
    X, xr1, xm = np.array([[1.0]]), np.array([[0.0]]), np.array([[1.0]])
    best, worst = np.array([2.0]), np.array([0.0])
    # delta rand, dx rand, randn, yp rands, yq rands, randn
    rng = ScriptedRng([[0.5]], [[1.0]], [[1.0]], [[1.0]], [[1.0]], [[1.0]], [[1.0]], [[1.0]])
    out = gradient_search_rule(X, xr1, xm, best, worst, X, np.zeros((1, 1)), 1.0, 0.0, rng=rng)
    # dx = |(2 - 0) + 0| / 2 = 1; GSR1 = 2*1*1/2 = 1; xs = 0; yp - yq = 2 dx = 2 -> GSR = 1
    np.testing.assert_allclose(out, [[1.0]])
    same = np.full((6, 2), 0.5)  # a collapsed population is a fixed point without LEO
    out = gbo_update(same, same[0], same[0], 0.7, pr=0.0, xl=np.zeros(2), xu=np.ones(2),
                     rng=np.random.default_rng(0))
    np.testing.assert_allclose(out, same, atol=1e-15)


# ---- runs ------------------------------------------------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_deterministic_in_bounds_and_exact_budget(name):
    problem = Sphere(n_var=7, bound=10.0)
    runs = [minimize(problem, get_algorithm(name, pop_size=20), ("n_eval", 1037), seed=11)
            for _ in range(2)]
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    np.testing.assert_array_equal(runs[0].F, runs[1].F)
    assert runs[0].algorithm.evaluator.n_eval == 1037
    other = minimize(problem, get_algorithm(name, pop_size=20), ("n_eval", 1037), seed=12)
    assert not np.array_equal(other.X, runs[0].X)
    X = runs[0].pop.get("X")
    assert np.all(np.abs(X) <= 10) and np.all(np.abs(runs[0].X) <= 10)


@pytest.mark.parametrize("name", NAMES)
def test_evaluations_per_iteration_as_documented(name):
    res = minimize(Sphere(n_var=5), get_algorithm(name, pop_size=10), ("n_gen", 4), seed=0)
    assert res.algorithm.evaluator.n_eval == 10 + 3 * 10 * PER_ITERATION[name]


@pytest.mark.parametrize("name", NAMES)
def test_sphere_10d_below_1e_6_within_30000_evaluations(name):
    """N=30; FPA needs the small population (with N=50 it stops near 1e-3 at this budget)."""
    res = minimize(Sphere(), get_algorithm(name, pop_size=30), ("n_eval", 30_000), seed=1)
    assert res.algorithm.evaluator.n_eval == 30_000 and res.F[0] < 1e-6


@pytest.mark.parametrize("name", NAMES)
def test_constrained_feasibility_first(name):
    res = minimize(Sphere(n_var=3, bound=5.0, n_ieq_constr=1), get_algorithm(name, pop_size=20),
                   ("n_eval", 4000), seed=2)
    assert res.X is not None and res.X[0] >= 1.0 and res.F[0] < 1.1


@pytest.mark.parametrize("name", NAMES)
def test_runs_on_position_ik(name):
    robot = moik.robots.get_robot("eosma7")
    q = np.array([0.3, -0.5, 0.4, 1.0, -0.2, 0.6, 0.1])
    problem = moik.problems.PositionIK(robot, robot.fk_position(q[None])[0])
    res = minimize(problem, get_algorithm(name, pop_size=30), ("n_eval", 3000), seed=2)
    xl, xu = problem.bounds()
    assert np.all(np.clip(res.X, xl, xu) == res.X) and res.F[0] < 5.0  # cm; ~50 at start
    assert res.F[0] < res.algorithm.convergence[0]


@pytest.mark.parametrize("cls", [PFA, MPA, TLBO])
def test_ask_tell_matches_minimize_for_multi_batch_generations(cls):
    problem = Sphere(n_var=4)
    ref = minimize(problem, cls(pop_size=12), ("n_eval", 500), seed=5)
    algo = cls(pop_size=12)
    algo.setup(problem, termination=("n_eval", 500), seed=5)
    while algo.has_next():  # the algorithm's own evaluator counts n_eval for the termination
        pop = algo.ask()
        algo.evaluator.eval(problem, pop)
        algo.tell(infills=pop)
    np.testing.assert_array_equal(algo.result().X, ref.X)
    assert algo.evaluator.n_eval == ref.algorithm.evaluator.n_eval == 500


@pytest.mark.parametrize(("cls", "params", "message"), [
    (DE, {"F": 0}, r"F must be a number in \(0.0, 2.0\]"),
    (DE, {"CR": 1.5}, r"CR must be a number in \[0.0, 1.0\]"),
    (DE, {"pop_size": 3}, r"pop_size must be an integer >= 4"),
    (FPA, {"p": -0.1}, r"p must be a number in \[0.0, 1.0\]"),
    (FPA, {"beta": 2.5}, r"beta must be a number in \(0.0, 2.0\]"),
    (FPA, {"levy_scale": 0}, r"levy_scale must be a number in \(0.0, inf\)"),
    (GBO, {"pr": 2}, r"pr must be a number in \[0.0, 1.0\]"),
    (GBO, {"pop_size": 4}, r"pop_size must be an integer >= 5"),
    (MPA, {"P": 0}, r"P must be a number in \(0.0, 2.0\]"),
    (MPA, {"FADs": "a"}, r"FADs must be a number"),
    (MRFO, {"S": -1}, r"S must be a number in \(0.0, 10.0\]"),
    (TLBO, {"pop_size": 1}, r"pop_size must be an integer >= 2"),
    (PFA, {"max_iter": 0}, r"max_iter must be a positive integer"),
])
def test_bad_parameters_raise(cls, params, message):
    with pytest.raises(ParameterError, match=message):
        cls(**params)


def test_registry_names_and_pymoo_de():
    from pymoo.algorithms.soo.nonconvex.de import DE as PymooDE  # noqa: N811

    assert isinstance(get_algorithm("de", F=0.5, CR=0.9), DE)
    assert isinstance(get_algorithm("pymoo-de", CR=0.9), PymooDE)
    for name, cls in zip(NAMES, [MRFO, MPA, PFA, FPA, DE, GBO, TLBO], strict=True):
        assert type(get_algorithm(name.upper())) is cls
