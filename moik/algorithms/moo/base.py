"""MOArrayAlgorithm: the array-state pymoo ``Algorithm`` of moik's multi-objective methods.

The multi-objective twin of :class:`moik.algorithms.base.ArrayAlgorithm` (see
design.md): the population, its objective rows and every per-algorithm array
stay numpy arrays; ``problem.evaluate`` is called on whole batches and
``evaluator.n_eval`` is kept exact. Every evaluated row is offered to an
external archive of non-dominated solutions (``pareto_archive``, a
:class:`~moik.algorithms.archive.CrowdingArchive` with capacity ``pop_size`` by
default), in one merge per iteration (``_flush``). The result is the archive:
``res.X``/``res.F``/``res.opt`` are its members, built as a ``Population`` when read.

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

Schedules: the length T of the papers' t/T schedules (``max_iter``) is fixed when
given; otherwise it is re-planned before every iteration from the algorithm's
*current* termination (:func:`~moik.algorithms.array_state.planned_iterations`:
``n_gen``, ``n_eval``, ``time``, pymoo's default and robust terminations and their
combinations), so t/T spans the real budget, also after a checkpoint is resumed
with a new termination; 1000 when no criterion bounds the run.

``n_eval`` budgets are exact: rows of a batch beyond the budget are not
evaluated, get ``F = CV = inf`` (never accepted by a memory, never archived). The
initial population is always evaluated in full.

``verbose=True`` prints pymoo's ``MultiObjectiveOutput`` columns (n_nds = archive
size, cv_min/cv_avg with constraints, igd/gd/hv when the problem knows its front,
else eps/indicator).

The archive attribute is not called ``archive``: pymoo's ``Algorithm`` uses that
name for its own ``pymoo.util.archive.Archive`` (``res.archive``).
"""

from __future__ import annotations

import math
import time
from typing import cast

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.population import Population
from pymoo.util.display.multi import MultiObjectiveOutput

from moik._validate import optional_integer
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.array_state import (
    ArrayStateMixin,
    Step,
    budget_left,
    check_sizes,
    find_limit,
    finite_bounds,
    initial_population,
    planned_iterations,
    refuse_unknown_keywords,
)
from moik.algorithms.mechanics import constraint_violation
from moik.algorithms.moo.dominance import (
    constrained_dominates,
    dominance_memory,
    dominates,
    pareto_memory,
)
from moik.algorithms.nonfinite import finite_rows
from moik.exceptions import NonFiniteError, ParameterError

DEFAULT_SCHEDULE_LENGTH = 1000
"""T when neither ``max_iter`` nor any termination criterion bounds the run."""

__all__ = ["DEFAULT_SCHEDULE_LENGTH", "MOArrayAlgorithm", "MOArrayOutput", "Step",
           "constrained_dominates", "dominance_memory", "dominates", "pareto_memory"]


class MOArrayOutput(MultiObjectiveOutput):
    """``verbose=True`` columns: pymoo's ``MultiObjectiveOutput`` (n_gen, n_eval, n_nds =
    archive size, cv_min/cv_avg with constraints, igd/gd/hv when the problem's
    ``pareto_front()`` is known, else eps/indicator)."""


