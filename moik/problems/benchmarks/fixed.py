"""Fixed-dimension classical test functions F14-F23 (MChOA paper, Table 2).

Source: the MChOA IK paper (the team's copy ``mchoa-industrial-robot``,
Table 2), i.e. the fixed-dimension multimodal functions of Yao, Liu & Lin
(1999, IEEE TEC 3(2)) as coded for GWO/ChOA: Shekel's foxholes (F14), Kowalik
(F15), six-hump camel back (F16), Branin (F17), Goldstein-Price (F18), Hartman
3 and 6 (F19, F20) and Shekel 5, 7, 10 (F21-F23). Constant tables are the
standard ones (Dixon & Szegoe 1978; Yao et al. 1999 Tables). Known optima are
from Jamil & Yang (2013, Int. J. Math. Model. Numer. Optim. 4(2)) and the SFU
Virtual Library of Simulation Experiments (Surjanovic & Bingham).

The table text gives F17's domain as ``[-5,10] [10,15]``; the standard (and
ChOA code) domain x1 in [-5, 10], x2 in [0, 15] is used. The global value
0.397887 is attained at (-pi, 12.275), inside both readings.
"""

from __future__ import annotations

import numpy as np

from moik.problems.benchmarks._base import Benchmark

_FOX = np.array([-32.0, -16.0, 0.0, 16.0, 32.0])
FOXHOLES_A = np.vstack([np.tile(_FOX, 5), np.repeat(_FOX, 5)])  # (2, 25)

KOWALIK_A = np.array(
    [0.1957, 0.1947, 0.1735, 0.16, 0.0844, 0.0627, 0.0456, 0.0342, 0.0323, 0.0235, 0.0246]
)
KOWALIK_B = 1.0 / np.array([0.25, 0.5, 1.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0])

HARTMAN_C = np.array([1.0, 1.2, 3.0, 3.2])
HARTMAN3_A = np.array([[3.0, 10.0, 30.0], [0.1, 10.0, 35.0], [3.0, 10.0, 30.0], [0.1, 10.0, 35.0]])
HARTMAN3_P = np.array(
    [
        [0.3689, 0.1170, 0.2673],
        [0.4699, 0.4387, 0.7470],
        [0.1091, 0.8732, 0.5547],
        [0.03815, 0.5743, 0.8828],
    ]
)
HARTMAN6_A = np.array(
    [
        [10.0, 3.0, 17.0, 3.5, 1.7, 8.0],
        [0.05, 10.0, 17.0, 0.1, 8.0, 14.0],
        [3.0, 3.5, 1.7, 10.0, 17.0, 8.0],
        [17.0, 8.0, 0.05, 10.0, 0.1, 14.0],
    ]
)
HARTMAN6_P = np.array(
    [
        [0.1312, 0.1696, 0.5569, 0.0124, 0.8283, 0.5886],
        [0.2329, 0.4135, 0.8307, 0.3736, 0.1004, 0.9991],
        [0.2348, 0.1451, 0.3522, 0.2883, 0.3047, 0.6650],
        [0.4047, 0.8828, 0.8732, 0.5743, 0.1091, 0.0381],
    ]
)

SHEKEL_A = np.array(
    [
        [4.0, 4.0, 4.0, 4.0],
        [1.0, 1.0, 1.0, 1.0],
        [8.0, 8.0, 8.0, 8.0],
        [6.0, 6.0, 6.0, 6.0],
        [3.0, 7.0, 3.0, 7.0],
        [2.0, 9.0, 2.0, 9.0],
        [5.0, 5.0, 3.0, 3.0],
        [8.0, 1.0, 8.0, 1.0],
        [6.0, 2.0, 6.0, 2.0],
        [7.0, 3.6, 7.0, 3.6],
    ]
)
SHEKEL_C = np.array([0.1, 0.2, 0.2, 0.4, 0.4, 0.6, 0.3, 0.7, 0.5, 0.5])


class F14(Benchmark):
    """Shekel's foxholes on [-65.536, 65.536]^2; 0.998004 near (-32, -32)."""

    def __init__(self) -> None:
        super().__init__(
            n_var=2, xl=-65.536, xu=65.536, f_opt=0.998003838, x_opt=[-31.97833, -31.97833]
        )

    def _evaluate(self, x, out, *args, **kwargs):
        d = np.sum((x[:, :, None] - FOXHOLES_A[None]) ** 6, axis=1)  # (n, 25)
        out["F"] = 1.0 / (1.0 / 500.0 + np.sum(1.0 / (np.arange(1, 26) + d), axis=1))


class F15(Benchmark):
    """Kowalik on [-5, 5]^4; 0.0003075 at (0.1928, 0.1908, 0.1231, 0.1358)."""

    def __init__(self) -> None:
        super().__init__(
            n_var=4,
            xl=-5.0,
            xu=5.0,
            f_opt=3.0748598e-4,
            x_opt=[0.19283335, 0.19083610, 0.12311723, 0.13576570],
        )

    def _evaluate(self, x, out, *args, **kwargs):
        b = KOWALIK_B[None, :]
        x1, x2, x3, x4 = (x[:, [i]] for i in range(4))
        model = x1 * (b**2 + b * x2) / (b**2 + b * x3 + x4)
        out["F"] = np.sum((KOWALIK_A[None, :] - model) ** 2, axis=1)


