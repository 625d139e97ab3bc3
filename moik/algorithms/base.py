"""ArrayAlgorithm: a pymoo ``Algorithm`` whose state lives in numpy arrays.

pymoo's ``Population`` objects cost 25-40x a swarm update rule (design.md), so
``ArrayAlgorithm`` keeps the population, its objective values and every
per-algorithm array (memory, velocities, pool) as numpy arrays and builds pymoo
objects lazily: ``algorithm.pop`` and ``algorithm.opt`` are properties that
build a ``Population`` from the arrays only when something reads them (the
final ``Result``, a tolerance termination, ``save_history`` copies). The
generation driver both bases share is :mod:`moik.algorithms.array_state`.

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

from typing import cast

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.population import Population
from pymoo.util.display.column import Column
from pymoo.util.display.output import Output

from moik.algorithms.array_state import (
    ArrayStateMixin,
    Step,
    budget_left,
    check_sizes,
    find_limit,
    finite_bounds,
    initial_population,
    refuse_unknown_keywords,
    schedule_length,
)
from moik.algorithms.mechanics import best_index, constraint_violation, is_better
from moik.exceptions import ParameterError


def _avg_f(algorithm) -> float | None:
    F = algorithm.F[np.isfinite(algorithm.F)]
    return float(F.mean()) if F.size else None


class ArrayOutput(Output):
    """``verbose=True`` columns: n_gen, n_eval, [cv_best], f_avg (current), f_best (so far)."""

    def initialize(self, algorithm) -> None:
        if algorithm.problem.has_constraints():
            self.columns.append(Column("cv_best", func=lambda a: a.best_cv))
        self.columns += [Column("f_avg", func=_avg_f), Column("f_best", func=lambda a: a.best_f)]


class ArrayAlgorithm(ArrayStateMixin, Algorithm):
    """Base of moik's single-objective population algorithms (array state).

    Public attributes for callbacks (all numpy, read them, do not mutate):
    ``X``/``F``/``CV`` (current population as each algorithm documents it, and violation;
    ``CV`` is None without constraints), ``best_x``/``best_f``/``best_cv``
    (best so far), ``convergence`` (best f per generation, 1-D), ``best_x_history``
    (best-so-far x after each generation, ``(generations, n_var)``), ``t`` (current
    iteration of the paper's schedule) and ``max_iter`` (its length T), plus
    the subclass arrays documented on each algorithm.

    ``save_history=True`` works but deep-copies the whole algorithm (problem
    included) every generation, which costs far more than the update rule.

    Args:
        pop_size: Population size N.
        X0: Optional initial points (k <= pop_size rows within the bounds); the
            remaining rows are drawn uniformly.
        max_iter: Schedule length T of algorithms whose parameters depend on
            t/T: the number of update iterations after initialization (the papers'
            Max_t; ``t = 1 .. T``). None: what an ``n_gen`` (``n_max_gen - 1``) or
            ``n_eval`` termination allows, else 1000.
        **kwargs: pymoo ``Algorithm`` options (``output``, ``callback``, ``seed`` ...,
            :data:`~moik.algorithms.array_state.PYMOO_OPTIONS`).

    Raises:
        ParameterError: For a keyword that is neither a parameter of the algorithm nor
            a pymoo option (the message lists the accepted ones), or a bad size.
    """

    min_pop_size = 2

    # pymoo's life cycle: X, F and max_iter are arrays / an int from setup() on, None (or the
    # max_iter given) before; the types are those of the run (callbacks, _generation)
    X: np.ndarray
    F: np.ndarray
    CV: np.ndarray | None
    best_x: np.ndarray
    best_cv: float | None
    max_iter: int

    def __init__(self, *, pop_size: int = 100, X0: np.ndarray | None = None,
                 max_iter: int | None = None, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        kwargs.setdefault("output", ArrayOutput())
        super().__init__(**kwargs)
        self.pop_size, max_iter = check_sizes(pop_size, self.min_pop_size, max_iter)
        self.max_iter = cast(int, max_iter)  # None: planned in setup() (schedule_length)
        self.X0 = X0
        self.X = self.F = cast(np.ndarray, None)  # set by setup() (the initial population)
        self.CV = None
        self.best_x, self.best_f, self.best_cv = cast(np.ndarray, None), np.inf, None
        self.t = 0

    # ---- lazily built pymoo objects (ArrayStateMixin) -------------------------------------
    def _build_pop(self) -> Population:
        X, F, CV = self._population_arrays()
        cv = np.zeros(len(F)) if CV is None else CV
        return Population.new("X", X, "F", F[:, None], "CV", cv[:, None])

    def _build_opt(self) -> Population:
        cv = 0.0 if self.best_cv is None else self.best_cv
        if not (np.isfinite(self.best_f) and np.isfinite(cv)):  # never report a non-finite row
            return Population.empty()
        args = ["X", self.best_x[None], "F", np.array([[self.best_f]]), "CV", np.array([[cv]])]
        for key, val in self._best_gh.items():
            args += [key, val[None]]
        return Population.new(*args)

    @property
    def convergence(self) -> np.ndarray:
        """Best-so-far f after each generation (generation 1 = initial population)."""
        return np.asarray(self._convergence, dtype=float)

    @property
    def best_x_history(self) -> np.ndarray:
        """Best-so-far x after each generation, ``(generations, n_var)`` (EOSMA Fig. 19a)."""
        return np.array(self._best_x_history, dtype=float).reshape(-1, self.problem.n_var)

    # ---- pymoo hooks ----------------------------------------------------------------------
    def _setup(self, problem, **kwargs) -> None:
        if problem.n_obj != 1:
            raise ParameterError(f"{type(self).__name__} is single-objective; the problem has "
                                 f"n_obj={problem.n_obj}")
        self.xl, self.xu = finite_bounds(problem, type(self).__name__)
        self._constrained = bool(problem.has_constraints())
        self._max_evals = find_limit(self.termination, "n_max_evals")
        self.max_iter = schedule_length(self.termination, self.max_iter, self.pop_size,
                                        self._evals_per_iteration())

    def _initialize_infill(self) -> Population:
        return initial_population(self.pop_size, self.xl, self.xu, self.X0,
                                  rng=self.random_state)

    def _initialize_advance(self, infills=None, **kwargs) -> None:
        self._convergence: list[float] = []
        self._best_x_history: list[np.ndarray] = []
        self._best_gh: dict[str, np.ndarray] = {}
        self._step = None
        F, CV, G, H = self._values_of(infills)
        self.X, self.F, self.CV = infills.get("X"), F, CV
        self._receive(self.X, F, CV, G, H)
        self._initialize_state()

    def _advance(self, infills=None, **kwargs) -> bool:
        assert self._step is not None and self._pending is not None  # an iteration is open
        F, CV, G, H = self._values_of(infills)
        F, CV = self._pad(len(self._pending), F, CV)
        self._receive(self._pending, F, CV, G, H)
        try:
            self._pending = self._step.send((F, CV))
            return False
        except StopIteration:
            self._step = self._pending = None
            return True

    def _post_advance(self) -> None:
        self._convergence.append(self.best_f)
        self._best_x_history.append(np.array(self.best_x, dtype=float))
        self._pop_stale = True
        super()._post_advance()

    # ---- evaluation -----------------------------------------------------------------------
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
            return self._sanitise(pop.get("X"), F, None) + (None, None)
        G, H = pop.get("G"), pop.get("H")
        return self._sanitise(pop.get("X"), F, constraint_violation(G, H)) + (G, H)

    def _evaluate(self, X: np.ndarray):
        """Evaluate candidates with the vectorized problem, counting n_eval exactly."""
        n = len(X)
        k = budget_left(self._max_evals, self.evaluator.n_eval, n)
        F, CV, G, H = np.empty(0), (np.empty(0) if self._constrained else None), None, None
        if k:
            out = self._problem_values(X if k == n else X[:k])
            self.evaluator.n_eval += k
            F = out["F"][:, 0]
            if self._constrained:
                G, H = out.get("G"), out.get("H")
                CV = constraint_violation(G, H)
            F, CV = self._sanitise(X, F, CV)
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
        raise NotImplementedError("abstract hook: subclasses implement it")
