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
  pymoo's crowding rule;
- while the archive holds no feasible point (and the initial swarm had none), each
  iteration is followed by one generation of the feasibility search
  (:mod:`moik.algorithms.moo.feasibility_search`, a moik extension: a companion DE
  population minimising the violation, its trials added to the archive), within the
  evaluation budget.

Seeding. pymoo's MOPSO-CD keeps its swarm archive in ``self.archive``, the name
pymoo's ``Algorithm`` uses for its optional archive of every evaluated point: after
each iteration ``Algorithm.advance`` calls ``self.archive = self.archive.add(infills)``
(pymoo/core/algorithm.py), and ``Archive.add`` truncates a full archive (more than
``archive_size`` non-dominated members) to 100 with ``RandomTruncation()``, which
draws from ``default_rng(None)``, OS entropy (pymoo/util/archive.py): runs with one
seed differed once the archive filled (ZDT1, 20,000 evaluations). Here the swarm
archive (:class:`SwarmArchive`) truncates with the algorithm's ``random_state``
instead (:class:`SeededTruncation`, the same draw as pymoo's), so a seed gives one run, in
one process and across processes; everything else about the archive stays pymoo's.
(``Algorithm.setup`` rebuilds ``random_state`` from the run's seed before the swarm
is sampled; pymoo's ``__init__`` builds one from ``seed=None``, which ``setup``
replaces.)

A ``sampling=`` array or ``Population`` reaches pymoo's code as a ``Sampling`` of the
points (:class:`~moik.algorithms.array_state.GivenPoints`: evaluated individuals are not
evaluated again); more points than ``pop_size`` are all evaluated and offered to the
archive, and NSGA-II's rank and crowding keeps the swarm
(:func:`~moik.algorithms.initial_survival.rank_and_crowding_rows`).

Non-finite values. A row whose objectives (or, with constraints, total violation)
are NaN or infinite is a fact about that point, not a member: it enters neither the
archive nor a personal best (pymoo's code would let an archive hold it, or, with the
constraint filter, leave the archive a plain empty ``Population``: the
``'Population' object has no attribute 'add'`` of MW11). Unconstrained problems with
finite values run pymoo's code unchanged (bit for bit, up to the seeded
truncation). pymoo's ``__init__`` also overwrites a ``termination`` given to the
constructor with its default termination; here the given one is kept.
"""

from __future__ import annotations

import numpy as np
from pymoo.algorithms.moo.mopso_cd import MOPSO_CD
from pymoo.core.population import Population
from pymoo.util.archive import MultiObjectiveArchive, Truncation

from moik._validate import integer, number, positive
from moik.algorithms.archive import constrained_nondominated_mask
from moik.algorithms.array_state import (
    GivenPoints,
    budget_left,
    find_limit,
    refuse_unknown_keywords,
)
from moik.algorithms.initial_survival import rank_and_crowding_rows
from moik.algorithms.meta import setup_through_wrapper
from moik.algorithms.moo.dominance import constrained_dominates
from moik.algorithms.moo.feasibility_search import start_search


class SeededTruncation(Truncation):
    """pymoo's ``RandomTruncation`` drawing from an algorithm's ``random_state`` (module doc).

    Args:
        algorithm: The algorithm whose ``random_state`` (read at each call, so the one
            ``setup`` made) draws the members kept.
    """

    def __init__(self, algorithm) -> None:
        self.algorithm = algorithm

    def __call__(self, sols, k):
        return self.algorithm.random_state.choice(sols, size=k, replace=False)


def finite_rows(pop: Population, constrained: bool) -> np.ndarray:
    """Rows of ``pop`` whose F (and CV when ``constrained``) are all finite."""
    ok = np.isfinite(pop.get("F")).all(axis=1)
    if constrained:
        ok &= np.isfinite(pop.get("CV")[:, 0])
    return ok


class SwarmArchive(MultiObjectiveArchive):
    """pymoo's ``MultiObjectiveArchive`` that never keeps a non-finite row (module doc).

    ``Algorithm.advance`` adds every iteration's infills to it (``add`` keeps the class);
    build it with ``truncation=SeededTruncation(algorithm)``.
    """

    def _find_opt(self, sols):
        ok = np.isfinite(sols.get("F")).all(axis=1) & np.isfinite(sols.get("cv"))
        return super()._find_opt(sols[ok]) if ok.any() else sols[ok]


class MOPSOCD(MOPSO_CD):
    """pymoo's MOPSO-CD with constraint-domination in its archive and personal bests.

    Takes pymoo's ``MOPSO_CD`` options (``pop_size``, ``w``, ``c1``, ``c2``,
    ``max_velocity_rate``, ``archive_size``, ``sampling``) and pymoo ``Algorithm``
    options.

    Raises:
        ParameterError: For a keyword pymoo's ``MOPSO_CD`` does not take (listing the
            accepted ones), or a size that is not a positive integer, a coefficient that is
            not a finite number or a velocity rate that is not positive (pymoo checks none).
    """

    def __init__(self, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        for size in ("pop_size", "archive_size"):
            if size in kwargs:
                integer(size, kwargs[size], minimum=1)
        for coefficient in ("w", "c1", "c2"):
            if coefficient in kwargs:
                number(coefficient, kwargs[coefficient])
        if "max_velocity_rate" in kwargs:
            positive("max_velocity_rate", kwargs["max_velocity_rate"])
        if isinstance(kwargs.get("sampling"), (np.ndarray, list, tuple, Population)):
            kwargs["sampling"] = GivenPoints(kwargs["sampling"])  # pymoo's MOPSO_CD: a Sampling
        super().__init__(**kwargs)
        if kwargs.get("termination") is not None:
            self.termination = kwargs["termination"]  # pymoo's __init__ replaced it

    def setup(self, problem, **kwargs):
        """pymoo's, also inside a wrapper that skips ``_setup`` (:mod:`moik.algorithms.meta`)."""
        setup_through_wrapper(self, super().setup, problem, **kwargs)
        return self

    def _setup(self, problem, **kwargs) -> None:
        self._problem_read = True
        super()._setup(problem, **kwargs)

    def _initialize_advance(self, infills=None, **kwargs):
        """pymoo's, after NSGA-II's survival cut a larger ``sampling=`` to ``pop_size``
        (the other points are offered to the archive)."""
        if infills is None or len(infills) <= self.pop_size:
            super()._initialize_advance(infills, **kwargs)
        else:
            kept = rank_and_crowding_rows(infills.get("F"), infills.get("CV")[:, 0],
                                          self.pop_size)
            rest = np.setdiff1d(np.arange(len(infills)), kept)
            super()._initialize_advance(infills[kept], **kwargs)
            self.archive = self._update_archive(infills[rest])
        CV = infills.get("CV")[:, 0] if self.problem.has_constraints() else None
        self._feasibility = start_search(infills.get("X"), CV, self.pop_size)

    def _advance(self, infills=None, **kwargs):
        """pymoo's iteration, then one generation of the feasibility search while the
        archive holds no feasible member (module doc)."""
        super()._advance(infills, **kwargs)
        search = self.__dict__.get("_feasibility")
        if search is None:
            return
        if bool(np.any(self.archive.get("CV")[:, 0] <= 0)) or bool(np.any(search.CV <= 0)):
            self._feasibility = None
            return
        U = search.trials(self.problem.xl, self.problem.xu, self.random_state)
        n = budget_left(find_limit(self.termination, "n_max_evals"), self.evaluator.n_eval,
                        len(U))
        CV = np.full(len(U), np.inf)  # rows past the budget: unevaluated, they lose
        if n:
            pop = Population.new("X", U[:n])
            self.evaluator.eval(self.problem, pop, algorithm=self)
            self.archive = self._update_archive(pop)
            CV[:n] = np.where(finite_rows(pop, True), pop.get("CV")[:, 0], np.inf)
        search.select(U, CV)

    def _update_archive(self, pop):
        constrained = self.problem.has_constraints()
        pop = pop[finite_rows(pop, constrained)] if len(pop) else pop
        if len(pop) == 0:
            archive = self.archive
        elif not constrained:
            archive = super()._update_archive(pop)
        else:
            combined = Population.merge(self.archive, pop) if len(self.archive) else pop
            keep = constrained_nondominated_mask(combined.get("F"), combined.get("CV")[:, 0])
            self.archive = Population.empty()  # pymoo merges self.archive with what it is given
            archive = super()._update_archive(combined[keep])
        return SwarmArchive(individuals=archive, max_size=self.archive_size,
                            truncation=SeededTruncation(self))

    def _update_pbest(self, new_pop) -> None:
        constrained = self.problem.has_constraints()
        finite = finite_rows(new_pop, constrained)
        if not constrained and finite.all():
            super()._update_pbest(new_pop)
            return
        for i in np.flatnonzero(finite):
            new_f, old_f = new_pop[i].F[None, :], self.pbest_f[i][None, :]
            new_cv = new_pop[i].CV if constrained else None
            old_cv = self.pbest[i].CV if constrained else None
            old_finite = np.isfinite(old_f).all() and np.isfinite(
                0.0 if old_cv is None else old_cv).all()
            if not old_finite or constrained_dominates(new_f, new_cv, old_f, old_cv)[0]:
                self.pbest[i], self.pbest_f[i] = new_pop[i].copy(), new_pop[i].F.copy()
            elif not constrained_dominates(old_f, old_cv, new_f, new_cv)[0]:
                crowding = self.cd.do(np.vstack([old_f, new_f]))  # pymoo's tie rule
                if crowding[1] > crowding[0]:
                    self.pbest[i], self.pbest_f[i] = new_pop[i].copy(), new_pop[i].F.copy()
