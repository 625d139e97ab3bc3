"""The evaluation helpers of the array-state base (:mod:`moik.algorithms.array_base`).

pymoo's contract: the initial population and ``ask()/tell()`` go through the algorithm's
``Evaluator``; after them, a batch goes through ``algorithm.evaluator`` too whenever
anything is attached to it (:func:`evaluator_attached`: an Evaluator subclass or
callback, the ``archive=`` option, a problem with ``requires_kwargs=True``, which then
receives ``algorithm=``), else through the array fast path (:func:`problem_values`:
``problem.evaluate`` on the array, counting ``evaluator.n_eval`` exactly; the same values
without building a ``Population``). ``benchmarks/evaluator_path.py`` prints both paths'
per-generation cost. An algorithm that evaluates one row at a time (MOEA/D) asks
:func:`compiled_objectives` for the problem's compiled objectives, where the fast path
applies.
"""

from __future__ import annotations

import numpy as np
from pymoo.core.evaluator import Evaluator
from pymoo.core.problem import Problem

from moik.algorithms.mechanics import constraint_violation

__all__ = ["DEFAULT_VALUES", "constraint_values", "evaluator_attached", "pad",
           "problem_values", "compiled_objectives", "values_asked"]

DEFAULT_VALUES = ["F", "G", "H"]
"""pymoo's ``Evaluator`` default ``evaluate_values_of``."""


def constraint_values(G, H, n: int) -> tuple[np.ndarray, np.ndarray]:
    """``(CV, GH)`` of ``n`` rows: total violations (pymoo's default rule) and the
    constraint values G and H side by side (a missing one has no columns)."""
    G = np.zeros((n, 0)) if G is None else np.asarray(G, float).reshape(n, -1)
    H = np.zeros((n, 0)) if H is None else np.asarray(H, float).reshape(n, -1)
    return constraint_violation(G, H), np.concatenate([G, H], axis=1)


def pad(n: int, F: np.ndarray, CV: np.ndarray | None):
    """``(F, CV)`` of ``n`` rows: rows left unevaluated by the budget get ``F = CV = inf``."""
    k = len(F)
    if k == n:
        return F, CV
    F = np.concatenate([F, np.full((n - k,) + F.shape[1:], np.inf)])
    return F, None if CV is None else np.concatenate([CV, np.full(n - k, np.inf)])


def evaluator_attached(evaluator, archive, problem) -> bool:
    """Whether anything is attached to pymoo's evaluation (then every batch goes through
    ``evaluator``): an Evaluator subclass or callback, an ``archive``, or a problem with
    ``requires_kwargs=True``."""
    return (type(evaluator) is not Evaluator or evaluator.callback is not None
            or archive is not None or bool(getattr(problem, "requires_kwargs", False)))


def values_asked(problem, evaluator) -> list[str] | None:
    """What the fast path asks ``problem.evaluate`` for: pymoo's default (F, and G/H when
    the problem has them) for a plain problem and the default values; else the
    Evaluator's ``evaluate_values_of`` (meta-problems such as ``ConstraintsAsPenalty``
    override ``do`` and need G and H)."""
    asked = evaluator.evaluate_values_of
    return None if type(problem).do is Problem.do and asked == DEFAULT_VALUES else list(asked)


def problem_values(problem, X: np.ndarray, *, constrained: bool,
                   asked: list[str] | None) -> dict:
    """``problem.evaluate(X, return_values_of=asked, return_as_dictionary=True)``; an
    unconstrained problem that offers ``batch_objectives(X)`` (moik's IK problems: the same
    F bit for bit, without pymoo's per-call bookkeeping) is asked that instead, unless it
    answers None."""
    direct = None if constrained else getattr(problem, "batch_objectives", None)
    if direct is not None:
        F = direct(X)
        if F is not None:
            return {"F": F}
    return problem.evaluate(X, return_values_of=asked, return_as_dictionary=True)


def compiled_objectives(problem, evaluator, archive, *, constrained: bool):
    """The problem's ``compiled_objectives()`` (moik's IK problems: a numba object that
    compiled code evaluates rows with, :func:`moik._jit.objectives_row`, bit for bit
    ``evaluate``'s) when the fast path applies (nothing attached to ``evaluator``, no
    constraints); else None."""
    if constrained or evaluator_attached(evaluator, archive, problem):
        return None
    make = getattr(problem, "compiled_objectives", None)
    return None if make is None else make()
