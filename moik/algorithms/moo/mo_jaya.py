"""MO-JAYA: one JAYA population per objective and a shared archive.

The MO-JAYA baseline of Rokbani, Neji, Slim, Mirjalili & Ghandour, "A
Multi-Objective Modified PSO for Inverse Kinematics of a 5-DOF Robotic Arm",
Applied Sciences 12, 7091 (2022), DOI 10.3390/app12147091, Section 5.2
(Table 6), built the way the paper builds MO-m-PSO (Section 2.2, Algorithm 2,
:mod:`moik.algorithms.moo.objective_swarms`): population k runs JAYA on objective k alone.

JAYA: Rao, "Jaya: A simple and new optimization algorithm for solving
constrained and unconstrained optimization problems", International Journal
of Industrial Engineering Computations 7, 19-34 (2016),
DOI 10.5267/j.ijiec.2015.8.004:

- Eq. 1: ``X' = X + r1 (X_best - |X|) - r2 (X_worst - |X|)``, r1 and r2 ~ U(0, 1)
  per variable and candidate, ``X_best``/``X_worst`` the best and worst
  candidates of the population (here: of the population's own objective);
- ``X'`` replaces ``X`` only if it is better (greedy acceptance), so the
  population is its own memory (``pbest_X`` here).

Every evaluated candidate of every population is offered to the shared
crowding-radius archive; ``res.X``/``res.F`` are its front and
``moik.metrics.compromise(res)`` picks the member closest to the utopia point (Eq. 8).

Defaults: JAYA has no algorithm-specific parameters ("parameter-less"); the
MO-m-PSO paper gives none. Evaluations: ``M pop_size`` per iteration and for
the initial population.

Readings and deviations:
- The paper names MO-JAYA after Tran Thien et al. (its ref. 38), a
  non-dominated-sorting JAYA, but describes it no further; this is the paper's
  own multi-swarm construction with JAYA, so the three baselines and MO-m-PSO
  differ only in the single-objective rule.
- The JAYA kernel lives here (moik has no single-objective JAYA module yet).
- Coordinates outside the box are clipped to the bounds (as Rao's code does).
- Archive: the EOSMA paper's crowding-radius archive, capacity ``archive_size``
  (default ``pop_size``), as for MO-m-PSO.

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import Step
from moik.algorithms.moo.objective_swarms import ObjectiveSwarms, swarm_extreme
from moik.algorithms.soo.jaya import jaya_update


class MOJAYA(ObjectiveSwarms):
    """MO-JAYA (JAYA per objective, Rokbani et al. 2022); ``res.F`` = the archive.

    The JAYA populations are ``pbest_X``/``pbest_S`` (greedy acceptance);
    ``X``/``F`` are the last evaluated candidates. See :class:`ObjectiveSwarms`.

    Args:
        pop_size: Candidates per population N (one population per objective).
        archive_size: Archive capacity; None means ``pop_size``.
        X0: Optional initial points (at most M * pop_size rows).
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0, **kwargs)

    def _generation(self) -> Step:
        M = self.problem.n_obj
        S = self._pbest_rank()
        best = swarm_extreme(self.pbest_X, S, M)
        worst = swarm_extreme(self.pbest_X, S, M, worst=True)
        X = jaya_update(self.pbest_X, best, worst, rng=self.random_state)  # Eq. 1
        X = clip_to_bounds(X, self.xl, self.xu)
        self._remember(X, *(yield X))  # greedy acceptance
