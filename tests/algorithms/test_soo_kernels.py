"""Kernels of EO, SMA, EOSMA, PSO and m-PSO on tiny hand-computed arrays.

``ScriptedRng`` hands out the random numbers in the order each kernel draws
them, so every expected value below is worked out by hand from the equations.
"""

import math

import numpy as np

from moik.algorithms.soo.eo import concentration_update, eo_schedule, update_pool, with_mean
from moik.algorithms.soo.eosma import eosma_update, random_difference_mutation
from moik.algorithms.soo.modified_pso import mpso_velocity
from moik.algorithms.soo.pso import clamp_velocity, pso_velocity
from moik.algorithms.soo.sma import sma_schedule, sma_update, sma_weights
from moik.testing import ScriptedRng


def test_eo_concentration_update_eqs_6_8_9():
    C, pool = np.array([[1.0, 2.0]]), np.array([[0.0, 0.0], [2.0, 2.0]])
    rng = ScriptedRng([[0.5, 0.5]], [[0.75, 0.25]], [1], [0.4], [0.6])  # lam, r, idx, r1, r2
    out = concentration_update(C, pool, 1.0, a1=2.0, GP=0.5, V=1.0, rng=rng)
    e = math.exp(-0.5) - 1.0
    F = [2.0 * e, -2.0 * e]  # Eq. 8: sign(0.75-0.5)=+1, sign(0.25-0.5)=-1
    G = [0.2 * (2.0 - 0.5 * 1.0) * F[0], 0.2 * (2.0 - 0.5 * 2.0) * F[1]]  # GCP = 0.5*0.4
    expected = [2.0 + (c - 2.0) * f + g / 0.5 * (1.0 - f)
                for c, f, g in zip((1.0, 2.0), F, G, strict=True)]
    np.testing.assert_allclose(out, [expected], rtol=1e-15)


def test_eo_generation_probability_switches_g_off():
    C, pool = np.array([[1.0]]), np.array([[3.0]])
    rng = ScriptedRng([[0.5]], [[0.75]], [0], [0.4], [0.3])  # r2 < GP: G = 0
    out = concentration_update(C, pool, 1.0, a1=1.0, GP=0.5, V=1.0, rng=rng)
    f = math.exp(-0.5) - 1.0
    np.testing.assert_allclose(out, [[3.0 + (1.0 - 3.0) * f]], rtol=1e-15)


def test_pool_keeps_four_best_so_far_and_mean():
    PX, PF = np.array([[0.0], [1.0]]), np.array([3.0, 1.0])
    X, F = np.array([[2.0], [3.0], [4.0]]), np.array([0.0, 5.0, 2.0])
    QX, QF, QCV = update_pool(PX, PF, None, X, F, None)
    np.testing.assert_array_equal(QX, [[2.0], [1.0], [4.0], [0.0]])
    np.testing.assert_array_equal(QF, [0.0, 1.0, 2.0, 3.0])
    assert QCV is None
    np.testing.assert_array_equal(with_mean(QX)[-1], [1.75])


def test_schedules():
    assert eo_schedule(250, 1000, 1.0) == 0.75**0.25
    assert eo_schedule(2000, 1000, 2.0) == 0.0  # capped at t = T
    a, b = sma_schedule(500, 1000)
    assert a == math.atanh(0.5) and b == 0.5


def test_sma_weights_eq4():
    S = np.array([3.0, 1.0, 2.0, 4.0])
    W = sma_weights(S, 1, rng=ScriptedRng(np.full((4, 1), 0.5)))
    expected = [1 - 0.5 * math.log10(5 / 3), 1.0, 1 + 0.5 * math.log10(4 / 3),
                1 - 0.5 * math.log10(2)]
    np.testing.assert_allclose(W[:, 0], expected, rtol=1e-12)


