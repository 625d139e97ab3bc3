"""Sine and cosine within 1 ulp, inlined into the compiled forward kinematics.

fdlibm's minimax polynomials (k_sin.c, k_cos.c) on ``[-pi/4, pi/4]`` after a
Cody-Waite reduction by pi/2 (e_rem_pio2.c), branch-free so that the batched FK
kernels of :mod:`moik.robots.fk_kernels` vectorise; libm beyond :data:`TRIG_MAX`.
"""

from __future__ import annotations

import math

import numpy as np

from moik._jit import jit

# sin and cos on [-pi/4, pi/4] (fdlibm k_sin.c / k_cos.c, error < 1 ulp) and the
# Cody-Waite split of pi/2 (fdlibm e_rem_pio2.c): exact products for |n| < 2**20
_S1, _S2, _S3 = -1.66666666666666324348e-01, 8.33333333332248946124e-03, -1.98412698298579493134e-04
_S4, _S5, _S6 = 2.75573137070700676789e-06, -2.50507602534068634195e-08, 1.58969099521155010221e-10
_C1, _C2, _C3 = 4.16666666666666019037e-02, -1.38888888888741095749e-03, 2.48015872894767294178e-05
_C4, _C5, _C6 = -2.75573143513906633035e-07, 2.08757232129817482790e-09, -1.13596475577881948265e-11
_INV_PIO2 = 6.36619772367581382433e-01
_PIO2_1, _PIO2_2 = 1.57079632673412561417e+00, 6.07710050630396597660e-11
_PIO2_2T = 2.02226624879595063154e-21
TRIG_MAX = 8.0e5  # below 2**19 * pi/2: the inline reduction is good to 118 bits there
"""Largest ``|x|`` the inline polynomials take (libm beyond)."""


@jit
def sin_cos_inline(x):
    """``(sin(x), cos(x))`` within 1 ulp for ``|x| <= TRIG_MAX``, branch-free (vectorisable).

    ``x = n pi/2 + (y0 + y1)`` by two Cody-Waite rounds, fdlibm's minimax
    polynomials on ``|y| <= pi/4``, then the quadrant by selects.
    """
    fn = np.rint(x * _INV_PIO2)
    t = x - fn * _PIO2_1
    r = t - fn * _PIO2_2
    w = fn * _PIO2_2T - ((t - r) - fn * _PIO2_2)
    y0 = r - w
    y1 = (r - y0) - w
    z = y0 * y0
    zz = z * z
    rs = _S2 + z * (_S3 + z * _S4) + z * zz * (_S5 + z * _S6)
    sn = y0 - ((z * (0.5 * y1 - z * y0 * rs) - y1) - z * y0 * _S1)
    rc = z * (_C1 + z * (_C2 + z * _C3)) + zz * zz * (_C4 + z * (_C5 + z * _C6))
    hz = 0.5 * z
    wc = 1.0 - hz
    cs = wc + (((1.0 - wc) - hz) + (z * rc - y0 * y1))
    quadrant = fn - 4.0 * np.floor(0.25 * fn)
    odd = quadrant == 1.0 or quadrant == 3.0
    s = cs if odd else sn
    c = sn if odd else cs
    s = -s if quadrant >= 2.0 else s
    c = -c if quadrant == 1.0 or quadrant == 2.0 else c
    return s, c


@jit
def sin_cos(x):
    """``(sin(x), cos(x))`` within 1 ulp of libm.

    Inline polynomials for ``|x| <= TRIG_MAX`` (every joint value in practice):
    a libm call costs about 6 ns per function on the development machine, as
    much as the rest of a joint's FK, and blocks vectorisation. Larger ``|x|``
    and infinities go to libm; NaN propagates.
    """
    if abs(x) > TRIG_MAX:
        return math.sin(x), math.cos(x)
    return sin_cos_inline(x)
