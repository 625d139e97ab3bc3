"""Test oracles: five CEC2017 functions transcribed from the official C code, in numpy.

Reference: ``cec17_func.cpp`` (CEC17 Test Function Suite, N. Awad, "Last update
on 26_5_2017"), as published with the official ``input_data`` folder; line
numbers below refer to that file. The transcription follows the C code, not the
CEC2017 report's formulas, quirks included (they are commented where they bite).
The data are the official files that minionpy ships (read through
:func:`moik.problems.benchmarks.cec2017.official_data_dir`).

Each oracle is compared with moik's CEC2017 problems (minionpy) at random
points of [-100, 100]^D to 1e-8 relative.
"""

from __future__ import annotations

import numpy as np
import pytest

from moik.problems.benchmarks.cec2017 import CEC2017, official_data_dir

pytest.importorskip("minionpy")

CF_NUM = 10  # cec17_func.cpp line 121: composition data hold 10 components


def _data(number: int, nx: int) -> tuple[np.ndarray, np.ndarray]:
    """(M, O): rotation rows and shift rows as cec17_func.cpp lines 154-221 load them."""
    folder = official_data_dir()
    with (folder / f"M_{number}_D{nx}.txt").open() as fh:
        rotation = np.loadtxt(fh)  # nx rows of nx (F1-F19), CF_NUM * nx rows (F20-F30)
    with (folder / f"shift_data_{number}.txt").open() as fh:
        rows = [line.split()[:nx] for line in fh if line.strip()]
    return rotation, np.array(rows, dtype=float)  # one row (F1-F19), CF_NUM rows (F20-F30)


def _shuffle(number: int, nx: int) -> np.ndarray:
    with (official_data_dir() / f"shuffle_data_{number}_D{nx}.txt").open() as fh:
        return np.array(fh.read().split(), dtype=int)  # 1-based, lines 223-259


def sr_func(x, o, rotation, sh_rate, s_flag=True, r_flag=True):
    """Shift, shrink to the original search range, rotate (lines 1559-1599)."""
    y = (x - o) * sh_rate if s_flag else x * sh_rate
    return rotation @ y if r_flag else y  # rotatefunc, lines 1546-1557: xrot_i = sum_j x_j M_ij


def zakharov(z):
    """zakharov_func, lines 444-459: the linear sum is weighted by 0.5 (i + 1)."""
    s2 = np.sum(0.5 * np.arange(1, z.size + 1) * z)
    return np.sum(z**2) + s2**2 + s2**4


def rastrigin(z):
    """rastrigin_func body, lines 646-657 (the caller scales by 5.12/100)."""
    return np.sum(z * z - 10.0 * np.cos(2.0 * np.pi * z) + 10.0)


def levy(z):
    """levy_func, lines 462-491: w = 1 + (z - 1) / 4, so the minimum is at z = 1."""
    w = 1.0 + (z - 1.0) / 4.0
    term1 = np.sin(np.pi * w[0]) ** 2
    term3 = (w[-1] - 1) ** 2 * (1 + np.sin(2 * np.pi * w[-1]) ** 2)
    return term1 + np.sum((w[:-1] - 1) ** 2 * (1 + 10 * np.sin(np.pi * w[:-1] + 1) ** 2)) + term3


def ellips(z):
    """ellips_func, lines 417-425."""
    return np.sum(10.0 ** (6.0 * np.arange(z.size) / (z.size - 1)) * z * z)


def ackley(z):
    """ackley_func, lines 583-600."""
    n = z.size
    return (np.e - 20.0 * np.exp(-0.2 * np.sqrt(np.sum(z * z) / n))
            - np.exp(np.sum(np.cos(2.0 * np.pi * z)) / n) + 20.0)


def schaffer_f7(y, n):
    """schaffer_F7_func, lines 568-581, on the first ``n`` entries of ``y``.

    The C loop reads the global ``y`` array, not its argument: inside a hybrid
    function that is the shuffled vector from its start, not the component's block.
    """
    zz = np.sqrt(y[: n - 1] ** 2 + y[1:n] ** 2)
    f = np.sum(zz**0.5 + zz**0.5 * np.sin(50.0 * zz**0.2) ** 2)
    return f * f / (n - 1) / (n - 1)


def hgbat(z):
    """hgbat_func body, lines 872-890 (after the 5/100 scaling)."""
    z = z - 1.0
    r2, sum_z = np.sum(z * z), np.sum(z)
    return abs(r2**2 - sum_z**2) ** 0.5 + (0.5 * r2 + sum_z) / z.size + 0.5


def schwefel(z):
    """schwefel_func body, lines 677-704 (after the 1000/100 scaling)."""
    n, f = z.size, 0.0
    for zi in z + 4.209687462275036e002:
        if zi > 500:
            f -= (500.0 - np.fmod(zi, 500)) * np.sin((500.0 - np.fmod(zi, 500)) ** 0.5)
            f += ((zi - 500.0) / 100) ** 2 / n
        elif zi < -500:
            f -= (-500.0 + np.fmod(abs(zi), 500)) * np.sin((500.0 - np.fmod(abs(zi), 500)) ** 0.5)
            f += ((zi + 500.0) / 100) ** 2 / n
        else:
            f -= zi * np.sin(abs(zi) ** 0.5)
    return f + 4.189828872724338e002 * n


def bent_cigar(z):
    """bent_cigar_func, lines 515-525."""
    return z[0] ** 2 + 1e6 * np.sum(z[1:] ** 2)