class MOArrayAlgorithm(ArrayStateMixin, Algorithm):
    """Base of moik's multi-objective population algorithms (array state, external archive).

    Public attributes for callbacks (numpy; read, do not mutate): ``X``/``F``/``CV``
    (last evaluated candidates, their objectives and violations; ``CV`` None without
    constraints), ``pareto_archive`` (its ``X``, ``F``, ``CV``, ``counts``), ``t``
    (iteration of the paper's schedule) and ``max_iter`` (its length T), plus the
    arrays each algorithm documents.

    Args:
        pop_size: Population size N (per swarm for multi-swarm methods).
        archive_size: Archive capacity; None means ``pop_size`` (the papers).
        X0: Optional initial points (k rows within the bounds, k at most the
            initial population); the other rows are drawn uniformly.
        max_iter: Schedule length T (update iterations after initialization, the
            papers' Max_t; ``t = 1 .. T``), fixed. None: planned before every iteration from
            the current termination (see the module doc), else
            :data:`DEFAULT_SCHEDULE_LENGTH`.
        **kwargs: pymoo ``Algorithm`` options (``output``, ``callback``, ``seed`` ...,
            :data:`~moik.algorithms.array_state.PYMOO_OPTIONS`).

    Raises:
        ParameterError: For a keyword that is neither a parameter of the algorithm nor
            a pymoo option (the message lists the accepted ones), or a bad size.
    """

    min_pop_size = 2

    # pymoo's life cycle: X, F, pareto_archive and max_iter are set from setup() on (None, or
    # the max_iter given, before); the types are those of the run (callbacks, _generation)
    X: np.ndarray
    F: np.ndarray
    CV: np.ndarray | None
    pareto_archive: ArchiveBase
    max_iter: int

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 X0: np.ndarray | None = None, max_iter: int | None = None, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        kwargs.setdefault("output", MOArrayOutput())
        super().__init__(**kwargs)
        self.pop_size, self._fixed_T = check_sizes(pop_size, self.min_pop_size, max_iter)
        self.max_iter = cast(int, self._fixed_T)  # None: planned in setup() (_plan_schedule)
        archive_size = optional_integer("archive_size", archive_size, minimum=1)
        self.X0 = X0
        self.archive_size = self.pop_size if archive_size is None else archive_size
        self.X = self.F = cast(np.ndarray, None)  # set by setup() (the initial population)
        self.CV = None
        self.pareto_archive = cast(ArchiveBase, None)  # made by setup() (_make_archive)
        self.t = 0

    # ---- lazily built pymoo objects (ArrayStateMixin) -------------------------------------
    def _build_pop(self) -> Population:
        X, F, CV = self._population_arrays()
        cv = np.zeros(len(F)) if CV is None else CV
        return Population.new("X", X, "F", F, "CV", cv[:, None])

    def _build_opt(self) -> Population:
        """The archive members as a ``Population`` (with CV, G and H for constrained problems)."""
        A = self.pareto_archive
        args = ["X", A.X.copy(), "F", A.F.copy()]
        if A.CV is None:
            return Population.new(*args, "CV", np.zeros((len(A), 1)))
        n_ieq, GH = self.problem.n_ieq_constr, A.extra
        assert GH is not None  # constrained runs store G and H with every member
        args += ["CV", A.CV[:, None].copy(), "G", GH[:, :n_ieq].copy(),
                 "H", GH[:, n_ieq:].copy()]
        return Population.new(*args)

    # ---- pymoo hooks ----------------------------------------------------------------------
    def _setup(self, problem, **kwargs) -> None:
        name = type(self).__name__
        if problem.n_obj < 2:
            raise ParameterError(f"{name} is multi-objective; the problem has "
                                 f"n_obj={problem.n_obj}")
        self.xl, self.xu = finite_bounds(problem, name)
        self._constrained = bool(problem.has_constraints())
        self._plans: dict = {}
        self._plan_schedule(t=1, n_eval=self._n_initial(), elapsed=0.0)

    def _plan_schedule(self, *, t: int, n_eval: int, elapsed: float) -> None:
        """Refresh the evaluation budget and T from the current termination (module doc)."""
        self._max_evals = find_limit(self.termination, "n_max_evals")
        if self._fixed_T is None:
            T = planned_iterations(self.termination, t=t, n_eval=n_eval, elapsed=elapsed,
                                   per_iteration=self._evals_per_iteration(), plans=self._plans)
            self.max_iter = int(T) if math.isfinite(T) else max(DEFAULT_SCHEDULE_LENGTH, t)

    def _begin_iteration(self) -> None:
        """Before an iteration's first batch: t and the planned schedule."""
        self.t = self.n_iter - 1
        self._plan_schedule(t=self.t, n_eval=self.evaluator.n_eval,
                            elapsed=time.time() - self.start_time)

    def next(self) -> None:
        if self.is_initialized and self._step is None:
            self._begin_iteration()
        super().next()

    def _infill(self) -> Population:
        if self._step is None:
            self._begin_iteration()
        return super()._infill()

    def _initialize_infill(self) -> Population:
        return initial_population(self._n_initial(), self.xl, self.xu, self.X0,
                                  rng=self.random_state)

    def _initialize_advance(self, infills=None, **kwargs) -> None:
        self._step = self._pending = None
        self.pareto_archive = self._make_archive(self.archive_size)
        X = infills.get("X")
        F, CV, GH = self._values_of(infills)
        self._buffer: list[tuple[np.ndarray, np.ndarray, np.ndarray | None,
                                 np.ndarray | None]] = []
        self._receive(X, F, CV, GH)
        self._flush()
        if len(self.pareto_archive) == 0:
            raise NonFiniteError(
                f"{type(self.problem).__name__} returned NaN or infinite values at every one of "
                f"the {len(F)} points of the initial population; {type(self).__name__} needs "
                f"at least one point with finite values to start its archive")
        self.X, self.F, self.CV = X, F, CV
        self._initialize_state()

    def _end_iteration(self) -> None:
        """Merge the iteration's evaluated rows into the archive."""
        self._flush()

    def _advance(self, infills=None, **kwargs) -> bool:
        assert self._step is not None and self._pending is not None  # an iteration is open
        F, CV, GH = self._values_of(infills)
        self._receive(self._pending[: len(F)], F, CV, GH)
        try:
            self._pending = self._step.send(self._pad(len(self._pending), F, CV))
            return False
        except StopIteration:
            self._step = self._pending = None
            self._flush()
            return True

    def _post_advance(self) -> None:
        self._pop_stale = True
        super()._post_advance()

    # ---- evaluation -----------------------------------------------------------------------
    def _values_of(self, pop: Population):
        """``(F, CV, GH)`` of an evaluated ``Population`` (GH: G and H side by side)."""
        if not len(pop):
            n_con = self.problem.n_ieq_constr + self.problem.n_eq_constr
            return (np.empty((0, self.problem.n_obj)),
                    np.empty(0) if self._constrained else None, np.empty((0, n_con)))
        F, X = pop.get("F").astype(float), pop.get("X")
        if not self._constrained:
            return self._sanitise(X, F, None) + (None,)
        F, CV, GH = self._constraint_values(F, pop.get("G"), pop.get("H"))
        return self._sanitise(X, F, CV) + (GH,)

    def _constraint_values(self, F, G, H):
        n = len(F)
        G = np.zeros((n, 0)) if G is None else np.asarray(G, float).reshape(n, -1)
        H = np.zeros((n, 0)) if H is None else np.asarray(H, float).reshape(n, -1)
        return F, constraint_violation(G, H), np.concatenate([G, H], axis=1)

    def _pad(self, n: int, F: np.ndarray, CV: np.ndarray | None):
        """Rows left unevaluated by the budget get ``F = CV = inf``."""
        k = len(F)
        if k == n:
            return F, CV
        F = np.concatenate([F, np.full((n - k, self.problem.n_obj), np.inf)])
        return F, None if CV is None else np.concatenate([CV, np.full(n - k, np.inf)])

    def _evaluate(self, X: np.ndarray):
        """Evaluate a batch (vectorized), count n_eval exactly, offer it to the archive.

        Returns:
            ``(F, CV)`` for every row of ``X`` (see ``_pad``).
        """
        n = len(X)
        k = budget_left(self._max_evals, self.evaluator.n_eval, n)
        if k == 0:
            return self._pad(n, np.empty((0, self.problem.n_obj)),
                             np.empty(0) if self._constrained else None)
        out = self._problem_values(X if k == n else X[:k])
        self.evaluator.n_eval += k
        F, CV, GH = (out["F"], None, None) if not self._constrained else \
            self._constraint_values(out["F"], out.get("G"), out.get("H"))
        F, CV = self._sanitise(X, F, CV)
        self._receive(X[:k], F, CV, GH)
        return self._pad(n, F, CV)

    def _receive(self, X, F, CV, GH) -> None:
        """Queue evaluated rows for the archive (merged once per iteration, see ``_flush``);
        rows a problem's NaN/inf made ``F = CV = inf`` are never archived."""
        ok = finite_rows(F, CV)
        if not ok.all():
            X, F = X[ok], F[ok]
            CV, GH = (None if CV is None else CV[ok]), (None if GH is None else GH[ok])
        if len(F):
            self._buffer.append((X, F, CV, GH))

    def _flush(self) -> None:
        """Merge the iteration's evaluated (finite) rows into the archive at once.

        The archive is read only between iterations, so this gives the same
        non-dominated set as a merge per batch; the truncation runs once on the union.
        """
        if self._buffer:
            parts = list(zip(*self._buffer, strict=True))
            self._buffer = []
            X, F = np.concatenate(parts[0]), np.concatenate(parts[1])
            if self._constrained:
                self.pareto_archive.add(X, F, rng=self.random_state,
                                        CV=np.concatenate(parts[2]),
                                        extra=np.concatenate(parts[3]))
            else:
                self.pareto_archive.add(X, F, rng=self.random_state)
            self._opt_stale = True

    # ---- subclass interface ---------------------------------------------------------------
    def _make_archive(self, capacity: int) -> ArchiveBase:
        """The external archive (MOEOSMA's crowding-radius archive by default)."""
        return CrowdingArchive.moeosma(capacity)

    def _n_initial(self) -> int:
        """Size of the initial population."""
        return self.pop_size

    def _evals_per_iteration(self) -> float:
        """Expected evaluations per iteration (used to plan T from an n_eval budget)."""
        return float(self.pop_size)

    def _initialize_state(self) -> None:
        """Create per-run arrays after the initial population was evaluated."""

    def _population_arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
        """Arrays ``(X, F, CV)`` reported as ``pop`` (default: the last evaluated candidates)."""
        return self.X, self.F, self.CV

    def _generation(self) -> Step:
        """One iteration: yield candidate arrays, receive ``(F, CV)`` for each."""
        raise NotImplementedError("abstract hook: subclasses implement it")
