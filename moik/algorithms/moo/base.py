"""MOArrayAlgorithm: the multi-objective array-state base (a Pareto archive as incumbent).

The generation driver, the evaluation path, the schedule rule and the lazily built pymoo
objects are those of :class:`moik.algorithms.array_base.ArrayStateAlgorithm` (shared
with the single-objective :class:`moik.algorithms.base.ArrayAlgorithm`). Every evaluated
row is offered to an external archive of non-dominated solutions (``pareto_archive``, a
:class:`~moik.algorithms.archive.CrowdingArchive` with capacity ``pop_size`` by
default), in one merge per iteration (:class:`~moik.algorithms.incumbent.ParetoIncumbent`).
The result is the archive: ``res.X``/``res.F``/``res.opt`` are its members, built as a
``Population`` when read.

A subclass writes one iteration as a generator ``_generation()`` that yields
candidate arrays ``X`` (k, n_var) and receives ``(F, CV)`` for them: their
objectives (k, n_obj) and total constraint violations (k,), ``CV`` None for
unconstrained problems. ``next()`` (used by ``minimize``) evaluates them
directly; ``ask()/tell()`` hand the same candidates out as ``Population``
objects (one ``ask()/tell()`` round per yield); both give identical runs.

Constraints: every comparison is constraint-domination
(:mod:`moik.algorithms.moo.dominance`; feasible first, then smaller total
violation ``sum(max(G, 0)) + sum(max(|H| - 1e-4, 0))``, then Pareto dominance), in
the archive, the memories and the rankings of each algorithm. The archive holds
only feasible members once one feasible point was found; before that, the
least infeasible ones, which ``res.opt`` carries with their ``CV`` so that pymoo's
``Result`` reports no solution (``res.X``/``res.F`` None) unless
``return_least_infeasible=True``. ``res.G``/``res.H`` are the members' constraint values.

Schedules and budgets follow the one rule of the array-state base
(:mod:`moik.algorithms.array_base`).

Feasibility search (a moik extension, :mod:`moik.algorithms.moo.feasibility_search`):
on a constrained problem whose initial population holds no feasible point, every
iteration is followed by DE generations (about as many evaluations as the iteration's) of
a companion population that minimises the violation alone, its trials offered to the
archive, until the archive holds a feasible member; then the method runs as published.
Unconstrained runs, and constrained runs that start with a feasible point, never start it.

``verbose=True`` prints pymoo's ``MultiObjectiveOutput`` columns (n_nds = archive
size, cv_min/cv_avg with constraints, igd/gd/hv when the problem knows its front,
else eps/indicator).

The archive attribute is not called ``archive``: pymoo's ``Algorithm`` uses that
name for its own ``pymoo.util.archive.Archive`` (``res.archive``).
"""

from __future__ import annotations

from typing import cast

import numpy as np
from pymoo.util.display.multi import MultiObjectiveOutput

from moik._validate import optional_integer
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.array_base import ArrayStateAlgorithm
from moik.algorithms.array_state import DEFAULT_SCHEDULE_LENGTH, Step
from moik.algorithms.incumbent import ParetoIncumbent
from moik.algorithms.initial_survival import rank_and_crowding_rows
from moik.algorithms.moo.dominance import (
    constrained_dominates,
    dominance_memory,
    dominates,
    pareto_memory,
)
from moik.algorithms.moo.feasibility_search import FeasibilitySearch, start_search
from moik.exceptions import NonFiniteError, ParameterError

__all__ = ["DEFAULT_SCHEDULE_LENGTH", "MOArrayAlgorithm", "MOArrayOutput", "Step",
           "constrained_dominates", "dominance_memory", "dominates", "pareto_memory"]


class MOArrayOutput(MultiObjectiveOutput):
    """``verbose=True`` columns: pymoo's ``MultiObjectiveOutput`` (n_gen, n_eval, n_nds =
    archive size, cv_min/cv_avg with constraints, igd/gd/hv when the problem's
    ``pareto_front()`` is known, else eps/indicator)."""


