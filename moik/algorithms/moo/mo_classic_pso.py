"""MO-PSO: one classical inertia-weight PSO swarm per objective and a shared archive.

The MO-PSO baseline of Rokbani, Neji, Slim, Mirjalili & Ghandour, "A
Multi-Objective Modified PSO for Inverse Kinematics of a 5-DOF Robotic Arm",
Applied Sciences 12, 7091 (2022), DOI 10.3390/app12147091, Section 5.2
(Table 6), built the way the paper builds MO-m-PSO (Section 2.2, Algorithm 2,
:mod:`moik.algorithms.moo.objective_swarms`): swarm k runs classical PSO (Shi &
Eberhart 1998, DOI 10.1109/ICEC.1998.699146; the paper's Eqs. 1-2,
:mod:`moik.algorithms.soo.pso`) on objective k alone:

- Eq. 1: ``v = w v + c1 r1 (x_l - x) + c2 r2 (x_g - x)``, ``x_l`` the particle's
  best and ``x_g`` its swarm's best on the swarm's objective;
- Eq. 2: ``x = x + v``.

Every evaluated particle of every swarm is offered to the shared
crowding-radius archive; ``res.X``/``res.F`` are its front and
``moik.metrics.compromise(res)`` picks the member closest to the utopia point (Eq. 8).

Defaults: w=0.8, c1=c2=1.493 (Section 4.1; the paper's PSO baselines use
"similar m-PSO parameters"). Evaluations: ``M pop_size`` per iteration and
for the initial population.

Readings and deviations:
- The paper names MO-PSO after Walha et al. (its ref. 36) but gives no
  details; this is the paper's own multi-swarm construction with classical PSO,
  so that it differs from MO-m-PSO only in the velocity rule.
- Archive: the EOSMA paper's crowding-radius archive, capacity ``archive_size``
  (default ``pop_size``), as for MO-m-PSO.
- As moik's PSO: zero initial velocities, velocity clamp ``vmax_rate`` (0.2)
  of the box width, positions clipped to the bounds, r1 and r2 per coordinate.

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import Step
from moik.algorithms.moo.objective_swarms import ObjectiveSwarms, swarm_best
from moik.algorithms.soo.pso import check_pso_params, clamp_velocity, pso_velocity


class MOClassicPSO(ObjectiveSwarms):
    """MO-PSO (classical PSO per objective, Rokbani et al. 2022); ``res.F`` = the archive.

    Extra public array: ``V`` (velocities); see :class:`ObjectiveSwarms` for
    ``swarm``, ``S`` and the personal bests.

    Args:
        pop_size: Particles per swarm N (one swarm per objective).
        archive_size: Archive capacity; None means ``pop_size``.
        w: Inertia weight in [0, 1.5] (paper: 0.8).
        c1: Cognitive coefficient in [0, 4] (paper: 1.493).
        c2: Social coefficient in [0, 4] (paper: 1.493).
        vmax_rate: Velocity clamp as a fraction of the box width, in (0, 1], or None.
        X0: Optional initial points (at most M * pop_size rows).
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 w: float = 0.8, c1: float = 1.493, c2: float = 1.493,
                 vmax_rate: float | None = 0.2, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0, **kwargs)
        self.w, self.c1, self.c2, self.vmax_rate = check_pso_params(w, c1, c2, vmax_rate)

    def _initialize_state(self) -> None:
        super()._initialize_state()
        self.V = np.zeros_like(self.X)
        self.vmax = None if self.vmax_rate is None else self.vmax_rate * (self.xu - self.xl)

    def _generation(self) -> Step:
        g = swarm_best(self.pbest_X, self._pbest_rank(), self.problem.n_obj)
        V = pso_velocity(self.V, self.X, self.pbest_X, g, w=self.w, c1=self.c1, c2=self.c2,
                         rng=self.random_state)  # Eq. 1
        self.V = clamp_velocity(V, self.vmax)
        X = clip_to_bounds(self.X + self.V, self.xl, self.xu)  # Eq. 2
        self._remember(X, *(yield X))
