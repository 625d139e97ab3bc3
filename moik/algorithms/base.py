"""ArrayAlgorithm: the single-objective array-state base (best so far as incumbent).

The generation driver, the evaluation path, the schedule rule and the lazily built pymoo
objects are those of :class:`moik.algorithms.array_base.ArrayStateAlgorithm`; this
class adds the single-objective parts: the objective check, the ``verbose=True``
columns and the composed :class:`~moik.algorithms.incumbent.BestSoFar`.

Constraints are handled feasibility-first (mechanics.py); an infeasible best is reported
by pymoo's ``Result`` as no solution (``res.X is None``), and so is a best with
non-finite values (a problem's NaN/inf, :mod:`moik.algorithms.nonfinite`).
"""

from __future__ import annotations

import numpy as np
from pymoo.util.display.column import Column
from pymoo.util.display.output import Output

from moik.algorithms.array_base import ArrayStateAlgorithm
from moik.algorithms.array_state import Step
from moik.algorithms.incumbent import BestSoFar
from moik.algorithms.initial_survival import best_rows
from moik.exceptions import ParameterError

__all__ = ["ArrayAlgorithm", "ArrayOutput", "Step"]


def _avg_f(algorithm) -> float | None:
    F = algorithm.F[np.isfinite(algorithm.F)]
    return float(F.mean()) if F.size else None


def _best_cv(algorithm) -> float | None:
    return algorithm.best_cv


def _best_f(algorithm) -> float:
    return algorithm.best_f


class ArrayOutput(Output):
    """``verbose=True`` columns: n_gen, n_eval, [cv_best], f_avg (current), f_best (so far).

    The columns read module-level functions (no lambdas), so an algorithm that ran with
    ``verbose=True`` still pickles."""

    def initialize(self, algorithm) -> None:
        if algorithm.problem.has_constraints():
            self.columns.append(Column("cv_best", func=_best_cv))
        self.columns += [Column("f_avg", func=_avg_f), Column("f_best", func=_best_f)]


class ArrayAlgorithm(ArrayStateAlgorithm):
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
        X0: Optional initial points (k rows within the bounds); the remaining rows are
            drawn uniformly, or, with more than ``pop_size`` rows, the ``pop_size`` best
            are kept (:mod:`moik.algorithms.initial_survival`).
        max_iter: Schedule length T of algorithms whose parameters depend on t/T (the
            papers' Max_t; ``t = 1 .. T``), fixed. None: planned before every iteration
            from the current termination (:mod:`moik.algorithms.array_base`).
        **kwargs: pymoo ``Algorithm`` options (``output``, ``callback``, ``seed`` ...,
            :data:`~moik.algorithms.array_state.PYMOO_OPTIONS`).

    Raises:
        ParameterError: For a keyword that is neither a parameter of the algorithm nor
            a pymoo option (the message lists the accepted ones), or a bad size.
    """

    incumbent: BestSoFar

    def __init__(self, *, pop_size: int = 100, X0: np.ndarray | None = None,
                 max_iter: int | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.incumbent = BestSoFar()

    @property
    def best_x(self) -> np.ndarray:
        """The best point so far (None before the initial population)."""
        return self.incumbent.x  # type: ignore[return-value]

    @property
    def best_f(self) -> float:
        """Its objective value (inf before the initial population)."""
        return self.incumbent.f

    @property
    def best_cv(self) -> float | None:
        """Its total violation (None for unconstrained problems)."""
        return self.incumbent.cv

    @property
    def convergence(self) -> np.ndarray:
        """Best-so-far f after each generation (generation 1 = initial population)."""
        return np.asarray(self.incumbent.history_f, dtype=float)

    @property
    def best_x_history(self) -> np.ndarray:
        """Best-so-far x after each generation, ``(generations, n_var)`` (EOSMA Fig. 19a)."""
        return np.array(self.incumbent.history_x, dtype=float).reshape(-1, self.problem.n_var)

    def _default_output(self) -> Output:
        return ArrayOutput()

    def _check_objectives(self, problem) -> None:
        if problem.n_obj != 1:
            raise ParameterError(f"{type(self).__name__} is single-objective; the problem has "
                                 f"n_obj={problem.n_obj}")

    def _make_incumbent(self) -> BestSoFar:
        return BestSoFar()

    def _initial_survivors(self, F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
        """The best rows, feasibility first
        (:func:`~moik.algorithms.initial_survival.best_rows`)."""
        return best_rows(F, CV, self._n_initial())
