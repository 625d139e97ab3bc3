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

Evaluation (pymoo's contract): the initial population and ``ask()/tell()`` go through
pymoo's ``Evaluator``; after them, a batch goes through ``self.evaluator`` too whenever
anything is attached to it (an Evaluator subclass or callback, the ``archive=`` option, a
problem with ``requires_kwargs=True``), else through the array fast path
(``problem.evaluate`` on the array, asking the Evaluator's ``evaluate_values_of``, counting
``evaluator.n_eval`` exactly; the same values without building a ``Population``).

``n_eval`` budgets are exact: rows of a batch beyond the budget are not evaluated and get
``F = CV = inf`` (never accepted by a memory, ranked last, never reported). The initial
population is always evaluated in full. A problem's NaN/inf is handled once here
(:mod:`moik.algorithms.nonfinite`).
"""

from __future__ import annotations

import math
import time
from typing import Any, cast

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.evaluator import Evaluator
from pymoo.core.population import Population

from moik._validate import seed
from moik.algorithms.array_state import (
    DEFAULT_SCHEDULE_LENGTH,
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
from moik.algorithms.nonfinite import sanitise

__all__ = ["ArrayStateAlgorithm"]


class ArrayStateAlgorithm(Algorithm):
    """The array-state base (module doc); subclass :class:`~moik.algorithms.base.ArrayAlgorithm`
    or :class:`~moik.algorithms.moo.base.MOArrayAlgorithm`.

    Args:
        pop_size: Population size N.
        X0: Optional initial points (k rows within the bounds, k at most the initial
            population); the other rows are drawn uniformly.
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
    _max_evals: float
    _step: Step | None
    _pending: np.ndarray | None

    def __init__(self, *, pop_size: int = 100, X0: np.ndarray | None = None,
                 max_iter: int | None = None, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        kwargs.setdefault("output", self._default_output())
        super().__init__(**kwargs)
        self.pop_size, self._fixed_T = check_sizes(pop_size, self.min_pop_size, max_iter)
        self.max_iter = cast(int, self._fixed_T)  # None: planned in setup() (_plan_schedule)
        self.X0 = X0
        self.X = self.F = cast(np.ndarray, None)  # set by setup() (the initial population)
        self.CV = None
        self.incumbent: Any = None  # made with the initial population (_make_incumbent)
        self.t = 0

    # ---- pymoo hooks ----------------------------------------------------------------------
    def setup(self, problem, **kwargs):
        """pymoo's ``setup`` (``minimize`` calls it), after checking the seed it will use.

        Raises:
            ParameterError: If the seed (``seed=`` of ``minimize`` or of the constructor)
                is not None, a non-negative integer or a numpy ``SeedSequence``.
        """
        seed("seed", kwargs.get("seed", self.seed))
        self._nonfinite_warned = False
        return super().setup(problem, **kwargs)

    def _setup(self, problem, **kwargs) -> None:
        self._check_objectives(problem)
        self.xl, self.xu = finite_bounds(problem, type(self).__name__)
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

    def _initialize_infill(self) -> Population:
        return initial_population(self._n_initial(), self.xl, self.xu, self.X0,
                                  rng=self.random_state)

    def _initialize_advance(self, infills=None, **kwargs) -> None:
        self._step = self._pending = None
        self.incumbent = self._make_incumbent()
        X = infills.get("X")
        F, CV, GH = self._values_of(infills)
        self.X, self.F, self.CV = X, F, CV
        self._opt_stale = self.incumbent.receive(X, F, CV, GH) | \
            self.incumbent.end_iteration(rng=self.random_state)
        self._check_start()
        self._initialize_state()

    def next(self) -> None:
        """One iteration through the array fast path: run ``_generation()``, sending each
        yielded batch its ``_evaluate`` result (pymoo's own path for initialization and
        while an ``ask()/tell()`` iteration is open)."""
        if not self.is_initialized or self._step is not None:
            return super().next()
        self._begin_iteration()
        step = self._generation()
        X = next(step)
        while True:
            try:
                X = step.send(self._evaluate(X))
            except StopIteration:
                break
        self._end_iteration()
        self._post_advance()
        if self.termination.has_terminated():
            self.finalize()

    def _infill(self) -> Population:
        if self._step is None:
            self._begin_iteration()
            self._step = self._generation()
            self._pending = next(self._step)
        assert self._pending is not None  # a batch is pending while an iteration is open
        n = budget_left(self._max_evals, self.evaluator.n_eval, len(self._pending))
        return Population.new("X", self._pending[:n])

    def _advance(self, infills=None, **kwargs) -> bool:
        assert self._step is not None and self._pending is not None  # an iteration is open
        F, CV, GH = self._values_of(infills)
        if self.incumbent.receive(self._pending[: len(F)], F, CV, GH):
            self._opt_stale = True
        try:
            self._pending = self._step.send(self._pad(len(self._pending), F, CV))
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

    def _constraint_values(self, G, H, n: int) -> tuple[np.ndarray, np.ndarray]:
        """``(CV, GH)``: total violations and the constraint values side by side."""
        G = np.zeros((n, 0)) if G is None else np.asarray(G, float).reshape(n, -1)
        H = np.zeros((n, 0)) if H is None else np.asarray(H, float).reshape(n, -1)
        return constraint_violation(G, H), np.concatenate([G, H], axis=1)

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
            CV, GH = self._constraint_values(pop.get("G"), pop.get("H"), n)
        F, CV = self._sanitise(pop.get("X"), F, CV)
        return F, CV, GH

    def _pad(self, n: int, F: np.ndarray, CV: np.ndarray | None):
        """Rows left unevaluated by the budget get ``F = CV = inf``."""
        k = len(F)
        if k == n:
            return F, CV
        F = np.concatenate([F, np.full((n - k,) + F.shape[1:], np.inf)])
        return F, None if CV is None else np.concatenate([CV, np.full(n - k, np.inf)])

    def _evaluator_attached(self) -> bool:
        """Whether anything is attached to pymoo's evaluation (then every batch goes through
        ``self.evaluator``): an Evaluator subclass or callback, the ``archive=`` option, or a
        problem with ``requires_kwargs=True`` (it receives ``algorithm=``)."""
        ev = self.evaluator
        return (type(ev) is not Evaluator or ev.callback is not None or self.archive is not None
                or bool(getattr(self.problem, "requires_kwargs", False)))

    def _problem_values(self, X: np.ndarray) -> dict:
        """``problem.evaluate(X, return_values_of=evaluator.evaluate_values_of,
        return_as_dictionary=True)`` (so meta-problems such as pymoo's
        ``ConstraintsAsPenalty`` get the values they remove); an unconstrained problem that
        offers ``batch_objectives(X)`` (moik's IK problems: the same F bit for bit, without
        pymoo's per-call bookkeeping) is asked that instead, unless it answers None."""
        direct = None if self._constrained else getattr(self.problem, "batch_objectives", None)
        if direct is not None:
            F = direct(X)
            if F is not None:
                return {"F": F}
        return self.problem.evaluate(X, return_values_of=self.evaluator.evaluate_values_of,
                                     return_as_dictionary=True)

    def _evaluate(self, X: np.ndarray):
        """Evaluate a batch (vectorized), count n_eval exactly, give it to the incumbent.

        Returns:
            ``(F, CV)`` for every row of ``X`` (see ``_pad``).
        """
        n = len(X)
        k = budget_left(self._max_evals, self.evaluator.n_eval, n)
        if k == 0:
            return self._pad(n, self._objectives(np.empty((0, self.problem.n_obj))),
                             np.empty(0) if self._constrained else None)
        Xk = X if k == n else X[:k]
        if self._evaluator_attached():  # pymoo's contract: the Evaluator sees every batch
            pop = Population.new("X", Xk)
            self.evaluator.eval(self.problem, pop, algorithm=self)
            archive: Any = self.__dict__.get("archive")  # pymoo's optional Archive (the archive= option)
            if archive is not None:
                self.archive = archive.add(pop)
            F, CV, GH = self._values_of(pop)
        else:  # the array fast path (same values, no Population)
            out = self._problem_values(Xk)
            self.evaluator.n_eval += k
            F, CV, GH = self._objectives(out["F"]), None, None
            if self._constrained:
                CV, GH = self._constraint_values(out.get("G"), out.get("H"), k)
            F, CV = self._sanitise(Xk, F, CV)
        if self.incumbent.receive(Xk, F, CV, GH):
            self._opt_stale = True
        return self._pad(n, F, CV)

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
