"""MO-m-PSO: one m-PSO swarm per objective and a shared archive of non-dominated points.

Rokbani, Neji, Slim, Mirjalili & Ghandour, "A Multi-Objective Modified PSO for
Inverse Kinematics of a 5-DOF Robotic Arm", Applied Sciences 12, 7091 (2022),
DOI 10.3390/app12147091, Section 2.2 (Eqs. 6-8), Algorithm 2:

- "a set of mono-objective m-PSO instances, where each instance is in charge of
  a single objective": M swarms of ``pop_size`` particles each (the paper: "the
  same number of particles, similar m-PSO parameters, and the same maximum
  iterations number"); swarm k runs m-PSO (Eqs. 3-5,
  :mod:`moik.algorithms.soo.modified_pso`) on objective k: its personal bests,
  its mean-of-local-bests switch and its fitness are on objective k alone
  (shared swarm mechanics in :mod:`moik.algorithms.moo.objective_swarms`);
- "then a Pareto-based approach is used to find a compromise solution by
  sorting the closest particle to the utopia point of the Pareto front" (Eq. 8):
  every evaluated particle of every swarm is offered to one shared
  crowding-radius archive (Eqs. 7, Pareto dominance); the result ``res.X``/
  ``res.F`` is the archive's front, and ``moik.metrics.compromise(res)`` picks the
  member closest to the utopia point (objectives scaled to [0, 1] over the
  front, :func:`moik.metrics.closest_to_utopia`).

Two readings of the social guide x_g of Eqs. 3-4 (``guide``):

- ``guide="compromise"`` (default): Algorithm 2 places "find Pareto Utopia
  point of (f_1(), f_2()); Select Best_q" *inside* the iteration loop, after
  both m-PSO steps, and returns Best_q. Read as written, Best_q is recomputed
  every iteration and it is the one solution the swarms share: here every
  particle of every swarm takes the archive member closest to the utopia point
  (:func:`~moik.algorithms.moo.objective_swarms.utopia_closest`, the same rule
  as the final pick) as its global guide, recomputed at the start of every
  iteration from the archive after the previous one;
- ``guide="own-best"``: the swarms are independent m-PSO runs, each guided by
  its own best on its own objective, and the compromise is only picked at the
  end (the reading of Section 2.2's prose alone; the swarm of objective k then
  converges to the minimiser of objective k and the front between them is
  sparse).

The paper's numbers support the coupled reading. Table 2 (one pose, 100 runs,
50 particles per swarm, 500 iterations; paper mean position error 0.015 cm,
orientation 0.0918 rad), from ``moik experiment run mpso-table2`` and ``moik
report`` (docs/results/mpso-table2.md): compromise guide mean 0.01991 cm (median
0.001883, one run of 100 at 1.73 cm), orientation 6.05e-05 rad; own-best guide
mean 2.563 cm (median 1.72), 0.1355 rad. The paper's Fig. 5 solution (30.00,
59.16, 44.59, 54.63, 57.92) deg misses the Eq. 16 pose by 0.0021 cm, an accuracy
only the coupled reading reaches.

Defaults (Section 4.1): w=0.8, c1=c2=1.493. The swarms are advanced together
as one (M * pop_size, n_var) array; one batch is evaluated per step.

Readings and deviations:
- The paper keeps only the compromise (Algorithm 2 returns ``Best_q``) and does
  not say how the non-dominated set is stored; here it is the EOSMA paper's
  crowding-radius archive with capacity ``archive_size`` (default
  ``pop_size``), so that fronts compare with MOEOSMA's at equal archive size.
- Evaluations per iteration: ``M (pop_size + 1)`` with the default
  ``switch="mean-position"`` (each swarm evaluates the mean of its personal
  bests, Algorithm 1 of the paper; those points are archived too), else
  ``M pop_size``. The initial population is ``M pop_size`` points.
- Zero initial velocities, velocity clamp ``vmax_rate`` of the box width,
  positions clipped to the bounds (as moik's m-PSO).

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik._validate import choice
from moik.algorithms.mechanics import clip_to_bounds, is_better
from moik.algorithms.moo.base import Step
from moik.algorithms.moo.objective_swarms import (
    ObjectiveSwarms,
    own_objective,
    swarm_best,
    utopia_closest,
)
from moik.algorithms.soo.modified_pso import SWITCHES, mpso_velocity
from moik.algorithms.soo.pso import check_pso_params, clamp_velocity
from moik.exceptions import ParameterError

__all__ = ["GUIDES", "MOMPSO", "own_objective", "swarm_best", "utopia_closest"]

GUIDES = ("compromise", "own-best")
"""The social guide x_g of Eqs. 3-4 (see the module doc)."""


class MOMPSO(ObjectiveSwarms):
    """MO-m-PSO (Rokbani et al. 2022) with array state; ``res.X``/``res.F`` = the archive.

    Extra public arrays (rows of swarm k are ``k N .. (k + 1) N - 1``): ``V``,
    ``pbest_X``/``pbest_F``/``pbest_S`` (personal bests on the swarm's objective), ``S``
    (current fitness on the swarm's objective), ``swarm`` (objective index of
    each row), ``classic`` (particles that moved classically last iteration).
    ``moik.metrics.compromise(res)`` picks the archive member closest to the utopia point.

    Args:
        pop_size: Particles per swarm N (one swarm per objective).
        archive_size: Archive capacity; None means ``pop_size``.
        w: Inertia weight in [0, 1.5] (paper: 0.8).
        c1: Cognitive coefficient in [0, 4] (paper: 1.493).
        c2: Social coefficient in [0, 4] (paper: 1.493).
        vmax_rate: Velocity clamp as a fraction of the box width, in (0, 1], or None.
        switch: "mean-position" (Algorithm 1) or "mean-fitness" (see m-PSO).
        guide: The social guide of every swarm: "compromise" (the archive member
            closest to the utopia point, recomputed every iteration) or "own-best"
            (each swarm's best on its own objective); see the module doc.
        X0: Optional initial points (at most M * pop_size rows).
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 w: float = 0.8, c1: float = 1.493, c2: float = 1.493,
                 vmax_rate: float | None = 0.2, switch: str = "mean-position",
                 guide: str = "compromise", X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0, **kwargs)
        self.w, self.c1, self.c2, self.vmax_rate = check_pso_params(w, c1, c2, vmax_rate)
        if switch not in SWITCHES:
            raise ParameterError(f"switch must be one of {', '.join(SWITCHES)}; got {switch!r}")
        self.switch = switch
        self.guide = choice("guide", guide, GUIDES)

    def _evals_per_iteration(self) -> float:
        extra = 1.0 if self.switch == "mean-position" else 0.0
        return self.problem.n_obj * (self.pop_size + extra)

    def _initialize_state(self) -> None:
        super()._initialize_state()
        self.V = np.zeros_like(self.X)
        self.vmax = None if self.vmax_rate is None else self.vmax_rate * (self.xu - self.xl)
        self.classic = np.ones(len(self.X), dtype=bool)

    def _generation(self) -> Step:
        M, N = self.problem.n_obj, self.pop_size
        if self.switch == "mean-position":
            means = self.pbest_X.reshape(M, N, -1).sum(axis=1) / N
            F_mean, cv_mean = yield means
            f_mean = own_objective(F_mean, np.arange(M))
        else:
            f_mean = self.pbest_S.reshape(M, N).sum(axis=1) / N
            cv_mean = (None if self.CV is None or self.pbest_CV is None
                       else self.pbest_CV.reshape(M, N).sum(axis=1) / N)
        self.classic = is_better(np.repeat(f_mean, N),  # f(x_i) > f(xmean)
                                 None if cv_mean is None else np.repeat(cv_mean, N),
                                 self.S, self.CV)
        g = self._social_guide()
        V = mpso_velocity(self.V, self.X, self.pbest_X, g, self.classic, w=self.w, c1=self.c1,
                          c2=self.c2, rng=self.random_state)  # Eqs. 3-4
        self.V = clamp_velocity(V, self.vmax)
        X = clip_to_bounds(self.X + self.V, self.xl, self.xu)  # Eq. 5
        self._remember(X, *(yield X))

    def _social_guide(self) -> np.ndarray:
        """x_g of Eqs. 3-4 for every row: Best_q of Algorithm 2, or each swarm's own best."""
        if self.guide == "own-best":
            return swarm_best(self.pbest_X, self._pbest_rank(), self.problem.n_obj)
        A = self.pareto_archive
        return A.X[utopia_closest(A.F)]  # broadcast over all rows of all swarms
