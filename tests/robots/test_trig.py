"""Inline sine and cosine of the compiled FK (moik.robots.trig): within 1 ulp of libm."""

import numba
import numpy as np

from moik.robots import trig


@numba.njit
def _sin_cos_many(x, s, c):
    for i in range(x.size):
        s[i], c[i] = trig.sin_cos(x[i])


def test_sin_cos_within_one_ulp():
    rng = np.random.default_rng(0)
    k = rng.integers(-500, 500, 5000)
    x = np.concatenate([rng.uniform(-10, 10, 50_000), k * np.pi / 2, k * np.pi / 4,
                        k * np.pi / 2 + rng.normal(size=k.size) * 1e-9,
                        rng.uniform(-trig.TRIG_MAX, trig.TRIG_MAX, 20_000),
                        [0.0, 1e-300, 5e-324, trig.TRIG_MAX, 1.0e6, 1e300]])
    s, c = np.empty_like(x), np.empty_like(x)
    _sin_cos_many(x, s, c)
    for got, want in ((s, np.sin(x)), (c, np.cos(x))):
        ulp = np.spacing(np.maximum(np.abs(want), np.finfo(float).tiny))
        assert np.max(np.abs(got - want) / ulp) <= 1.0
    special = np.array([np.inf, -np.inf, np.nan])
    s, c = np.empty(3), np.empty(3)
    _sin_cos_many(special, s, c)
    assert np.all(np.isnan(s)) and np.all(np.isnan(c))