def test_sma_update_eqs_1_2():
    X, W = np.array([[1.0], [2.0]]), np.ones((2, 1))
    # vb, vc, r, A, B, restart draw, restart position
    rng = ScriptedRng([[0.2], [0.4]], [[0.5], [-0.5]], [[0.3], [0.3]], [[0], [1]], [[1], [0]],
                      [0.5, 0.5])
    out = sma_update(X, W, np.array([0.5]), np.array([0.0, 10.0]), 0.0, 1.0, 0.5, z=0.03,
                     xl=np.array([0.0]), xu=np.array([4.0]), rng=rng)
    # row 0: p = tanh(0) = 0 -> vc*X = 0.5; row 1: p ~ 1 -> 0.5 + 0.4*(1*2 - 1) = 0.9
    np.testing.assert_allclose(out, [[0.5], [0.9]])
    rng = ScriptedRng([[0.2], [0.4]], [[0.5], [-0.5]], [[0.3], [0.3]], [[0], [1]], [[1], [0]],
                      [0.5, 0.01], [[0.25]])
    out = sma_update(X, W, np.array([0.5]), np.array([0.0, 10.0]), 0.0, 1.0, 0.5, z=0.03,
                     xl=np.array([0.0]), xu=np.array([4.0]), rng=rng)
    np.testing.assert_allclose(out, [[0.5], [1.0]])  # row 1 restarts at 0 + 0.25*4


def test_eosma_update_eq15_picks_operator_per_agent():
    P, W, pool = np.array([[1.0], [2.0]]), np.array([[1.0], [2.0]]), np.array([[3.0], [4.0]])
    rng = ScriptedRng(np.full((2, 1), 0.5), np.full((2, 1), 0.75), [1, 0], [0.4, 0.4],
                      [0.6, 0.6],  # EO draws (t1 = 0 makes F = 0: X = Ceq)
                      [[0.9], [0.5]], [0, 1], [0, 0],  # vb, A, B
                      [0.1, 0.9])  # rand < z: EO for agent 0, SMA for agent 1
    out = eosma_update(P, np.array([0.5]), pool, W, 0.0, 1.0, z=0.5, a1=2.0, GP=0.5, V=1.0,
                       rng=rng)
    np.testing.assert_allclose(out, [[4.0], [0.5 + 0.5 * (2.0 * 2.0 - 1.0)]])


def test_random_difference_mutation_eq16():
    P = np.array([[0.0], [1.0], [2.0]])
    rng = ScriptedRng([[2, 1, 1], [1, 2, 0], [0, 0, 0]], [[0.5], [0.4], [0.3]])
    out = random_difference_mutation(P, rng=rng)
    np.testing.assert_allclose(out, [[2.5], [1.8], [1.0]])


def test_pso_velocity_eq1_and_clamp():
    rng = ScriptedRng([[0.5]], [[0.25]])
    V = pso_velocity(np.array([[1.0]]), np.array([[0.0]]), np.array([[2.0]]), np.array([3.0]),
                     w=0.5, c1=1.0, c2=2.0, rng=rng)
    np.testing.assert_allclose(V, [[0.5 + 1.0 * 0.5 * 2.0 + 2.0 * 0.25 * 3.0]])
    np.testing.assert_array_equal(clamp_velocity(np.array([[3.0, -3.0]]), np.array([2.0, 2.0])),
                                  [[2.0, -2.0]])
    assert clamp_velocity(V, None) is V


def test_mpso_velocity_eqs_3_4():
    zeros = np.zeros((2, 1))
    rng = ScriptedRng(np.full((2, 1), 0.5), np.full((2, 1), 0.5))
    V = mpso_velocity(zeros, zeros, np.ones((2, 1)), np.array([2.0]), np.array([True, False]),
                      w=0.8, c1=1.0, c2=1.0, rng=rng)
    np.testing.assert_allclose(V, [[0.5 * 1.0 + 0.5 * 2.0], [0.5 * 2.0]])
