"""Picking one solution from a Pareto front.

MO-m-PSO paper (Rokbani et al. 2022, Section 2.2, Eq. 8 and Algorithm 2): the
compromise solution is the front member closest to the utopia point, the
vector of each objective's minimum over the front. Objectives are first
scaled to [0, 1] over the front so that units (cm vs rad) do not decide.
:func:`compromise` applies it to a run (a pymoo ``Result`` or the algorithm).
"""

from __future__ import annotations

import numpy as np

from moik.exceptions import NonFiniteError, ParameterError, ShapeError


def _check_front(F) -> np.ndarray:
    F = np.asarray(F, dtype=float)
    if F.ndim != 2 or F.shape[0] == 0:
        raise ShapeError(f"front must be a non-empty (n, n_obj) array, got shape {F.shape}")
    if not np.all(np.isfinite(F)):
        raise NonFiniteError("front must be finite, got NaN or inf")
    return F


def normalized_front(F) -> np.ndarray:
    """Each objective scaled to [0, 1] over the front (constant objectives -> 0)."""
    F = _check_front(F)
    lo, hi = F.min(axis=0), F.max(axis=0)
    span = np.where(hi > lo, hi - lo, 1.0)
    return (F - lo) / span


def closest_to_utopia(F, *, normalize: bool = True) -> int:
    """Index of the front member closest (Euclidean) to the utopia point (Eq. 8)."""
    Z = normalized_front(F) if normalize else _check_front(F) - _check_front(F).min(axis=0)
    return int(np.argmin(np.linalg.norm(Z, axis=1)))


def weighted_choice(F, weights) -> int:
    """Index minimising the weighted sum of normalized objectives."""
    Z = normalized_front(F)
    w = np.asarray(weights, dtype=float)
    if w.shape != (Z.shape[1],) or np.any(w < 0) or not np.isfinite(w).all() or w.sum() == 0:
        raise ParameterError(
            f"weights must be {Z.shape[1]} finite non-negative numbers, not all zero; got {weights}"
        )
    return int(np.argmin(Z @ w))


def compromise(res_or_algorithm) -> tuple[np.ndarray, np.ndarray]:
    """The front member closest to the utopia point (Eq. 8) of a run, as ``(x, f)`` copies.

    Args:
        res_or_algorithm: A multi-objective pymoo ``Result`` or the algorithm that ran.
            The front is the algorithm's external archive when it keeps one (moik's
            multi-objective algorithms, ``pareto_archive``), else the result's
            ``X``/``F`` (or the algorithm's ``opt``).

    Raises:
        ShapeError: If there is no front yet (the algorithm has not run).
    """
    X, F = _front_of(res_or_algorithm)
    if X is None or F is None or len(F) == 0:
        raise ShapeError("no archive yet: run the algorithm before compromise()")
    i = closest_to_utopia(F)
    return np.array(X[i], dtype=float), np.array(F[i], dtype=float)


def _front_of(run) -> tuple[np.ndarray | None, np.ndarray | None]:
    """``(X, F)`` of a run's front (see :func:`compromise`)."""
    algorithm = getattr(run, "algorithm", run)
    archive = getattr(algorithm, "pareto_archive", None)
    if archive is not None:
        return archive.X, archive.F
    if hasattr(run, "F") and hasattr(run, "X") and run is not algorithm:
        return (None, None) if run.F is None else (np.atleast_2d(run.X), np.atleast_2d(run.F))
    opt = getattr(algorithm, "opt", None)
    if opt is None or len(opt) == 0:
        return None, None
    return opt.get("X"), opt.get("F")
