"""MOPSO-CD: pymoo's, with constraint handling.

Raquel & Naval, "An effective use of crowding distance in multiobjective
particle swarm optimization", GECCO 2005, DOI 10.1145/1068009.1068047, as
implemented by pymoo 0.6 (``pymoo.algorithms.moo.mopso_cd.MOPSO_CD``).

pymoo's implementation compares objective vectors only: on a constrained
problem its archive keeps infeasible points that dominate feasible ones in F,
and ``res.F`` then mixes feasible and infeasible members (measured on OSY: 1 of
63 members feasible). :class:`MOPSOCD` keeps pymoo's algorithm and adds
constraint-domination where it compares points (feasible first, then smaller
total violation, then Pareto dominance), as the Raquel & Naval paper does for
its constrained test problems:

- the archive update keeps the constraint-non-dominated points
  (:func:`~moik.algorithms.archive.constrained_nondominated_mask`: the feasible
  non-dominated ones, or the least infeasible ones while none is feasible)
  before pymoo's crowding-distance truncation;
- the personal best is replaced by a new position that constraint-dominates
  it, kept if it constraint-dominates the new one, and otherwise decided by
  pymoo's crowding rule.

Unconstrained problems run pymoo's code unchanged (bit for bit). Seeding is
pymoo's: ``Algorithm.setup`` rebuilds ``random_state`` from the run's seed
before the swarm is sampled, so a seed gives one run (checked by the registry's
determinism test; pymoo's ``__init__`` builds a random state from ``seed=None``
too, which ``setup`` replaces). pymoo's ``__init__`` also overwrites a
``termination`` given to the constructor with its default termination; here
the given one is kept.
"""

from __future__ import annotations

import numpy as np
from pymoo.algorithms.moo.mopso_cd import MOPSO_CD
from pymoo.core.population import Population

from moik.algorithms.archive import constrained_nondominated_mask
from moik.algorithms.array_state import refuse_unknown_keywords
from moik.algorithms.moo.dominance import constrained_dominates


class MOPSOCD(MOPSO_CD):
    """pymoo's MOPSO-CD with constraint-domination in its archive and personal bests.

    Takes pymoo's ``MOPSO_CD`` options (``pop_size``, ``w``, ``c1``, ``c2``,
    ``max_velocity_rate``, ``archive_size``, ``sampling``) and pymoo ``Algorithm``
    options.

    Raises:
        ParameterError: For a keyword pymoo's ``MOPSO_CD`` does not take (listing the
            accepted ones).
    """

    def __init__(self, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        super().__init__(**kwargs)
        if kwargs.get("termination") is not None:
            self.termination = kwargs["termination"]  # pymoo's __init__ replaced it

    def _update_archive(self, pop):
        if not self.problem.has_constraints() or len(pop) == 0:
            return super()._update_archive(pop)
        archive = self.archive
        combined = Population.merge(archive, pop) if archive is not None and len(archive) else pop
        keep = constrained_nondominated_mask(combined.get("F"), combined.get("CV")[:, 0])
        self.archive = Population.empty()  # pymoo merges self.archive with what it is given
        return super()._update_archive(combined[keep])

    def _update_pbest(self, new_pop) -> None:
        if not self.problem.has_constraints():
            super()._update_pbest(new_pop)
            return
        for i in range(len(new_pop)):
            new_f, new_cv = new_pop[i].F[None, :], new_pop[i].CV
            old_f, old_cv = self.pbest_f[i][None, :], self.pbest[i].CV
            if constrained_dominates(new_f, new_cv, old_f, old_cv)[0]:
                self.pbest[i], self.pbest_f[i] = new_pop[i].copy(), new_pop[i].F.copy()
            elif not constrained_dominates(old_f, old_cv, new_f, new_cv)[0]:
                crowding = self.cd.do(np.vstack([old_f, new_f]))  # pymoo's tie rule
                if crowding[1] > crowding[0]:
                    self.pbest[i], self.pbest_f[i] = new_pop[i].copy(), new_pop[i].F.copy()
