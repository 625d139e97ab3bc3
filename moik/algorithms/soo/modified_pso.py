"""m-PSO: the fitness-based modified-behaviour PSO.

Rokbani, Neji, Slim, Mirjalili & Ghandour, "A Multi-Objective Modified PSO for
Inverse Kinematics of a 5-DOF Robotic Arm", Applied Sciences 12, 7091 (2022),
DOI 10.3390/app12147091, Eqs. 3-5 and Algorithm 1:

- Eq. 3: a particle worse than the mean of the local bests moves as classical
  inertia-weight PSO, ``v = w v + c1 r1 (x_l - x) + c2 r2 (x_g - x)``;
- Eq. 4: the others move toward the global best only, ``v = w v + c2 r2 (x_g - x)``;
- Eq. 5: ``x = x + v``.

Defaults (Section 4.1): w=0.8, c1=c2=1.493.

Reading of "worse than the mean of the local bests": Algorithm 1 computes
``xmean <- means{xl1, ..., xln}`` (the mean *position* of the local bests) and
tests ``f(x_i) > f(xmean)``, which costs one extra evaluation per iteration
(N + 1 evaluations per iteration). That is the default, ``switch="mean-position"``.
The abstract's wording ("fitness better than the mean local best") also reads
as the mean of the local-best *fitness* values: ``switch="mean-fitness"``
(N evaluations per iteration).

Typos in the paper, read as intended: Algorithm 1's classical update prints
``(x_i^k - x_i^k)`` for ``(x_l^k - x_i^k)``; Eqs. 2 and 5 print ``x_i^+``.

Choices the paper leaves open (same as moik's PSO): zero initial velocities,
velocity clamp ``vmax_rate=0.2`` of the box width, positions clipped to the
bounds, r1 and r2 drawn per coordinate, feasibility-first comparisons.
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    best_index,
    clip_to_bounds,
    greedy_memory,
    is_better,
)
from moik.algorithms.soo.pso import check_pso_params, clamp_velocity
from moik.exceptions import ParameterError

SWITCHES = ("mean-position", "mean-fitness")


def mpso_velocity(V, X, P, g, classic: np.ndarray, *, w: float, c1: float, c2: float,
                  rng: np.random.Generator) -> np.ndarray:
    """Eqs. 3-4: classical velocity for rows where ``classic`` is True, else social only."""
    r1 = rng.random(X.shape)
    r2 = rng.random(X.shape)
    cognitive = np.where(classic[:, None], c1 * r1 * (P - X), 0.0)
    return w * V + cognitive + c2 * r2 * (g - X)


class MPSO(ArrayAlgorithm):
    """m-PSO (Rokbani et al. 2022) with array state.

    Extra public arrays: ``V``, ``pbest_X``/``pbest_F``/``pbest_CV``, ``classic``
    (the particles that moved classically in the last iteration).

    Args:
        pop_size: Number of particles N.
        w: Inertia weight in [0, 1.5] (paper: 0.8).
        c1: Cognitive coefficient in [0, 4] (paper: 1.493).
        c2: Social coefficient in [0, 4] (paper: 1.493).
        vmax_rate: Velocity clamp as a fraction of the box width, in (0, 1], or None.
        switch: "mean-position" (Algorithm 1) or "mean-fitness" (see module doc).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, w: float = 0.8, c1: float = 1.493,
                 c2: float = 1.493, vmax_rate: float | None = 0.2,
                 switch: str = "mean-position", X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.w, self.c1, self.c2, self.vmax_rate = check_pso_params(w, c1, c2, vmax_rate)
        if switch not in SWITCHES:
            raise ParameterError(f"switch must be one of {', '.join(SWITCHES)}; got {switch!r}")
        self.switch = switch

    def _evals_per_iteration(self) -> float:
        return self.pop_size + (1.0 if self.switch == "mean-position" else 0.0)

    def _initialize_state(self) -> None:
        self.V = np.zeros_like(self.X)
        self.vmax = None if self.vmax_rate is None else self.vmax_rate * (self.xu - self.xl)
        self.pbest_X, self.pbest_F, self.pbest_CV = self.X, self.F, self.CV
        self.classic = np.ones(self.pop_size, dtype=bool)

    def _population_arrays(self):
        return self.pbest_X, self.pbest_F, self.pbest_CV

    def _generation(self) -> Step:
        if self.switch == "mean-position":
            f_mean, cv_mean = yield self.pbest_X.sum(axis=0, keepdims=True) / self.pop_size
            self.classic = is_better(f_mean, cv_mean, self.F, self.CV)  # f(x_i) > f(xmean)
        else:
            cv_mean = (None if self.CV is None or self.pbest_CV is None
                       else self.pbest_CV.sum() / self.pop_size)
            self.classic = is_better(self.pbest_F.sum() / self.pop_size, cv_mean, self.F, self.CV)
        g = self.pbest_X[best_index(self.pbest_F, self.pbest_CV)]
        V = mpso_velocity(self.V, self.X, self.pbest_X, g, self.classic, w=self.w, c1=self.c1,
                          c2=self.c2, rng=self.random_state)
        self.V = clamp_velocity(V, self.vmax)
        X = clip_to_bounds(self.X + self.V, self.xl, self.xu)  # Eq. 5
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
        self.pbest_X, self.pbest_F, self.pbest_CV = greedy_memory(
            X, F, CV, self.pbest_X, self.pbest_F, self.pbest_CV)
