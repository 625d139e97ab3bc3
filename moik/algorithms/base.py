"""ArrayAlgorithm: a pymoo ``Algorithm`` whose state lives in numpy arrays.

pymoo builds ``Population``/``Individual`` objects every generation, which costs
25-40x the update rule of a swarm algorithm at N=100, dim=7 (docs: design.md).
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

Constraints are handled feasibility-first (Deb's rules): a feasible solution
beats an infeasible one, two infeasible ones compare by total violation ``CV``
(``G`` clipped at zero plus ``|H|`` beyond pymoo's 1e-4), two feasible ones by
``f``. An infeasible best is reported by pymoo's ``Result`` as no solution.

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

from moik.exceptions import NonFiniteError, ParameterError, ShapeError

Step = Generator[np.ndarray, tuple, None]


def uniform_population(n: int, xl: np.ndarray, xu: np.ndarray, *, rng: np.random.Generator):
    """Return ``n`` points drawn uniformly in the box ``[xl, xu]``, shape (n, dim)."""
    return xl + rng.random((n, xl.size)) * (xu - xl)


def clip_to_bounds(X: np.ndarray, xl: np.ndarray, xu: np.ndarray) -> np.ndarray:
    """Return ``X`` with every coordinate clipped into ``[xl, xu]``."""
    return np.minimum(np.maximum(X, xl), xu)


def midpoint_repair(X_new: np.ndarray, X_old: np.ndarray, xl: np.ndarray, xu: np.ndarray):
    """EOSMA Eq. 17: a coordinate beyond a bound moves halfway from its old value to it."""
    hi, lo = X_new > xu, X_new < xl
    if not (hi.any() or lo.any()):
        return X_new
    X = np.where(hi, (X_old + xu) / 2.0, X_new)
    return np.where(lo, (X_old + xl) / 2.0, X)


def constraint_violation(G: np.ndarray | None, H: np.ndarray | None, eq_tol: float = 1e-4):
    """Total violation per row (pymoo's default: sum of G+ and of |H| beyond ``eq_tol``)."""
    cv = 0.0
    if G is not None and G.size:
        cv = cv + np.maximum(G, 0.0).sum(axis=1)
    if H is not None and H.size:
        cv = cv + np.maximum(np.abs(H) - eq_tol, 0.0).sum(axis=1)
    return np.asarray(cv, dtype=float)


def is_better(f1, cv1, f2, cv2):
    """Feasibility-first strict comparison; ``cv1 is None`` means unconstrained."""
    if cv1 is None:
        return f1 < f2
    return (cv1 < cv2) | ((cv1 == cv2) & (f1 < f2))


def greedy_memory(X, F, CV, PX, PF, PCV):
    """EOSMA Eq. 18: keep a new point in the memory only if strictly better.

    Returns:
        The updated memory ``(PX, PF, PCV)`` as new arrays.
    """
    better = is_better(F, CV, PF, PCV)
    PX = np.where(better[:, None], X, PX)
    PCV = None if CV is None else np.where(better, CV, PCV)
    return PX, np.where(better, F, PF), PCV


def ranking_fitness(F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
    """A scalar with the feasibility-first order: F if feasible, else worst feasible F + CV."""
    if CV is None:
        return F
    feas = CV <= 0.0
    worst = F[feas].max() if feas.any() else 0.0
    return np.where(feas, F, worst + CV)


def best_index(F: np.ndarray, CV: np.ndarray | None) -> int:
    """Index of the feasibility-first best row."""
    if CV is None:
        return int(np.argmin(F))
    feas = CV <= 0.0
    if feas.any():
        idx = np.flatnonzero(feas)
        return int(idx[np.argmin(F[idx])])
    return int(np.argmin(CV))


def check_param(name: str, value, lo: float, hi: float, *, lo_open: bool = False,
                hi_open: bool = False) -> float:
    """Return ``value`` as float if it lies in the range, else raise ParameterError."""
    ok = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)
    v = float(value) if ok else np.nan
    ok = ok and (lo < v if lo_open else lo <= v) and (v < hi if hi_open else v <= hi)
    if not ok:
        rng = f"{'(' if lo_open else '['}{lo}, {hi}{')' if hi_open else ']'}"
        raise ParameterError(f"{name} must be a number in {rng}, got {value!r}")
    return v


def _find_limit(termination, attr: str) -> float:
    """Smallest ``attr`` (n_max_gen / n_max_evals) among any-of termination criteria."""
    limit = getattr(termination, attr, None)
    limit = np.inf if limit is None else float(limit)
    if isinstance(termination, (TerminateIfAny, DefaultTermination)):
        for sub in termination.criteria:
            limit = min(limit, _find_limit(sub, attr))
    return limit


def _best_f(algorithm):
    return algorithm.best_f


def _best_cv(algorithm):
    return algorithm.best_cv


def _avg_f(algorithm):
    F = algorithm.F[np.isfinite(algorithm.F)]
    return float(F.mean()) if F.size else None


class ArrayOutput(Output):
    """``verbose=True`` columns: n_gen, n_eval, [cv_best], f_avg (current), f_best (so far)."""

    def initialize(self, algorithm) -> None:
        if algorithm.problem.has_constraints():
            self.columns.append(Column("cv_best", func=_best_cv))
        self.columns += [Column("f_avg", func=_avg_f), Column("f_best", func=_best_f)]


class ArrayAlgorithm(Algorithm):
    """Base of moik's single-objective population algorithms (array state).

    Public attributes for callbacks (all numpy, read them, do not mutate):
    ``X``/``F``/``CV`` (last evaluated candidates, their objective and violation;
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

    def __init__(
        self,
        *,
        pop_size: int = 100,
        X0: np.ndarray | None = None,
        max_iter: int | None = None,
        **kwargs,
    ):
        kwargs.setdefault("output", ArrayOutput())
        super().__init__(**kwargs)
        if (
            isinstance(pop_size, bool)
            or not isinstance(pop_size, (int, np.integer))
            or pop_size < self.min_pop_size
        ):
            raise ParameterError(
                f"pop_size must be an integer >= {self.min_pop_size}, got {pop_size!r}"
            )
        if max_iter is not None and (not isinstance(max_iter, (int, np.integer)) or max_iter < 1):
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
            raise ParameterError(
                f"{type(self).__name__} is single-objective; the problem has n_obj={problem.n_obj}"
            )
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
                raise ShapeError(
                    f"X0 must have shape (k, {n_var}) with 1 <= k <= pop_size="
                    f"{self.pop_size}, got {X0.shape}"
                )
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
        k = self._budget_left(n)
        if k == 0:
            F, G, H = np.empty(0), None, None
            CV = np.empty(0) if self._constrained else None
        else:
            out = self.problem.evaluate(X if k == n else X[:k], return_as_dictionary=True)
            self.evaluator.n_eval += k
            F, G, H = out["F"][:, 0], out.get("G"), out.get("H")
            CV = constraint_violation(G, H) if self._constrained else None
        F, CV = self._pad(n, F, CV)
        self._receive(X, F, CV, G, H)
        return F, CV

    def _receive(self, X, F, CV, G, H) -> None:
        """Update the best so far with an evaluated batch."""
        i = best_index(F, CV)
        cv_i = None if CV is None else CV[i]
        if self.best_x is None or is_better(F[i], cv_i, self.best_f, self.best_cv):
            self.best_x, self.best_f, self.best_cv = X[i].copy(), float(F[i]), cv_i
            self._best_gh = {
                k: np.array(v[i]) for k, v in (("G", G), ("H", H)) if v is not None and i < len(v)
            }
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
