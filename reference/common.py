"""Shared helpers of the reference-code ports (``reference/__init__.py``): evaluation,
dominance, MATLAB's roulette wheel."""

from __future__ import annotations

import numpy as np

EPS = np.finfo(float).eps


def evaluate(problem, X):
    return problem.evaluate(X, return_values_of=["F"])


def evaluate_cv(problem, X):
    """``(F, CV)``: CV the total violation (positive G plus abs(H)), 0 when feasible."""
    F, G, H = problem.evaluate(X, return_values_of=["F", "G", "H"])
    cv = np.zeros(len(F))
    for part in (np.maximum(G, 0.0) if G is not None else None,
                 np.abs(H) if H is not None else None):
        if part is not None and part.size:
            cv += part.reshape(len(F), -1).sum(axis=1)
    return F, cv


def _dominates(a, b):
    return bool(np.all(a <= b) and np.any(a < b))


def _nondominated(F):
    m = len(F)
    return np.array([not any(_dominates(F[j], F[i]) for j in range(m) if j != i)
                     for i in range(m)], dtype=bool)


def roulette(weights, rng) -> int:
    """RouletteWheelSelection.m (Mirjalili): first index with cumsum > r sum, else -1."""
    acc = np.cumsum(weights)
    hit = np.flatnonzero(acc > rng.random() * acc[-1])
    return int(hit[0]) if hit.size else -1



def nondominated_fast(F):
    leq = np.all(F[:, None, :] <= F[None, :, :], axis=2)  # leq[j, i]: F_j <= F_i
    lt = np.any(F[:, None, :] < F[None, :, :], axis=2)
    return ~np.any(leq & lt, axis=0)


def constrained_nondominated(F, CV):
    """Constraint-domination first (not in the codes; the rule of moik's archives): the
    non-dominated rows among the feasible ones, or among those of the smallest violation."""
    best = CV <= 0.0
    if not best.any():
        best = CV.min() == CV
    keep = np.zeros(len(F), dtype=bool)
    keep[np.flatnonzero(best)[nondominated_fast(F[best])]] = True
    return keep


