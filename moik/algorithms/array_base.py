"""ArrayStateAlgorithm: the one array-state pymoo ``Algorithm`` under moik's own methods.

pymoo's ``Population`` objects cost 25-40x a swarm update rule (design.md), so the
population, its objective values and every per-algorithm array (memory, velocities,
pool) stay numpy arrays; pymoo objects are built only when read: ``algorithm.pop`` and
``algorithm.opt`` are properties built from the arrays (the final ``Result``, a
tolerance termination, ``save_history`` copies). The single-objective
(:class:`moik.algorithms.base.ArrayAlgorithm`) and multi-objective
(:class:`moik.algorithms.moo.base.MOArrayAlgorithm`) bases differ only in their
objective check, their output columns and their composed incumbent
(:mod:`moik.algorithms.incumbent`: the best so far, or a Pareto archive).

A subclass writes one iteration as a generator ``_generation()`` that yields candidate
arrays ``X`` (k, n_var) and receives ``(F, CV)`` for them: objectives ((k,) with one
objective, (k, n_obj) with several) and total violations (k,) (``CV`` None for
unconstrained problems). ``next()`` (used by ``minimize``) evaluates them directly;
``ask()/tell()`` hand the same candidates out as ``Population`` objects (one round per
yield); both give identical runs.

Schedule (one rule for both halves): the length T of the papers' t/T schedules
(``max_iter``) is fixed when given; otherwise it is planned before every iteration from
the algorithm's *current* termination
(:func:`~moik.algorithms.array_state.planned_iterations`: ``n_gen``, ``n_eval``, ``time``,
pymoo's default and robust terminations and their combinations), so t/T spans the real
budget, also after a checkpoint is resumed with a new termination;
:data:`~moik.algorithms.array_state.DEFAULT_SCHEDULE_LENGTH` when nothing bounds the run.

Evaluation: pymoo's ``Evaluator`` whenever anything is attached to it, else the array
fast path (:mod:`moik.algorithms.evaluation`).

Default termination: without one, the run is the algorithm's own schedule,
``("n_gen", T + 1)`` with T = ``max_iter`` when given, else pymoo's count of
:data:`~moik.algorithms.array_state.DEFAULT_SCHEDULE_LENGTH` generations, the initial one
included (:meth:`ArrayStateAlgorithm.default_termination`), not pymoo's stagnation-based
default. A termination with a tolerance criterion (pymoo's ``ftol``/``xtol``/``cv``, as in
``DefaultSingleObjectiveTermination``) is run as given, with a
:class:`~moik.exceptions.ToleranceTerminationWarning`: it stops a method whose best so far
stays flat while it explores.
An ``n_gen`` or ``n_eval`` limit below 1 is refused with a ``ParameterError``.

``n_eval`` budgets are exact: rows of a batch beyond the budget are not evaluated and get
``F = CV = inf`` (never accepted by a memory, ranked last, never reported). The initial
population is always evaluated in full. A problem's NaN/inf is handled once here
(:mod:`moik.algorithms.nonfinite`).
"""

from __future__ import annotations

import math
import time
import warnings
from typing import Any, cast

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.population import Population
from pymoo.termination.max_gen import MaximumGenerationTermination

from moik._validate import seed
from moik.algorithms.array_state import (
    DEFAULT_SCHEDULE_LENGTH,
    Step,
    budget_left,
    check_sizes,
    check_termination,
    find_limit,
    finite_bounds,
    given_rows,
    has_time_criterion,
    initial_infill,
    planned_iterations,
    refuse_unknown_keywords,
    tolerance_criteria,
)
from moik.algorithms.evaluation import (
    constraint_values,
    evaluator_attached,
    pad,
    problem_values,
    values_asked,
)
from moik.algorithms.meta import setup_through_wrapper
from moik.algorithms.nonfinite import sanitise
from moik.exceptions import ParameterError, ToleranceTerminationWarning

__all__ = ["ArrayStateAlgorithm"]