class MOArrayAlgorithm(ArrayStateAlgorithm):
    """Base of moik's multi-objective population algorithms (array state, external archive).

    Public attributes for callbacks (numpy; read, do not mutate): ``X``/``F``/``CV``
    (last evaluated candidates, their objectives and violations; ``CV`` None without
    constraints), ``pareto_archive`` (its ``X``, ``F``, ``CV``, ``counts``), ``t``
    (iteration of the paper's schedule) and ``max_iter`` (its length T), plus the
    arrays each algorithm documents.

    Args:
        pop_size: Population size N (per swarm for multi-swarm methods).
        archive_size: Archive capacity; None means ``pop_size`` (the papers).
        X0: Optional initial points (k rows within the bounds); the other rows are drawn
            uniformly, or, with more rows than the initial population, all are offered to
            the archive and the algorithm's ranking keeps the population
            (:meth:`_initial_survivors`).
        max_iter: Schedule length T (update iterations after initialization, the
            papers' Max_t; ``t = 1 .. T``), fixed. None: planned before every iteration from
            the current termination (:mod:`moik.algorithms.array_base`), else
            :data:`DEFAULT_SCHEDULE_LENGTH`.
        **kwargs: pymoo ``Algorithm`` options (``output``, ``callback``, ``seed`` ...,
            :data:`~moik.algorithms.array_state.PYMOO_OPTIONS`).

    Raises:
        ParameterError: For a keyword that is neither a parameter of the algorithm nor
            a pymoo option (the message lists the accepted ones), or a bad size.
    """

    incumbent: ParetoIncumbent
    _feasibility: FeasibilitySearch | None

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 X0: np.ndarray | None = None, max_iter: int | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        archive_size = optional_integer("archive_size", archive_size, minimum=1)
        self.archive_size = self.pop_size if archive_size is None else archive_size

    @property
    def pareto_archive(self) -> ArchiveBase:
        """The external archive (None before the initial population)."""
        return cast(ArchiveBase, None) if self.incumbent is None else self.incumbent.archive

    def _default_output(self) -> MultiObjectiveOutput:
        return MOArrayOutput()

    def _check_objectives(self, problem) -> None:
        if problem.n_obj < 2:
            raise ParameterError(f"{type(self).__name__} is multi-objective; the problem has "
                                 f"n_obj={problem.n_obj}")

    def _make_incumbent(self) -> ParetoIncumbent:
        return ParetoIncumbent(self._make_archive(self.archive_size))

    def _initial_survivors(self, F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
        """NSGA-II's survival: constrained non-dominated rank, then crowding
        (:func:`~moik.algorithms.initial_survival.rank_and_crowding_rows`); every row was
        offered to the archive first."""
        return rank_and_crowding_rows(F, CV, self._n_initial())

    def _iteration(self) -> Step:
        """The method's iteration, then generations of the feasibility search while the run
        has found nothing feasible (module doc)."""
        yield from self._generation()
        search = self.__dict__.get("_feasibility")
        if search is None:
            return
        rounds = max(1, round(self._evals_per_iteration() / len(search.X)))
        for _ in range(rounds):  # about as many evaluations as the method's iteration
            CV = self.pareto_archive.CV
            if CV is None or bool(np.any(CV <= 0)) or bool(np.any(search.CV <= 0)):
                self._feasibility = None  # found: the method runs as published from here on
                break
            U = search.trials(self.xl, self.xu, self.random_state)
            _, CVU = yield U
            search.select(U, CVU)
        self._plan_again()  # T from the evaluations left

    def _check_start(self) -> None:
        self._feasibility = start_search(self.X, self.CV, self.pop_size)
        if len(self.pareto_archive) == 0:
            raise NonFiniteError(
                f"{type(self.problem).__name__} returned NaN or infinite values at every one of "
                f"the {len(self.F)} points of the initial population; {type(self).__name__} "
                f"needs at least one point with finite values to start its archive")

    # ---- subclass interface ---------------------------------------------------------------
    def _make_archive(self, capacity: int) -> ArchiveBase:
        """The external archive (MOEOSMA's crowding-radius archive by default)."""
        return CrowdingArchive.moeosma(capacity)
