"""Chaotic PSO with arctangent acceleration coefficients (CPSO-AT), I-BES ref. [44].

Ma, Yuan, Han, Sun & Ma, "Improved Chaotic Particle Swarm Optimization
Algorithm with More Symmetric Distribution for Numerical Function
Optimization", Symmetry 11, 876 (2019), DOI 10.3390/sym11070876. Its
Algorithm 1, as far as used here:

- Eq. 6: chaotic initialization, a logistic-map sequence ``z <- 4 z (1 - z)``
  per dimension mapped into the box;
- Eqs. 1-2: the inertia-weight PSO step (kernels of :mod:`moik.algorithms.soo.pso`);
- Eq. 7: a chaotic local search of K points around the global best,
  ``gbest + R (2 z - 1)``, z from the logistic map; the best point found so
  far becomes the global best.

Defaults (I-BES paper, Table 1): w from 0.9 to 0.4, c1 = c2 = 2. Choices the
available sources leave open (documented readings, not the CPSO-AT paper's own
Eqs. 8-10, which were not available here): w decreases linearly with t/T; c1
and c2 stay constant at Table 1's values (the arctangent schedule of Eqs. 8-9
is not reproduced); Eq. 6 is read as the linear map ``lb + (ub - lb) z``
(printed with cos(Z)); K = 10 chaotic points per iteration with radius
``R = r0 (1 - t/T) (ub - lb)``, r0 = 0.1; velocities start uniform in
``[-vmax, vmax]`` and are clamped to ``vmax = 0.2 (ub - lb)``. Evaluations:
N + K per iteration. Positions are clipped to the bounds. Constrained
problems: personal and global bests are feasibility-first (Deb's rules, see
base.py).
"""

from __future__ import annotations

import numpy as np

from moik._validate import integer, interval
from moik.algorithms.array_state import given_rows
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, greedy_memory
from moik.algorithms.soo.pso import clamp_velocity, pso_velocity


def logistic_sequence(z0: np.ndarray, n: int) -> np.ndarray:
    """``n`` logistic-map iterates ``4 z (1 - z)`` after the start ``z0``, shape (n, *z0.shape)."""
    out, z = [], z0
    for _ in range(n):
        z = 4.0 * z * (1.0 - z)
        out.append(z)
    return np.asarray(out)


def chaotic_local_search(g, z: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """Eq. 7 (as read here): points ``g + R (2 z - 1)`` around the global best."""
    return g + radius * (2.0 * z - 1.0)


class CPSOAT(ArrayAlgorithm):
    """CPSO-AT with array state (``X``/``F``: the personal bests).

    Args:
        pop_size: Number of particles N.
        w_max: Initial inertia weight (Table 1: 0.9). w_min: final (0.4).
        c1: Cognitive coefficient (Table 1: 2). c2: social coefficient (2).
        n_chaos: Chaotic local-search points K per iteration, integer >= 0 (10).
        radius: Initial local-search radius r0 as a fraction of the box (0.1).
        vmax_rate: Velocity clamp as a fraction of the box width (0.2).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 150, w_max: float = 0.9, w_min: float = 0.4,
                 c1: float = 2.0, c2: float = 2.0, n_chaos: int = 10, radius: float = 0.1,
                 vmax_rate: float = 0.2, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.w_max = interval("w_max", w_max, 0.0, 1.5)
        self.w_min = interval("w_min", w_min, 0.0, self.w_max)
        self.c1 = interval("c1", c1, 0.0, 4.0)
        self.c2 = interval("c2", c2, 0.0, 4.0)
        self.radius = interval("radius", radius, 0.0, 1.0)
        self.vmax_rate = interval("vmax_rate", vmax_rate, 0.0, 1.0, lo_open=True)
        self.n_chaos = integer("n_chaos", n_chaos, minimum=0)

    def _evals_per_iteration(self) -> float:
        return float(self.pop_size + self.n_chaos)

    def _initialize_infill(self):
        pop = super()._initialize_infill()
        X = pop.get("X")
        k = given_rows(self.X0, self.sampling, self.pop_size)
        if k >= self.pop_size:
            return pop
        z0 = self.random_state.uniform(0.01, 0.99, self.xl.size)
        X[k:] = self.xl + (self.xu - self.xl) * logistic_sequence(z0, self.pop_size - k)
        pop.set("X", X)
        return pop

    def _initialize_state(self) -> None:
        self.vmax = self.vmax_rate * (self.xu - self.xl)
        self.V = self.random_state.uniform(-self.vmax, self.vmax, self.X.shape)
        self.positions = self.X
        self.z = self.random_state.uniform(0.01, 0.99, self.xl.size)

    def _generation(self) -> Step:
        s = min(self.t / self.max_iter, 1.0)
        w = self.w_max - (self.w_max - self.w_min) * s
        V = pso_velocity(self.V, self.positions, self.X, self.best_x, w=w, c1=self.c1,
                         c2=self.c2, rng=self.random_state)
        self.V = clamp_velocity(V, self.vmax)
        P = clip_to_bounds(self.positions + self.V, self.xl, self.xu)
        F, CV = yield P
        self.positions = P
        self.X, self.F, self.CV = greedy_memory(P, F, CV, self.X, self.F, self.CV)
        if self.n_chaos:
            Z = logistic_sequence(self.z, self.n_chaos)
            self.z = Z[-1]
            R = self.radius * (1.0 - s) * (self.xu - self.xl)
            Y = clip_to_bounds(chaotic_local_search(self.best_x, Z, R), self.xl, self.xu)
            yield Y  # the base keeps the best of them as the global best
