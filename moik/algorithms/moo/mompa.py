"""MOMPA: multi-objective marine predators algorithm with an external archive.

Zhong, Zhou, Deng, Zhou & Luo, "MOMPA: Multi-objective marine predator
algorithm", Computer Methods in Applied Mechanics and Engineering 385, 114029
(2021), DOI 10.1016/j.cma.2021.114029 (the MOMPA of the EOSMA paper, Yin et
al. 2022, DOI 10.1038/s41598-022-13516-3, its ref. 54 and Table 4). MPA's
operators (Faramarzi et al. 2020, DOI 10.1016/j.eswa.2020.113377,
:mod:`moik.algorithms.soo.mpa`: Eqs. 12-15 phase moves, Eq. 16 FADs / eddy
formation, marine memory) with the non-dominated solutions kept in an
external archive that supplies the top predator:

- archive (Mirjalili's crowding-radius archive,
  :meth:`~moik.algorithms.archive.CrowdingArchive.mirjalili`: radius
  ``range / 20``, overflow removed by roulette on the crowding count),
  capacity ``archive_size``; every evaluated prey is offered to it;
- Elite (Eq. 10): the top predator of the iteration is an archive member drawn
  by roulette on ``1 / count`` (less crowded likelier), repeated in every row;
- marine memory with Pareto dominance: a prey keeps its previous position only
  if that dominates the new one (:func:`~moik.algorithms.moo.dominance.dominance_memory`;
  constraint-domination for constrained problems);
- the phase move (Eqs. 12-15) and the FADs step (Eq. 16) are each followed by
  an evaluation and the memory, as in MPA.

Defaults (EOSMA Table 4): P=0.5, FADs=0.2, N = archive = 100. Evaluations:
2N per iteration.

Deviations and readings:
- The archive details (radius divisor 20, roulette leader on 1/count) follow
  the MSSA/MOALO archive code of Mirjalili that this group's multi-objective
  ports share; the EOSMA paper's Table 4 lists only P and FADs.
- One top predator per iteration (the Elite matrix repeats one predator, Eq. 10);
  it is redrawn from the archive before the phase move.
- Coordinates are clipped to the bounds (as in MPA's code); the other readings
  of moik's MPA (phase boundaries, one FADs branch per iteration) apply.
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import MOArrayAlgorithm, Step
from moik.algorithms.moo.dominance import dominance_memory
from moik.algorithms.soo.mpa import fads_effect, mpa_cf, mpa_phase, predator_move


def top_predator(archive: ArchiveBase, *, rng: np.random.Generator) -> np.ndarray:
    """The top predator (Eq. 10) drawn from the archive by its leader rule, shape (d,)."""
    return archive.X[archive.leaders(1, rng=rng)[0]]


class MOMPA(MOArrayAlgorithm):
    """MOMPA (Zhong et al. 2021) with array state; ``res.X``/``res.F`` = the archive.

    Extra public arrays: ``elite`` (top predator of the last iteration).
    ``X``/``F``/``CV`` is the prey matrix after marine memory.

    Args:
        pop_size: Number of search agents N (Table 4: 100).
        archive_size: Archive capacity; None means ``pop_size`` (Table 4: 100).
        P: Step constant in (0, 2] (Table 4: 0.5).
        FADs: Fish-aggregating-devices probability in [0, 1] (Table 4: 0.2).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 P: float = 0.5, FADs: float = 0.2, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.P = interval("P", P, 0.0, 2.0, lo_open=True)
        self.FADs = interval("FADs", FADs, 0.0, 1.0)

    def _make_archive(self, capacity: int) -> ArchiveBase:
        return CrowdingArchive.mirjalili(capacity)

    def _evals_per_iteration(self) -> float:
        return 2.0 * self.pop_size

    def _initialize_state(self) -> None:
        self.elite = top_predator(self.pareto_archive, rng=self.random_state)

    def _generation(self) -> Step:
        rng = self.random_state
        self.elite = top_predator(self.pareto_archive, rng=rng)  # Eq. 10
        CF = mpa_cf(self.t, self.max_iter)
        phase = mpa_phase(self.t, self.max_iter)
        X = predator_move(self.X, self.elite, phase, CF, P=self.P, rng=rng)  # Eqs. 12-15
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = dominance_memory(X, F, CV, self.X, self.F, self.CV)  # memory
        X = fads_effect(self.X, CF, FADs=self.FADs, xl=self.xl, xu=self.xu, rng=rng)  # Eq. 16
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = dominance_memory(X, F, CV, self.X, self.F, self.CV)