class F16(Benchmark):
    """Six-hump camel back on [-5, 5]^2; -1.0316285 at (0.0898, -0.7126)."""

    def __init__(self) -> None:
        super().__init__(
            n_var=2, xl=-5.0, xu=5.0, f_opt=-1.0316284535, x_opt=[0.08984201, -0.71265640]
        )

    def _evaluate(self, x, out, *args, **kwargs):
        x1, x2 = x[:, 0], x[:, 1]
        out["F"] = 4.0 * x1**2 - 2.1 * x1**4 + x1**6 / 3.0 + x1 * x2 - 4.0 * x2**2 + 4.0 * x2**4


class F17(Benchmark):
    """Branin on [-5, 10] x [0, 15]; 0.397887 at (-pi, 12.275), (pi, 2.275), (9.42478, 2.475)."""

    def __init__(self) -> None:
        super().__init__(
            n_var=2,
            xl=np.array([-5.0, 0.0]),
            xu=np.array([10.0, 15.0]),
            f_opt=0.39788735772973816,
            x_opt=[-np.pi, 12.275],
        )

    def _evaluate(self, x, out, *args, **kwargs):
        x1, x2 = x[:, 0], x[:, 1]
        ridge = x2 - 5.1 / (4.0 * np.pi**2) * x1**2 + 5.0 / np.pi * x1 - 6.0
        out["F"] = ridge**2 + 10.0 * (1.0 - 1.0 / (8.0 * np.pi)) * np.cos(x1) + 10.0


class F18(Benchmark):
    """Goldstein-Price on [-2, 2]^2; 3 at (0, -1)."""

    def __init__(self) -> None:
        super().__init__(n_var=2, xl=-2.0, xu=2.0, f_opt=3.0, x_opt=[0.0, -1.0])

    def _evaluate(self, x, out, *args, **kwargs):
        x1, x2 = x[:, 0], x[:, 1]
        a = 1.0 + (x1 + x2 + 1.0) ** 2 * (
            19.0 - 14.0 * x1 + 3.0 * x1**2 - 14.0 * x2 + 6.0 * x1 * x2 + 3.0 * x2**2
        )
        b = 30.0 + (2.0 * x1 - 3.0 * x2) ** 2 * (
            18.0 - 32.0 * x1 + 12.0 * x1**2 + 48.0 * x2 - 36.0 * x1 * x2 + 27.0 * x2**2
        )
        out["F"] = a * b


def hartman(x: np.ndarray, a: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Hartman family ``-sum_i c_i exp(-sum_j a_ij (x_j - p_ij)^2)`` for rows of ``x``."""
    inner = np.sum(a[None] * (x[:, None, :] - p[None]) ** 2, axis=2)  # (n, 4)
    return -np.sum(HARTMAN_C[None] * np.exp(-inner), axis=1)


class F19(Benchmark):
    """Hartman 3 on [0, 1]^3; -3.86278 at (0.114614, 0.555649, 0.852547)."""

    def __init__(self) -> None:
        super().__init__(
            n_var=3,
            xl=0.0,
            xu=1.0,
            f_opt=-3.86278214782076,
            x_opt=[0.114614, 0.555649, 0.852547],
        )

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = hartman(x, HARTMAN3_A, HARTMAN3_P)


class F20(Benchmark):
    """Hartman 6 on [0, 1]^6; -3.32237 at (0.2017, 0.1500, 0.4769, 0.2753, 0.3117, 0.6573)."""

    def __init__(self) -> None:
        super().__init__(
            n_var=6,
            xl=0.0,
            xu=1.0,
            f_opt=-3.32236801141551,
            x_opt=[0.20169, 0.150011, 0.476874, 0.275332, 0.311652, 0.657300],
        )

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = hartman(x, HARTMAN6_A, HARTMAN6_P)


class _Shekel(Benchmark):
    """Shekel ``-sum_{i<=m} 1 / ((x - a_i)(x - a_i)^T + c_i)`` on [0, 10]^4."""

    m: int = 5
    opt_value: float = 0.0

    def __init__(self) -> None:
        super().__init__(n_var=4, xl=0.0, xu=10.0, f_opt=self.opt_value, x_opt=[4.0, 4.0, 4.0, 4.0])

    def _evaluate(self, x, out, *args, **kwargs):
        a, c = SHEKEL_A[: self.m], SHEKEL_C[: self.m]
        d = np.sum((x[:, None, :] - a[None]) ** 2, axis=2)  # (n, m)
        out["F"] = -np.sum(1.0 / (d + c[None]), axis=1)


class F21(_Shekel):
    """Shekel 5 on [0, 10]^4; -10.1532 near (4, 4, 4, 4)."""

    m = 5
    opt_value = -10.1531996790582


class F22(_Shekel):
    """Shekel 7 on [0, 10]^4; -10.4029 near (4, 4, 4, 4)."""

    m = 7
    opt_value = -10.4029405668187


class F23(_Shekel):
    """Shekel 10 on [0, 10]^4; -10.5364 near (4, 4, 4, 4)."""

    m = 10
    opt_value = -10.5364098166920
