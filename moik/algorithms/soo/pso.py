"""Classical inertia-weight particle swarm optimization (PSO).

Shi & Eberhart, "A modified particle swarm optimizer", IEEE ICEC 1998,
DOI 10.1109/ICEC.1998.699146, as restated and used as the baseline in Rokbani
et al., "A Multi-Objective Modified PSO for Inverse Kinematics of a 5-DOF
Robotic Arm", Applied Sciences 12, 7091 (2022), DOI 10.3390/app12147091:

- Eq. 1: ``v = w v + c1 r1 (x_l - x) + c2 r2 (x_g - x)``;
- Eq. 2: ``x = x + v``.

Defaults: w=0.8, c1=c2=1.493 (the m-PSO paper, Section 4.1: the PSO baseline
uses "similar m-PSO parameters"). Evaluations: N per iteration.

Choices the paper leaves open (documented deviations):
- Velocities start at zero and are clamped to ``|v| <= vmax_rate (xu - xl)``
  with ``vmax_rate=0.2`` (pymoo's default rate); ``vmax_rate=None`` disables it.
- Positions leaving the box are clipped to the bounds.
- r1, r2 are drawn per coordinate.
- Constrained problems: the personal and global bests use feasibility-first
  comparisons (see base.py).
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    best_index,
    clip_to_bounds,
    greedy_memory,
)


def pso_velocity(V, X, P, g, *, w: float, c1: float, c2: float,
                 rng: np.random.Generator) -> np.ndarray:
    """Eq. 1: inertia-weight velocity toward personal bests ``P`` and global best ``g``."""
    r1 = rng.random(X.shape)
    r2 = rng.random(X.shape)
    return w * V + c1 * r1 * (P - X) + c2 * r2 * (g - X)


def clamp_velocity(V: np.ndarray, vmax: np.ndarray | None) -> np.ndarray:
    """Clamp every velocity coordinate into ``[-vmax, vmax]`` (no-op for None)."""
    return V if vmax is None else np.minimum(np.maximum(V, -vmax), vmax)


def check_pso_params(w, c1, c2, vmax_rate) -> tuple[float, float, float, float | None]:
    """Validate the shared PSO hyperparameters (used by PSO and MPSO)."""
    w = interval("w", w, 0.0, 1.5)
    c1 = interval("c1", c1, 0.0, 4.0)
    c2 = interval("c2", c2, 0.0, 4.0)
    if vmax_rate is not None:
        vmax_rate = interval("vmax_rate", vmax_rate, 0.0, 1.0, lo_open=True)
    return w, c1, c2, vmax_rate


class PSO(ArrayAlgorithm):
    """Inertia-weight PSO with array state.

    Extra public arrays: ``V`` (velocities), ``pbest_X``/``pbest_F``/``pbest_CV``.
    ``X``/``F`` is the current swarm.

    Args:
        pop_size: Number of particles N.
        w: Inertia weight in [0, 1.5] (paper: 0.8).
        c1: Cognitive coefficient in [0, 4] (paper: 1.493).
        c2: Social coefficient in [0, 4] (paper: 1.493).
        vmax_rate: Velocity clamp as a fraction of the box width, in (0, 1], or
            None for no clamp (default 0.2; not in the paper).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, w: float = 0.8, c1: float = 1.493,
                 c2: float = 1.493, vmax_rate: float | None = 0.2,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.w, self.c1, self.c2, self.vmax_rate = check_pso_params(w, c1, c2, vmax_rate)

    @classmethod
    def ibes(cls, **kwargs) -> PSO:
        """The PSO preset of the I-BES paper's comparisons (its Table 1).

        c1 = c2 = 1.4, w = 0.9, N = 150; the velocity limit ``v = 0.5 x`` is read as
        half the box width (``vmax_rate=0.5``). ``kwargs`` override any of them.
        """
        params = {"w": 0.9, "c1": 1.4, "c2": 1.4, "vmax_rate": 0.5, "pop_size": 150}
        return cls(**{**params, **kwargs})

    def _initialize_state(self) -> None:
        self.V = np.zeros_like(self.X)
        self.vmax = None if self.vmax_rate is None else self.vmax_rate * (self.xu - self.xl)
        self.pbest_X, self.pbest_F, self.pbest_CV = self.X, self.F, self.CV

    def _population_arrays(self):
        return self.pbest_X, self.pbest_F, self.pbest_CV

    def _move(self, V: np.ndarray) -> np.ndarray:
        """Clamp the velocities, take the step (Eq. 2) and clip into the box."""
        self.V = clamp_velocity(V, self.vmax)
        return clip_to_bounds(self.X + self.V, self.xl, self.xu)

    def _remember(self, X, F, CV) -> None:
        self.X, self.F, self.CV = X, F, CV
        self.pbest_X, self.pbest_F, self.pbest_CV = greedy_memory(
            X, F, CV, self.pbest_X, self.pbest_F, self.pbest_CV)

    def _generation(self) -> Step:
        g = self.pbest_X[best_index(self.pbest_F, self.pbest_CV)]
        V = pso_velocity(self.V, self.X, self.pbest_X, g, w=self.w, c1=self.c1, c2=self.c2,
                         rng=self.random_state)
        X = self._move(V)
        F, CV = yield X
        self._remember(X, F, CV)
