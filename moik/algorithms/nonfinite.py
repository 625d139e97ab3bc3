"""Points where a problem returns NaN or infinite values: infeasible and worst, never reported.

Some problems are undefined at some points (pymoo's CTP2-CTP5 and truss2d on their
bounds, several MW problems): they return NaN or inf in ``F``, ``G`` or ``H``. Such a
value is a fact about that point, not a reason to stop a run.

How pymoo treats them (pymoo 0.6.2, read from its source): nothing replaces them unless
the problem asks (``Problem(replace_nan_values_by=...)``, ``core/problem.py``); a NaN
constraint gives a NaN violation (``core/individual.py: calc_cv``), whose feasibility
flag ``CV <= 0`` is False, so the point is infeasible (``core/survival.py:
split_by_feasibility``) and, sorted by ``np.argsort`` of the violations, ranked after
every finite violation; ``util/optimum.py: filter_optimum`` reports only feasible points
unless ``return_least_infeasible=True``. A NaN objective with finite constraints is not
handled (its comparisons are all False, so it is never dominated and can reach
``res.F``).

moik makes the rule explicit and total, in one place of the array-state evaluation path
(:func:`sanitise`, called by both bases on every evaluated batch, the initial population
and ``ask()/tell()`` included): a row with any NaN or infinite objective, or a NaN or
infinite total violation (a NaN or ``+inf`` in ``G``, a NaN or infinite ``H``), gets
``F = inf`` in every objective and ``CV = inf``: infeasible and worse than every point
with finite values (pymoo's ranking of a NaN violation, extended to NaN objectives).
Memories never accept it, rankings put it last, the external archives never receive it
and the single-objective best-so-far is reported only when its values are finite (else
``res.X`` is None). The first such batch of a run issues one
:class:`~moik.exceptions.NonFiniteValuesWarning` naming the problem and a point.
"""

from __future__ import annotations

import warnings

import numpy as np

from moik.exceptions import NonFiniteValuesWarning

__all__ = ["finite_rows", "sanitise"]


def finite_rows(F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
    """Mask of the rows whose objectives (``(n,)`` or ``(n, m)``) and violation are finite."""
    ok = np.isfinite(F) if F.ndim == 1 else np.isfinite(F).all(axis=1)
    if CV is not None:
        ok &= np.isfinite(CV)
    return ok


def sanitise(X: np.ndarray, F: np.ndarray, CV: np.ndarray | None, *, problem: object,
             warned: bool) -> tuple[np.ndarray, np.ndarray | None, bool]:
    """``(F, CV, warned)`` with every non-finite row set to ``F = CV = inf`` (module doc).

    The inputs are returned as they are when every row is finite (the common case costs
    one ``isfinite`` pass); otherwise copies. ``CV`` stays None for unconstrained problems.

    Args:
        X: The evaluated points (rows matching ``F``; named in the warning).
        F: Their objective values, ``(n,)`` or ``(n, m)``.
        CV: Their total constraint violations ``(n,)``, or None.
        problem: The problem (named in the warning).
        warned: Whether this run has warned already (no second warning).

    Returns:
        The sanitised ``F`` and ``CV`` and the new ``warned`` flag.
    """
    if np.isfinite(F).all() and (CV is None or np.isfinite(CV).all()):
        return F, CV, warned
    ok = finite_rows(F, CV)
    bad = np.flatnonzero(~ok)
    F = np.array(F, dtype=float)
    F[bad] = np.inf
    if CV is not None:
        CV = np.array(CV, dtype=float)
        CV[bad] = np.inf
    if not warned:
        warnings.warn(
            f"{type(problem).__name__} returned NaN or infinite objective or constraint "
            f"values at {bad.size} of {len(ok)} points (first: x = {np.asarray(X)[bad[0]]}); "
            f"moik treats such points as infeasible and worst (F = CV = inf) and never "
            f"reports them (warned once per run)", NonFiniteValuesWarning, stacklevel=4)
    return F, CV, True
