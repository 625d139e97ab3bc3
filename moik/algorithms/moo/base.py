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
candidate arrays ``X`` (k, n_var) and receives their objectives ``F`` (k, n_obj).
``next()`` (used by ``minimize``) evaluates them directly; ``ask()/tell()`` hand
the same candidates out as ``Population`` objects; both give identical runs.

``n_eval`` budgets are exact: rows of a batch beyond the budget are not
evaluated, get ``F = inf`` (never accepted by a memory, never archived). The
initial population is always evaluated in full. Constrained problems are
rejected (the papers' archives have no feasibility rule).

The archive attribute is not called ``archive``: pymoo's ``Algorithm`` uses that
name for its own ``pymoo.util.archive.Archive`` (``res.archive``).
"""

from __future__ import annotations

from collections.abc import Generator

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.population import Population
from pymoo.util.display.column import Column
from pymoo.util.display.output import Output

from moik._validate import optional_integer
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.array_state import (
    ArrayStateMixin,
    budget_left,
    check_sizes,
    find_limit,
    finite_bounds,
    initial_population,
    refuse_unknown_keywords,
    schedule_length,
)
from moik.exceptions import ParameterError

Step = Generator[np.ndarray, np.ndarray, None]


def dominates(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """Row-wise Pareto dominance (EOSMA Eq. 11): ``A_i <= B_i`` everywhere, ``<`` somewhere."""
    return np.all(A <= B, axis=1) & np.any(A < B, axis=1)


def pareto_memory(X, F, PX, PF):
    """Eq. 18 with Pareto dominance: the memory keeps ``PX_i`` only if it dominates ``X_i``.

    An equal, incomparable or better new point replaces it (the authors' MOEOSMA.m
    keeps the old point only when it is better in every objective).

    Returns:
        The updated memory ``(PX, PF)`` as new arrays.
    """
    keep = dominates(PF, F)[:, None]
    return np.where(keep, PX, X), np.where(keep, PF, F)


class MOArrayOutput(Output):
    """``verbose=True`` columns: n_gen, n_eval, n_nds (archive size), f<k>_min (k <= 3)."""

    def initialize(self, algorithm) -> None:
        self.columns.append(Column("n_nds", func=lambda a: len(a.pareto_archive), width=7))
        for k in range(min(algorithm.problem.n_obj, 3)):
            self.columns.append(Column(f"f{k + 1}_min",
                                       func=lambda a, k=k: float(a.pareto_archive.F[:, k].min())))


class MOArrayAlgorithm(ArrayStateMixin, Algorithm):
    """Base of moik's multi-objective population algorithms (array state, external archive).

    Public attributes for callbacks (numpy; read, do not mutate): ``X``/``F``
    (last evaluated candidates and their objectives), ``pareto_archive`` (its
    ``X``, ``F``, ``counts``), ``t`` (iteration of the paper's schedule) and
    ``max_iter`` (its length T), plus the arrays each algorithm documents.

    Args:
        pop_size: Population size N (per swarm for multi-swarm methods).
        archive_size: Archive capacity; None means ``pop_size`` (the papers).
        X0: Optional initial points (k rows within the bounds, k at most the
            initial population); the other rows are drawn uniformly.
        max_iter: Schedule length T. None: from an ``n_gen``/``n_eval``
            termination, else 1000.
        **kwargs: pymoo ``Algorithm`` options (``output``, ``callback``, ``seed`` ...,
            :data:`~moik.algorithms.array_state.PYMOO_OPTIONS`).

    Raises:
        ParameterError: For a keyword that is neither a parameter of the algorithm nor
            a pymoo option (the message lists the accepted ones), or a bad size.
    """

    min_pop_size = 2

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 X0: np.ndarray | None = None, max_iter: int | None = None, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        kwargs.setdefault("output", MOArrayOutput())
        super().__init__(**kwargs)
        self.pop_size, self.max_iter = check_sizes(pop_size, self.min_pop_size, max_iter)
        archive_size = optional_integer("archive_size", archive_size, minimum=1)
        self.X0 = X0
        self.archive_size = self.pop_size if archive_size is None else archive_size
        self.X = self.F = self.pareto_archive = None
        self.t = 0

    # ---- lazily built pymoo objects (ArrayStateMixin) -------------------------------------
    def _build_pop(self) -> Population:
        X, F = self._population_arrays()
        return Population.new("X", X, "F", F, "CV", np.zeros((len(F), 1)))

    def _build_opt(self) -> Population:
        """The archive members as a ``Population``."""
        A = self.pareto_archive
        return Population.new("X", A.X.copy(), "F", A.F.copy(), "CV", np.zeros((len(A), 1)))

    # ---- pymoo hooks ----------------------------------------------------------------------
    def _setup(self, problem, **kwargs) -> None:
        name = type(self).__name__
        if problem.n_obj < 2:
            raise ParameterError(f"{name} is multi-objective; the problem has "
                                 f"n_obj={problem.n_obj}")
        if problem.has_constraints():
            raise ParameterError(f"{name} handles unconstrained problems only; the problem has "
                                 f"n_ieq_constr={problem.n_ieq_constr}, "
                                 f"n_eq_constr={problem.n_eq_constr}")
        self.xl, self.xu = finite_bounds(problem, name)
        self._max_evals = find_limit(self.termination, "n_max_evals")
        self.max_iter = schedule_length(self.termination, self.max_iter, self._n_initial(),
                                        self._evals_per_iteration())

    def _initialize_infill(self) -> Population:
        return initial_population(self._n_initial(), self.xl, self.xu, self.X0,
                                  rng=self.random_state)

    def _initialize_advance(self, infills=None, **kwargs) -> None:
        self._step = self._pending = None
        self.pareto_archive = self._make_archive(self.archive_size)
        X, F = infills.get("X"), infills.get("F").astype(float)
        self._buffer = []
        self._receive(X, F)
        self._flush()
        self.X, self.F = X, F
        self._initialize_state()

    def _end_iteration(self) -> None:
        """Merge the iteration's evaluated rows into the archive."""
        self._flush()

    def _advance(self, infills=None, **kwargs) -> bool:
        F = infills.get("F").astype(float) if len(infills) else np.empty((0, self.problem.n_obj))
        self._receive(self._pending[: len(F)], F)
        try:
            self._pending = self._step.send(self._pad(len(self._pending), F))
            return False
        except StopIteration:
            self._step = self._pending = None
            self._flush()
            return True

    def _post_advance(self) -> None:
        self._pop_stale = True
        super()._post_advance()

    # ---- evaluation -----------------------------------------------------------------------
    def _pad(self, n: int, F: np.ndarray) -> np.ndarray:
        """Rows left unevaluated by the budget get ``F = inf``."""
        if len(F) == n:
            return F
        return np.concatenate([F, np.full((n - len(F), self.problem.n_obj), np.inf)])

    def _evaluate(self, X: np.ndarray) -> np.ndarray:
        """Evaluate a batch (vectorized), count n_eval exactly, offer it to the archive."""
        n = len(X)
        k = budget_left(self._max_evals, self.evaluator.n_eval, n)
        if k == 0:
            return self._pad(n, np.empty((0, self.problem.n_obj)))
        F = self.problem.evaluate(X if k == n else X[:k], return_as_dictionary=True)["F"]
        self.evaluator.n_eval += k
        self._receive(X[:k], F)
        return self._pad(n, F)

    def _receive(self, X: np.ndarray, F: np.ndarray) -> None:
        """Queue evaluated rows for the archive (merged once per iteration, see ``_flush``)."""
        if len(F):
            self._buffer.append((X, F))

    def _flush(self) -> None:
        """Merge the iteration's evaluated rows into the archive at once (NonFiniteError on NaN).

        The archive is read only between iterations, so this gives the same
        non-dominated set as a merge per batch; the truncation runs once on the union.
        """
        if self._buffer:
            X = np.concatenate([b[0] for b in self._buffer])
            F = np.concatenate([b[1] for b in self._buffer])
            self._buffer = []
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
        """Expected evaluations per iteration (used to infer T from an n_eval budget)."""
        return float(self.pop_size)

    def _initialize_state(self) -> None:
        """Create per-run arrays after the initial population was evaluated."""

    def _population_arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """Arrays reported as ``pop`` (default: the last evaluated candidates)."""
        return self.X, self.F

    def _generation(self) -> Step:
        """One iteration: yield candidate arrays, receive ``F`` for each."""
        raise NotImplementedError("abstract hook: subclasses implement it")
