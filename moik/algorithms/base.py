"""ArrayAlgorithm: a pymoo ``Algorithm`` whose state lives in numpy arrays.

pymoo's ``Population`` objects cost 25-40x a swarm update rule (design.md), so
``ArrayAlgorithm`` keeps the population, its objective values and every
per-algorithm array (memory, velocities, pool) as numpy arrays and builds pymoo
objects lazily: ``algorithm.pop`` and ``algorithm.opt`` are properties that
build a ``Population`` from the arrays only when something reads them (the
final ``Result``, a tolerance termination, ``save_history`` copies).

A subclass writes one generation as a generator ``_generation()`` that yields
candidate arrays ``X`` and receives ``(F, CV)`` for them (``CV`` is ``None`` for
unconstrained problems). Two drivers run it: ``next()`` (used by ``minimize``)
evaluates with ``problem.evaluate`` directly; ``ask()/tell()`` hand the same
candidates out as ``Population`` objects. Both give bit-identical runs.

Constraints are handled feasibility-first (mechanics.py); an infeasible best
is reported by pymoo's ``Result`` as no solution (``res.X is None``).

``n_eval`` terminations are honoured exactly: when a batch would overrun the
budget only its first rows are evaluated and the others get ``F = CV = inf``
(never accepted by a greedy memory, ranked last). The initial population is
always evaluated in full.
"""

from __future__ import annotations

from collections.abc import Generator

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.population import Population
from pymoo.core.termination import TerminateIfAny
from pymoo.termination.default import DefaultTermination
from pymoo.util.display.column import Column
from pymoo.util.display.output import Output

from moik.algorithms.mechanics import (
    best_index,
    clip_to_bounds,
    constraint_violation,
    is_better,
    uniform_population,
)
from moik.exceptions import NonFiniteError, ParameterError, ShapeError

Step = Generator[np.ndarray, tuple, None]


def _find_limit(termination, attr: str) -> float:
    """Smallest ``attr`` (n_max_gen / n_max_evals) among any-of termination criteria."""
    limit = getattr(termination, attr, None)
    limit = np.inf if limit is None else float(limit)
    if isinstance(termination, (TerminateIfAny, DefaultTermination)):
        for sub in termination.criteria:
            limit = min(limit, _find_limit(sub, attr))
    return limit


def _is_int(value) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def _avg_f(algorithm) -> float | None:
    F = algorithm.F[np.isfinite(algorithm.F)]
    return float(F.mean()) if F.size else None


class ArrayOutput(Output):
    """``verbose=True`` columns: n_gen, n_eval, [cv_best], f_avg (current), f_best (so far)."""

    def initialize(self, algorithm) -> None:
        if algorithm.problem.has_constraints():
            self.columns.append(Column("cv_best", func=lambda a: a.best_cv))
        self.columns += [Column("f_avg", func=_avg_f), Column("f_best", func=lambda a: a.best_f)]


