"""Equilibrium optimizer (moik.algorithms.soo.eo): Eqs. 6-9 on hand-computed arrays.

``ScriptedRng`` hands out the random numbers in the order each kernel draws
them, so every expected value below is worked out by hand from the equations.
"""

import math

import numpy as np
import pytest

from moik.algorithms.soo.eo import concentration_update, eo_schedule, update_pool, with_mean
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


def test_eo_schedule():
    assert eo_schedule(250, 1000, 1.0) == 0.75**0.25
    assert eo_schedule(2000, 1000, 2.0) == 0.0  # capped at t = T


@pytest.mark.parametrize("seed", range(6))
def test_compiled_update_and_pool_equal_the_numpy_formulas(seed, numpy_rules):
    rng = np.random.default_rng(seed)
    C, pool = rng.uniform(-3, 3, (11, 4)), rng.uniform(-3, 3, (5, 4))
    for a1, GP, V in ((2.0, 0.5, 1.0), (1.0, 0.0, 0.5), (0.5, 1.0, 3.0)):
        kw = {"a1": a1, "GP": GP, "V": V}
        out = concentration_update(C, pool, 0.4, **kw, rng=np.random.default_rng(seed))
        ref = numpy_rules.concentration_update(C, pool, 0.4, **kw,
                                               rng=np.random.default_rng(seed))
        np.testing.assert_array_equal(out, ref)
    np.testing.assert_array_equal(with_mean(pool), numpy_rules.with_mean(pool))
    F = rng.integers(0, 4, 11).astype(float)
    for CV in (None, np.where(rng.random(11) < 0.5, 0.0, rng.random(11))):
        PCV = None if CV is None else CV[:3]
        out = update_pool(C[:3] + 1, F[:3], PCV, C, F, CV)
        ref = numpy_rules.update_pool(C[:3] + 1, F[:3], PCV, C, F, CV)
        for a, b in zip(out, ref, strict=True):
            assert (a is None and b is None) or np.array_equal(a, b)


def test_a_zero_lambda_gives_numpys_inf_or_nan_not_an_error():
    """numba raises on a float division by zero; the kernel answers as numpy does."""
    C, pool = np.array([[1.0, 2.0]]), np.array([[0.0, 3.0]])
    rng = ScriptedRng([[0.0, 0.0]], [[0.75, 0.25]], [0], [0.4], [0.6])
    out = concentration_update(C, pool, 1.0, a1=2.0, GP=0.5, V=1.0, rng=rng)
    assert np.isnan(out).all()  # lam = 0: F = 0, G / 0 = 0 / 0
