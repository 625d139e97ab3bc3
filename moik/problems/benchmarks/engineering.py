"""Constrained engineering design problems of the I-BES paper (Section 5.3).

Source: I-BES paper (the team's copy ``ibes-manipulators-2024``, Section
5.3, Tables 14-17), with the standard formulations of the tension/compression
spring (Belegundu 1982; Arora 1989) and the pressure vessel (Kannan & Kramer
1994; Sandgren 1990). Both are pymoo ``Problem``s with ``n_ieq_constr=4``;
a design is feasible when every ``G <= 0``. pymoo's constraint violation is
``sum(max(G, 0))``.

Constraint handling is the algorithm's job: these problems never penalize the
objective. moik's ``ArrayAlgorithm`` ranks by feasibility first (Deb's rules:
feasible beats infeasible, lower violation beats higher, then lower ``F``), so
an infeasible design is never reported as the best feasible one; an algorithm
that uses a penalty instead must say so in its docstring.

Spring: x = (d, D, N), 0.05 <= d <= 2, 0.25 <= D <= 1.3, 2 <= N <= 15 (the
paper's bounds). Best known feasible weight 0.012665 at (0.051689, 0.356718,
11.288966) (Coello 2000; He & Wang 2007). g2 divides by ``D d^3 - d^4``; at
``D == d`` it is ``+inf`` (infeasible). The paper's Table 14 reports
d = D = 0.25, N = 15 with f = 2.6952e6, which is that singular, infeasible
corner (f there is 0.2656 unpenalized): its spring numbers are penalized values,
not weights, and are not reproducible as such.

Pressure vessel: x = (Ts, Th, R, L) with the paper's bounds 0 <= Ts, Th <= 99,
10 <= R, L <= 200. The paper treats Ts and Th as continuous (its best design
0.7782, 0.3847, 40.3223, 200 with cost 5886.2 is not on the 0.0625 grid), and
L <= 200 cuts the classical optimum (L = 176.64), so the applicable optimum
is the continuous, relaxed one: 5885.3328 at (0.778169, 0.384649, 40.319619,
200) (e.g. Coelho 2010). ``discrete=True`` rounds Ts and Th up to multiples
of 0.0625 before evaluation (the original formulation); with it the classical
6059.7143 at (0.8125, 0.4375, 42.098446, 176.636596) applies.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from moik.problems.benchmarks._base import Benchmark

THICKNESS_STEP = 0.0625


class SpringDesign(Benchmark):
    """Tension/compression spring weight ``(N + 2) D d^2`` with 4 constraints."""

    def __init__(self) -> None:
        super().__init__(
            n_var=3,
            xl=np.array([0.05, 0.25, 2.0]),
            xu=np.array([2.0, 1.3, 15.0]),
            f_opt=0.012665232788,
            x_opt=[0.051689062324, 0.356717769668, 11.288964000524],
            n_ieq_constr=4,
        )

    def _evaluate(self, x, out, *args, **kwargs):
        d, D, N = x[:, 0], x[:, 1], x[:, 2]
        out["F"] = (N + 2.0) * D * d**2
        with np.errstate(divide="ignore"):
            g1 = 1.0 - D**3 * N / (71785.0 * d**4)
            g2 = (4.0 * D**2 - d * D) / (12566.0 * (D * d**3 - d**4)) + 1.0 / (5108.0 * d**2) - 1.0
            g3 = 1.0 - 140.45 * d / (D**2 * N)
        g4 = (d + D) / 1.5 - 1.0
        out["G"] = np.column_stack([g1, g2, g3, g4])


def vessel_cost(ts, th, r, length):
    """Pressure vessel cost (material, forming, welding) for scalars or arrays."""
    return (
        0.6224 * ts * r * length + 1.7781 * th * r**2 + 3.1661 * ts**2 * length + 19.84 * ts**2 * r
    )


def relaxed_vessel_optimum() -> np.ndarray:
    """Continuous optimum under the paper's bound L <= 200, in closed form.

    The cost grows with Ts, Th and falls with L along the volume constraint, so
    g1, g2, g3 are active and L sits on its bound: Ts = 0.0193 R,
    Th = 0.00954 R, L = 200, and R is the real root of
    ``pi R^2 200 + 4/3 pi R^3 = 1296000``.

    Returns:
        The design (Ts, Th, R, L).
    """
    roots = np.roots([4.0 / 3.0 * np.pi, 200.0 * np.pi, 0.0, -1296000.0])
    real = roots[np.abs(roots.imag) < 1e-9].real
    r = float(real[real > 0.0][0])
    return np.array([0.0193 * r, 0.00954 * r, r, 200.0])


class PressureVessel(Benchmark):
    """Pressure vessel cost with 4 constraints (continuous, or 0.0625-step thicknesses).

    Args:
        discrete: If True, Ts and Th are rounded up to multiples of 0.0625
            before evaluation (original formulation); default False, as in I-BES.
    """

    def __init__(self, *, discrete: bool = False) -> None:
        self.discrete = bool(discrete)
        x_opt: ArrayLike
        if self.discrete:
            f_opt, x_opt = 6059.714335, [0.8125, 0.4375, 42.098446, 176.636596]
        else:
            x_opt = relaxed_vessel_optimum()
            f_opt = vessel_cost(*x_opt)
        super().__init__(
            n_var=4,
            xl=np.array([0.0, 0.0, 10.0, 10.0]),
            xu=np.array([99.0, 99.0, 200.0, 200.0]),
            f_opt=f_opt,
            x_opt=x_opt,
            n_ieq_constr=4,
        )

    def _evaluate(self, x, out, *args, **kwargs):
        ts, th, r, length = x[:, 0], x[:, 1], x[:, 2], x[:, 3]
        if self.discrete:
            ts = np.ceil(np.round(ts / THICKNESS_STEP, 9)) * THICKNESS_STEP
            th = np.ceil(np.round(th / THICKNESS_STEP, 9)) * THICKNESS_STEP
        out["F"] = vessel_cost(ts, th, r, length)
        g1 = -ts + 0.0193 * r
        g2 = -th + 0.00954 * r
        g3 = -np.pi * r**2 * length - 4.0 / 3.0 * np.pi * r**3 + 1296000.0
        g4 = length - 240.0
        out["G"] = np.column_stack([g1, g2, g3, g4])
