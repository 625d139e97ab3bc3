"""Slime mould algorithm (moik.algorithms.soo.sma): Eqs. 1-4 on hand-computed arrays."""

import math

import numpy as np
import pytest

from moik.algorithms.soo.sma import EPS, sma_schedule, sma_update, sma_weights
from moik.testing import ScriptedRng


def test_sma_schedule():
    a, b = sma_schedule(500, 1000)
    assert a == math.atanh(0.5) and b == 0.5


def test_sma_weights_stay_finite_when_the_fitness_spread_is_zero_or_below_eps():
    """bF == wF: every weight is 1. A spread of eps or less (where the authors' code's
    ``bF - wF + eps`` is 0 or positive, giving log10 of -inf or of a negative number):
    the weights stay finite, within 1 +/- log10(2)."""
    rng = np.random.default_rng(0)
    np.testing.assert_array_equal(sma_weights(np.full(6, 0.25), 3, rng=rng), np.ones((6, 3)))
    for spread in (EPS / 2, EPS, 2 * EPS):
        S = np.array([0.0, spread, 0.0, spread, spread / 2, 0.0])
        W = sma_weights(S, 3, rng=rng)
        assert np.all(np.isfinite(W))
        assert np.all(np.abs(W - 1.0) <= math.log10(2.0))


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


@pytest.mark.parametrize("seed", range(6))
def test_compiled_weights_and_update_equal_the_numpy_formulas(seed, numpy_rules):
    rng = np.random.default_rng(seed)
    n, d = 13, 4
    X = rng.uniform(-2, 2, (n, d))
    S = rng.integers(0, 5, n).astype(float)  # ties
    if seed % 2:
        S[3] = np.nan
    W = sma_weights(S, d, rng=np.random.default_rng(seed))
    np.testing.assert_array_equal(W, numpy_rules.sma_weights(S, d, rng=np.random.default_rng(seed)))
    xl, xu = np.full(d, -2.0), np.full(d, 2.0)
    for x_best in (X[0], X[rng.integers(n, size=n)]):  # one best, or a food source per agent
        args = (X, W, x_best, S, 0.5, 0.8, 0.3)
        kw = {"z": 0.3, "xl": xl, "xu": xu}
        out = sma_update(*args, **kw, rng=np.random.default_rng(seed))
        ref = numpy_rules.sma_update(*args, **kw, rng=np.random.default_rng(seed))
        np.testing.assert_array_equal(out, ref)