class ArrayAlgorithm(Algorithm):
    """Base of moik's single-objective population algorithms (array state).

    Public attributes for callbacks (all numpy, read them, do not mutate):
    ``X``/``F``/``CV`` (current population as each algorithm documents it, and violation;
    ``CV`` is None without constraints), ``best_x``/``best_f``/``best_cv``
    (best so far), ``convergence`` (best f per generation, 1-D), ``t`` (current
    iteration of the paper's schedule) and ``max_iter`` (its length T), plus
    the subclass arrays documented on each algorithm.

    ``save_history=True`` works but deep-copies the whole algorithm (problem
    included) every generation, which costs far more than the update rule.

    Args:
        pop_size: Population size N.
        X0: Optional initial points (k <= pop_size rows within the bounds); the
            remaining rows are drawn uniformly.
        max_iter: Schedule length T of algorithms whose parameters depend on
            t/T. None: taken from an ``n_gen``/``n_eval`` termination, else 1000.
        **kwargs: pymoo ``Algorithm`` options (``output``, ``callback`` ...).
    """

    min_pop_size = 2

    def __init__(self, *, pop_size: int = 100, X0: np.ndarray | None = None,
                 max_iter: int | None = None, **kwargs):
        kwargs.setdefault("output", ArrayOutput())
        super().__init__(**kwargs)
        if not _is_int(pop_size) or pop_size < self.min_pop_size:
            raise ParameterError(f"pop_size must be an integer >= {self.min_pop_size}, "
                                 f"got {pop_size!r}")
        if max_iter is not None and (not _is_int(max_iter) or max_iter < 1):
            raise ParameterError(f"max_iter must be a positive integer or None, got {max_iter!r}")
        self.pop_size, self.X0, self.max_iter = int(pop_size), X0, max_iter
        self.X = self.F = self.CV = None
        self.best_x, self.best_f, self.best_cv = None, np.inf, None
        self.t = 0

    # ---- lazily built pymoo objects -------------------------------------------------------
    @property
    def pop(self) -> Population | None:
        if self.__dict__.get("_pop_stale"):
            X, F, CV = self._population_arrays()
            cv = np.zeros(len(F)) if CV is None else CV
            self._pop = Population.new("X", X, "F", F[:, None], "CV", cv[:, None])
            self._pop_stale = False
        return self.__dict__.get("_pop")

    @pop.setter
    def pop(self, value) -> None:
        self._pop, self._pop_stale = value, False

    @property
    def opt(self) -> Population | None:
        if self.__dict__.get("_opt_stale"):
            cv = 0.0 if self.best_cv is None else self.best_cv
            args = ["X", self.best_x[None], "F", np.array([[self.best_f]]), "CV", np.array([[cv]])]
            for key, val in self._best_gh.items():
                args += [key, val[None]]
            self._opt = Population.new(*args)
            self._opt_stale = False
        return self.__dict__.get("_opt")

    @opt.setter
    def opt(self, value) -> None:
        self._opt, self._opt_stale = value, False

    @property
    def convergence(self) -> np.ndarray:
        """Best-so-far f after each generation (generation 1 = initial population)."""
        return np.asarray(self._convergence, dtype=float)

    # ---- pymoo hooks ----------------------------------------------------------------------
    def _setup(self, problem, **kwargs) -> None:
        if problem.n_obj != 1:
            raise ParameterError(f"{type(self).__name__} is single-objective; the problem has "
                                 f"n_obj={problem.n_obj}")
        xl, xu = problem.bounds()
        if xl is None or xu is None or not (np.all(np.isfinite(xl)) and np.all(np.isfinite(xu))):
            raise ParameterError(f"{type(self).__name__} needs finite bounds xl, xu")
        self.xl, self.xu = np.asarray(xl, float), np.asarray(xu, float)
        self._constrained = bool(problem.has_constraints())
        self._max_evals = _find_limit(self.termination, "n_max_evals")
        if self.max_iter is None:
            per_gen = self._evals_per_iteration()
            n_gen = _find_limit(self.termination, "n_max_gen")
            by_eval = (self._max_evals - self.pop_size) / per_gen + 1
            limit = min(n_gen, np.ceil(by_eval))
            self.max_iter = int(limit) if np.isfinite(limit) else 1000
        self.max_iter = max(int(self.max_iter), 1)

    def _initialize_infill(self) -> Population:
        n_var = self.problem.n_var
        X = uniform_population(self.pop_size, self.xl, self.xu, rng=self.random_state)
        if self.X0 is not None:
            X0 = np.asarray(self.X0, dtype=float)
            if X0.ndim != 2 or X0.shape[1] != n_var or not 1 <= len(X0) <= self.pop_size:
                raise ShapeError(f"X0 must have shape (k, {n_var}) with 1 <= k <= pop_size="
                                 f"{self.pop_size}, got {X0.shape}")
            if not np.all(np.isfinite(X0)):
                raise NonFiniteError("X0 holds NaN or infinite values")
            if np.any(clip_to_bounds(X0, self.xl, self.xu) != X0):
                raise ParameterError("X0 has points outside the problem bounds [xl, xu]")
            X[: len(X0)] = X0
        return Population.new("X", X)

    def _initialize_advance(self, infills=None, **kwargs) -> None:
        self._convergence, self._best_gh, self._step = [], {}, None
        F, CV, G, H = self._values_of(infills)
        self.X, self.F, self.CV = infills.get("X"), F, CV
        self._receive(self.X, F, CV, G, H)
        self._initialize_state()

    def next(self) -> None:
        """One generation through the array fast path (pymoo's path for initialization)."""
        if not self.is_initialized or self._step is not None:
            return super().next()
        self.t = self.n_iter - 1
        step = self._generation()
        X = next(step)
        while True:
            F, CV = self._evaluate(X)
            try:
                X = step.send((F, CV))
            except StopIteration:
                break
        self._post_advance()
        if self.termination.has_terminated():
            self.finalize()

    def _infill(self) -> Population:
        if self._step is None:
            self.t = self.n_iter - 1
            self._step = self._generation()
            self._pending = next(self._step)
        n = len(self._pending)
        return Population.new("X", self._pending[: max(0, min(n, self._budget_left(n)))])

    def _advance(self, infills=None, **kwargs) -> bool:
        F, CV, G, H = self._values_of(infills)
        F, CV = self._pad(len(self._pending), F, CV)
        self._receive(self._pending, F, CV, G, H)
        try:
            self._pending = self._step.send((F, CV))
            return False
        except StopIteration:
            self._step = self._pending = None
            return True

    def _set_optimum(self) -> None:
        """Nothing to do: ``opt`` is built lazily from ``best_x`` when read."""

    def _post_advance(self) -> None:
        self._convergence.append(self.best_f)
        self._pop_stale = True
        super()._post_advance()

    # ---- evaluation -----------------------------------------------------------------------
    def _budget_left(self, n: int) -> int:
        left = self._max_evals - self.evaluator.n_eval
        return n if left >= n else int(max(left, 0))

    def _pad(self, n: int, F: np.ndarray, CV: np.ndarray | None):
        """Give rows left unevaluated by the budget F = CV = inf."""
        k = len(F)
        if k == n:
            return F, CV
        F = np.concatenate([F, np.full(n - k, np.inf)])
        return F, (None if CV is None else np.concatenate([CV, np.full(n - k, np.inf)]))

    def _values_of(self, pop: Population):
        F = pop.get("F")[:, 0].astype(float) if len(pop) else np.empty(0)
        if not self._constrained:
            return F, None, None, None
        G, H = pop.get("G"), pop.get("H")
        return F, constraint_violation(G, H), G, H

    def _evaluate(self, X: np.ndarray):
        """Evaluate candidates with the vectorized problem, counting n_eval exactly."""
        n = len(X)
        k = n if self._max_evals == np.inf else self._budget_left(n)
        F, CV, G, H = np.empty(0), (np.empty(0) if self._constrained else None), None, None
        if k:
            out = self.problem.evaluate(X if k == n else X[:k], return_as_dictionary=True)
            self.evaluator.n_eval += k
            F = out["F"][:, 0]
            if self._constrained:
                G, H = out.get("G"), out.get("H")
                CV = constraint_violation(G, H)
        if k < n:
            F, CV = self._pad(n, F, CV)
        self._receive(X, F, CV, G, H)
        return F, CV

    def _receive(self, X, F, CV, G, H) -> None:
        """Update the best so far with an evaluated batch."""
        if CV is None:  # unconstrained fast path
            i = F.argmin()
            if F[i] < self.best_f or self.best_x is None:
                self.best_x, self.best_f, self._opt_stale = X[i].copy(), float(F[i]), True
            return
        i = best_index(F, CV)
        if self.best_x is None or is_better(F[i], CV[i], self.best_f, self.best_cv):
            self.best_x, self.best_f, self.best_cv = X[i].copy(), float(F[i]), float(CV[i])
            self._best_gh = {k: np.array(v[i]) for k, v in (("G", G), ("H", H))
                             if v is not None and i < len(v)}
            self._opt_stale = True

    # ---- subclass interface ---------------------------------------------------------------
    def _evals_per_iteration(self) -> float:
        """Expected evaluations per generation (used to infer T from an n_eval budget)."""
        return float(self.pop_size)

    def _initialize_state(self) -> None:
        """Create per-run arrays after the initial population was evaluated."""

    def _population_arrays(self):
        """Arrays reported as ``pop`` (default: the last evaluated candidates)."""
        return self.X, self.F, self.CV

    def _generation(self) -> Step:
        """One iteration: yield candidate arrays, receive ``(F, CV)`` for each."""
        raise NotImplementedError
