"""Shared mechanics of moik's population algorithms, as pure functions.

Bound handling (uniform initialization, clipping, the EOSMA midpoint repair of
Eq. 17), the greedy personal-best memory (EOSMA Eq. 18) and feasibility-first
comparisons (Deb's rules: a feasible point beats an infeasible one, two
infeasible ones compare by total violation CV, two feasible ones by f). ``CV``
is ``None`` for unconstrained problems, which keeps their comparisons to a
single ``<``. Mantegna's Levy-stable step is shared by FPA, MPA, HHO, MODA and
I-BES. Randomness only through the ``rng`` keyword (no default). Hyperparameter
validation is :mod:`moik._validate`'s (``interval``, ``integer``, ``flag``).
"""

from __future__ import annotations

import math

import numpy as np


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


def mantegna_sigma(beta: float) -> float:
    """Scale ``sigma_u`` of the numerator in Mantegna's Levy-stable step
    (Mantegna 1994): ``(G(1+b) sin(pi b/2) / (G((1+b)/2) b 2^((b-1)/2)))^(1/b)``."""
    num = math.gamma(1.0 + beta) * math.sin(math.pi * beta / 2.0)
    den = math.gamma((1.0 + beta) / 2.0) * beta * 2.0 ** ((beta - 1.0) / 2.0)
    return (num / den) ** (1.0 / beta)


def mantegna_levy(shape: tuple[int, ...], beta: float, *,
                  rng: np.random.Generator) -> np.ndarray:
    """Symmetric Levy-stable steps ``sigma u / |v|^(1/beta)`` (u, v standard normal,
    drawn in that order), unscaled: FPA, MPA, HHO, MODA and I-BES multiply by
    their own factor (0.01 or 0.05)."""
    u = rng.standard_normal(shape) * mantegna_sigma(beta)
    v = rng.standard_normal(shape)
    return u / np.abs(v) ** (1.0 / beta)