class ArrayStateAlgorithm(Algorithm):
    """The array-state base (module doc); subclass :class:`~moik.algorithms.base.ArrayAlgorithm`
    or :class:`~moik.algorithms.moo.base.MOArrayAlgorithm`.

    Args:
        pop_size: Population size N.
        X0: Optional initial points (k rows within the bounds); with fewer rows than the
            initial population the other rows are drawn uniformly, with more all are
            evaluated and the algorithm's ranking keeps the population
            (:mod:`moik.algorithms.initial_survival`).
        sampling: pymoo's form of the same (a ``Sampling``, an array or a ``Population``,
            :func:`~moik.algorithms.array_state.initial_infill`); not with ``X0``.
        max_iter: Schedule length T (update iterations after initialization, the papers'
            Max_t; ``t = 1 .. T``), fixed. None: planned before every iteration from the
            current termination (module doc).
        **kwargs: pymoo ``Algorithm`` options (``output``, ``callback``, ``seed`` ...,
            :data:`~moik.algorithms.array_state.PYMOO_OPTIONS`).

    Raises:
        ParameterError: For a keyword that is neither a parameter of the algorithm nor a
            pymoo option (the message lists the accepted ones), or a bad size.
    """

    min_pop_size = 2

    # pymoo's life cycle: X, F and max_iter are arrays / an int from setup() on (None, or the
    # max_iter given, before); the types are those of the run (callbacks, _generation)
    X: np.ndarray
    F: np.ndarray
    CV: np.ndarray | None
    max_iter: int
    t: int
    """The iteration of the paper's schedule (0 while the initial population is built)."""
    n_received: int
    """Evaluations this algorithm has received (its own count: an outside Evaluator, as in
    pymoo's ask/tell and loop forms, does not advance ``evaluator.n_eval``)."""
    _max_evals: float
    _plan_varies: bool
    _step: Step | None
    _pending: np.ndarray | None

    def __init__(self, *, pop_size: int = 100, X0: np.ndarray | None = None,
                 max_iter: int | None = None, sampling: object = None, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        kwargs.setdefault("output", self._default_output())
        super().__init__(**kwargs)
        self.pop_size, self._fixed_T = check_sizes(pop_size, self.min_pop_size, max_iter)
        self.max_iter = cast(int, self._fixed_T)  # None: planned in setup() (_plan_schedule)
        self.X0, self.sampling = X0, sampling
        if X0 is not None and sampling is not None:
            raise ParameterError("give the initial points as X0 or as sampling, not both")
        self.X = self.F = cast(np.ndarray, None)  # set by setup() (the initial population)
        self.CV = None
        self.incumbent: Any = None  # made with the initial population (_make_incumbent)
        self.t = self.n_received = 0

    # ---- pymoo hooks ----------------------------------------------------------------------
    def setup(self, problem, **kwargs):
        """pymoo's ``setup`` (``minimize`` calls it), after checking the seed it will use;
        inside a pymoo wrapper that skips ``_setup`` (``AdaptiveConstraintHandling``) the
        algorithm's ``_setup`` still runs (:mod:`moik.algorithms.meta`).

        Raises:
            ParameterError: If the seed (``seed=`` of ``minimize`` or of the constructor)
                is not None, a non-negative integer or a numpy ``SeedSequence``.
        """
        seed("seed", kwargs.get("seed", self.seed))
        self._nonfinite_warned = False
        if kwargs.get("termination") is None and self.termination is None:
            kwargs["termination"] = self.default_termination()
        setup_through_wrapper(self, super().setup, problem, **kwargs)
        check_termination(self.termination)
        self._warn_of_tolerance()
        return self

    def _warn_of_tolerance(self) -> None:
        """Warn (:class:`~moik.exceptions.ToleranceTerminationWarning`) when the termination
        holds a tolerance criterion (``ftol``, ``xtol``, ``cv``)."""
        found = tolerance_criteria(self.termination)
        if not found:
            return
        name = type(self).__name__
        warnings.warn(
            f"{name} runs under a tolerance termination ({', '.join(sorted(set(found)))}): "
            f"it may stop {name} early, in its exploration phase, where the best so far stays "
            f"flat for tens of generations (the schedule t/T of a schedule-driven method "
            f"is then cut short, and its answer is an early one); give a budget instead, "
            f"('n_gen', G), ('n_eval', E) or ('time', s), or no termination (the algorithm's "
            f"own schedule)", ToleranceTerminationWarning, stacklevel=3)

    def default_termination(self) -> MaximumGenerationTermination:
        """The termination used when none is given: the algorithm's own schedule.

        With ``max_iter`` given, its T update iterations after the initial population,
        ``("n_gen", T + 1)``; without, pymoo's generation count: ``("n_gen",``
        :data:`DEFAULT_SCHEDULE_LENGTH` ``)``, the limit of pymoo's default termination
        (the initial population is generation 1, so T = 999 is planned from it and the run
        ends at ``n_gen`` 1001, as pymoo's own algorithms do).

        pymoo's default termination (1000 generations or 100,000 evaluations, or a
        stagnation window of 30-50 generations) would stop a schedule-driven method in its
        exploration phase, long before t/T reaches 1 (ChOA: 0.499 after ~32 generations
        where its schedule reaches 0.014)."""
        if self._fixed_T is None:
            return MaximumGenerationTermination(DEFAULT_SCHEDULE_LENGTH)
        return MaximumGenerationTermination(self._fixed_T + 1)

    def _setup(self, problem, **kwargs) -> None:
        self._problem_read = True
        self._check_objectives(problem)
        self.xl, self.xu = finite_bounds(problem, type(self).__name__)
        self._constrained = bool(problem.has_constraints())
        self._plans: dict = {}
        n_initial = max(self._n_initial(), given_rows(self.X0, self.sampling, self._n_initial()))
        self._plan_schedule(t=1, n_eval=n_initial, elapsed=0.0)

    def _plan_schedule(self, *, t: int, n_eval: int, elapsed: float) -> None:
        """Refresh the evaluation budget and T from the current termination (module doc).

        A termination object already planned whose plan cannot change (no ``time``
        criterion: ``n_gen`` is fixed and an ``n_eval`` plan is made once) is not walked
        again."""
        key = id(self.termination)
        if key == self.__dict__.get("_planned_for") and not self._plan_varies:
            if self._fixed_T is None and self.max_iter < t:  # every T is at least t
                self.max_iter = t
            return
        self._planned_for, self._plan_varies = key, has_time_criterion(self.termination)
        self._max_evals = find_limit(self.termination, "n_max_evals")
        if self._fixed_T is None:
            T = planned_iterations(self.termination, t=t, n_eval=n_eval, elapsed=elapsed,
                                   per_iteration=self._evals_per_iteration(), plans=self._plans)
            self.max_iter = int(T) if math.isfinite(T) else max(DEFAULT_SCHEDULE_LENGTH, t)

    def _plan_again(self) -> None:
        """Plan T afresh before the next iteration (the evaluations per iteration changed)."""
        self._plans.clear()
        self.__dict__.pop("_planned_for", None)

    def _begin_iteration(self) -> None:
        """Before an iteration's first batch: t and the planned schedule."""
        self.t = self.n_iter - 1
        self._plan_schedule(t=self.t, n_eval=self.evaluator.n_eval,
                            elapsed=time.time() - self.start_time)

    def _initialize_infill(self) -> Population:
        return initial_infill(self.problem, self._n_initial(), self.xl, self.xu, X0=self.X0,
                              sampling=self.sampling, rng=self.random_state)

    def _initialize_advance(self, infills=None, **kwargs) -> None:
        self._step = self._pending = None
        self.incumbent = self._make_incumbent()
        X = infills.get("X")
        F, CV, GH = self._values_of(infills)
        self.n_received = len(F)
        self._opt_stale = self.incumbent.receive(X, F, CV, GH) | \
            self.incumbent.end_iteration(rng=self.random_state)
        if len(F) > self._n_initial():  # a larger sample: the algorithm's ranking keeps N
            keep = self._initial_survivors(F, CV)
            X, F, CV = X[keep], F[keep], (None if CV is None else CV[keep])
        self.X, self.F, self.CV = X, F, CV
        self._check_start()
        self._initialize_state()

    def next(self) -> None:
        """One iteration through the array fast path: run ``_generation()``, sending each
        yielded batch its ``_evaluate`` result (pymoo's own path for initialization and
        while an ``ask()/tell()`` iteration is open)."""
        if not self.is_initialized or self._step is not None:
            return super().next()
        self._begin_iteration()
        self._run_generation()
        self._end_iteration()
        self._post_advance()
        if self.termination.has_terminated():
            self.finalize()

    def _run_generation(self) -> None:
        """One iteration's batches through the array fast path: ``_generation()``, each
        yielded batch sent its ``_evaluate`` result (a subclass with a faster path for some
        problems overrides this and calls it for the others)."""
        step = self._iteration()
        X = next(step)
        while True:
            try:
                X = step.send(self._evaluate(X))
            except StopIteration:
                break

    def _infill(self) -> Population:
        if self._step is None:
            self._begin_iteration()
            self._step = self._iteration()
            self._pending = next(self._step)
        assert self._pending is not None  # a batch is pending while an iteration is open
        n = budget_left(self._max_evals, self.evaluator.n_eval, len(self._pending))
        return Population.new("X", self._pending[:n])

    def _advance(self, infills=None, **kwargs) -> bool:
        assert self._step is not None and self._pending is not None  # an iteration is open
        F, CV, GH = self._values_of(infills)
        self._receive(self._pending[: len(F)], F, CV, GH)
        try:
            self._pending = self._step.send(pad(len(self._pending), F, CV))
            return False
        except StopIteration:
            self._step = self._pending = None
            self._end_iteration()
            return True

    def _end_iteration(self) -> None:
        """After an iteration's last batch: the incumbent merges what it queued."""
        if self.incumbent.end_iteration(rng=self.random_state):
            self._opt_stale = True

    def _post_advance(self) -> None:
        self.incumbent.record()
        self._pop_stale = True
        super()._post_advance()

    def _set_optimum(self) -> None:
        """Nothing to do: ``opt`` is built when read."""

    # ---- evaluation -----------------------------------------------------------------------
    def _objectives(self, F: np.ndarray) -> np.ndarray:
        """The objective array the algorithm works with: (k,) for one objective, else F."""
        return F[:, 0] if self.problem.n_obj == 1 else F

    def _sanitise(self, X: np.ndarray, F: np.ndarray,
                  CV: np.ndarray | None) -> tuple[np.ndarray, np.ndarray | None]:
        """A batch's ``(F, CV)`` with rows holding a problem's NaN/inf set to ``F = CV = inf``
        (infeasible and worst, warned once per run: :mod:`moik.algorithms.nonfinite`)."""
        F, CV, self._nonfinite_warned = sanitise(
            X, F, CV, problem=self.problem, warned=self.__dict__.get("_nonfinite_warned", False))
        return F, CV

    def _values_of(self, pop: Population):
        """``(F, CV, GH)`` of an evaluated ``Population`` (GH: G and H side by side)."""
        n = len(pop)
        if not n:
            F = self._objectives(np.empty((0, self.problem.n_obj)))
            if not self._constrained:
                return F, None, None
            n_con = self.problem.n_ieq_constr + self.problem.n_eq_constr
            return F, np.empty(0), np.empty((0, n_con))
        F = self._objectives(pop.get("F")).astype(float)
        CV = GH = None
        if self._constrained:
            CV, GH = constraint_values(pop.get("G"), pop.get("H"), n)
        F, CV = self._sanitise(pop.get("X"), F, CV)
        return F, CV, GH

    def _evaluate(self, X: np.ndarray):
        """Evaluate a batch (vectorized), count n_eval exactly, give it to the incumbent.

        Returns:
            ``(F, CV)`` for every row of ``X`` (see ``_pad``).
        """
        n = len(X)
        k = budget_left(self._max_evals, self.evaluator.n_eval, n)
        if k == 0:
            return pad(n, self._objectives(np.empty((0, self.problem.n_obj))),
                       np.empty(0) if self._constrained else None)
        Xk = X if k == n else X[:k]
        archive: Any = self.__dict__.get("archive")  # the archive= option
        if evaluator_attached(self.evaluator, archive, self.problem):  # pymoo's contract
            pop = Population.new("X", Xk)
            self.evaluator.eval(self.problem, pop, algorithm=self)
            if archive is not None:
                self.archive = archive.add(pop)
            F, CV, GH = self._values_of(pop)
        else:  # the array fast path (same values, no Population)
            out = problem_values(self.problem, Xk, constrained=self._constrained,
                                 asked=values_asked(self.problem, self.evaluator))
            self.evaluator.n_eval += k
            F, CV, GH = self._objectives(out["F"]), None, None
            if self._constrained:
                CV, GH = constraint_values(out.get("G"), out.get("H"), k)
            F, CV = self._sanitise(Xk, F, CV)
        self._receive(Xk, F, CV, GH)
        return pad(n, F, CV)

    def _receive(self, X: np.ndarray, F: np.ndarray, CV: np.ndarray | None,
                 GH: np.ndarray | None) -> None:
        """Count evaluated rows (``n_received``) and give them to the incumbent."""
        self.n_received += len(F)
        if self.incumbent.receive(X, F, CV, GH):
            self._opt_stale = True

    # ---- lazily built pymoo objects -------------------------------------------------------
    def _build_pop(self) -> Population:
        X, F, CV = self._population_arrays()
        cv = np.zeros(len(F)) if CV is None else CV
        return Population.new("X", X, "F", F.reshape(len(F), -1), "CV", cv[:, None])

    @property
    def pop(self) -> Population | None:
        if self.__dict__.get("_pop_stale"):
            self._pop, self._pop_stale = self._build_pop(), False
        return self.__dict__.get("_pop")

    @pop.setter
    def pop(self, value) -> None:
        self._pop, self._pop_stale = value, False

    @property
    def opt(self) -> Population | None:
        if self.__dict__.get("_opt_stale"):
            self._opt, self._opt_stale = self.incumbent.build_opt(self.problem), False
        return self.__dict__.get("_opt")

    @opt.setter
    def opt(self, value) -> None:
        self._opt, self._opt_stale = value, False

    # ---- subclass interface ---------------------------------------------------------------
    def _default_output(self):
        """The ``verbose=True`` output (the SO and MO bases give their columns)."""
        raise NotImplementedError("abstract hook: the SO and MO bases implement it")

    def _check_objectives(self, problem) -> None:
        """Refuse a problem with the wrong number of objectives (ParameterError)."""
        raise NotImplementedError("abstract hook: the SO and MO bases implement it")

    def _make_incumbent(self):
        """The composed incumbent (:mod:`moik.algorithms.incumbent`)."""
        raise NotImplementedError("abstract hook: the SO and MO bases implement it")

    def _check_start(self) -> None:
        """Checks after the initial population was received (the MO base needs an archive)."""

    def _n_initial(self) -> int:
        """Size of the initial population."""
        return self.pop_size

    def _initial_survivors(self, F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
        """Indices of the rows of an initial sample larger than :meth:`_n_initial` that
        form the initial population (:mod:`moik.algorithms.initial_survival`; the SO and MO
        bases rank them, an algorithm with its own survival overrides this)."""
        raise NotImplementedError("abstract hook: the SO and MO bases implement it")

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

    def _iteration(self) -> Step:
        """The batches of one iteration: the algorithm's ``_generation()`` (the MO base adds
        its feasibility search after it)."""
        return self._generation()