def escaffer6(z):
    """escaffer6_func, lines 831-850 (the pairs wrap around: (z_D, z_1) last)."""
    s = z * z + np.roll(z, -1) ** 2
    return np.sum(0.5 + (np.sin(np.sqrt(s)) ** 2 - 0.5) / (1.0 + 0.001 * s) ** 2)


def cf_cal(x, shifts, delta, bias, fit):
    """cf_cal, lines 1645-1683: distance weights of the components."""
    d2 = np.sum((x - shifts[: len(fit)]) ** 2, axis=1)
    with np.errstate(divide="ignore"):
        w = np.where(d2 != 0, (1.0 / d2) ** 0.5 * np.exp(-d2 / 2.0 / x.size / delta**2), 1e99)
    if w.max() == 0:
        w = np.ones_like(w)
    return np.sum(w / w.sum() * (fit + bias))


def f3(x):
    """case 3, lines 281-284."""
    rotation, o = _data(3, x.size)
    return zakharov(sr_func(x, o[0], rotation, 1.0)) + 300.0


def f5(x):
    """case 5, lines 289-292: rastrigin_func shrinks x - o by 5.12/100 (line 651)."""
    rotation, o = _data(5, x.size)
    return rastrigin(sr_func(x, o[0], rotation, 5.12 / 100.0)) + 500.0


def f8(x):
    """case 8, lines 301-304: step_rastrigin_func (lines 659-675).

    Its rounding step writes the global ``y``, which sr_func then overwrites
    from ``x``: the official F8 is the plain rotated Rastrigin on F8's data.
    """
    rotation, o = _data(8, x.size)
    return rastrigin(sr_func(x, o[0], rotation, 5.12 / 100.0)) + 800.0


def f9(x):
    """case 9, lines 305-308: levy_func with no scaling (sh_rate 1.0, line 466)."""
    rotation, o = _data(9, x.size)
    return levy(sr_func(x, o[0], rotation, 1.0)) + 900.0


def f14(x):
    """case 14, lines 325-328: hf04 (lines 1015-1056), shares 0.2, 0.2, 0.2, 0.4."""
    nx = x.size
    rotation, o = _data(14, nx)
    y = sr_func(x, o[0], rotation, 1.0)[_shuffle(14, nx) - 1]
    sizes = [int(np.ceil(0.2 * nx))] * 3
    sizes.append(nx - sum(sizes))
    g = np.cumsum([0, *sizes])
    # components get s_flag = r_flag = 0: only their own sh_rate applies
    f = ellips(y[g[0]:g[1]]) + ackley(y[g[1]:g[2]])
    f += schaffer_f7(y, sizes[2])  # reads y from index 0 (see schaffer_f7)
    f += rastrigin(y[g[3]:g[4]] * 5.12 / 100.0)
    return f + 1400.0


def f27(x):
    """case 27, lines 377-380: cf07 (lines 1450-1475), six rotated, shifted components."""
    nx = x.size
    rotation, o = _data(27, nx)
    m = [rotation[k * nx:(k + 1) * nx] for k in range(6)]
    fit = np.array([
        10000 * hgbat(sr_func(x, o[0], m[0], 5.0 / 100.0)) / 1000,
        10000 * rastrigin(sr_func(x, o[1], m[1], 5.12 / 100.0)) / 1e3,
        10000 * schwefel(sr_func(x, o[2], m[2], 1000.0 / 100.0)) / 4e3,
        10000 * bent_cigar(sr_func(x, o[3], m[3], 1.0)) / 1e30,
        10000 * ellips(sr_func(x, o[4], m[4], 1.0)) / 1e10,
        10000 * escaffer6(sr_func(x, o[5], m[5], 1.0)) / 2e7,
    ])
    delta = np.array([10.0, 20, 30, 40, 50, 60])
    bias = np.array([0.0, 100, 200, 300, 400, 500])
    return cf_cal(x, o, delta, bias, fit) + 2700.0


ORACLES = {3: f3, 5: f5, 8: f8, 9: f9, 14: f14, 27: f27}


@pytest.mark.parametrize("n_var", [10, 30, 50])
@pytest.mark.parametrize("number", sorted(ORACLES))
def test_minionpy_agrees_with_the_official_code(number, n_var):
    X = np.random.default_rng(100 * number + n_var).uniform(-100.0, 100.0, (12, n_var))
    expected = np.array([ORACLES[number](x) for x in X])
    got = CEC2017(number, n_var=n_var).evaluate(X)[:, 0]
    np.testing.assert_allclose(got, expected, rtol=1e-8, atol=0.0)


@pytest.mark.parametrize("number", sorted(ORACLES))
def test_oracles_give_100_i_at_the_optimum(number):
    problem = CEC2017(number, n_var=30)
    assert ORACLES[number](problem.x_opt) == pytest.approx(100.0 * number, rel=1e-12)


def test_the_schaffer_quirk_is_what_tells_the_hybrid_apart():
    # the component on its own block (as the report's formula reads) differs from the C code
    nx = 30
    x = np.random.default_rng(14).uniform(-100.0, 100.0, nx)
    rotation, o = _data(14, nx)
    y = sr_func(x, o[0], rotation, 1.0)[_shuffle(14, nx) - 1]
    own_block = schaffer_f7(y[12:18], 6)
    from_start = schaffer_f7(y, 6)
    assert own_block != pytest.approx(from_start, rel=1e-3)
    assert CEC2017(14, n_var=nx).evaluate(x[None])[0, 0] == pytest.approx(f14(x), rel=1e-12)
