"""The smallest circle around 2-D points (Welzl's algorithm), compiled.

Used by the capsule fits (:mod:`moik.collision.fit`): a fit of a high-poly mesh finds
hundreds of circles around thousands of hull vertices each. The points are taken in a
fixed shuffled order (seed 0, so a fit is the same on every run); each loop looks for the
next point outside the current circle, by more than ``tol`` in squared distance.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from moik._jit import jit


@jit
def _first_outside(X, start, stop, c, r2):
    """The first index in ``[start, stop)`` whose point lies outside the circle ``c``
    (centre ``c[0], c[1]``, squared radius ``r2``, tolerance ``c[2]``), or ``stop``."""
    for m in range(start, stop):
        dx, dy = X[m, 0] - c[0], X[m, 1] - c[1]
        if dx * dx + dy * dy > r2 + c[2]:
            return m
    return stop


@jit
def _d2(ax, ay, bx, by):
    """The squared distance of two points (a kernel of its own: six call sites)."""
    return (ax - bx) * (ax - bx) + (ay - by) * (ay - by)


@jit
def _circle_of_three(X, i, j, k, c):
    """Set ``c[:2]`` to the centre of the smallest circle through (or, collinear, around)
    points ``i, j, k``; return its squared radius."""
    px, py, qx, qy, sx, sy = X[i, 0], X[i, 1], X[j, 0], X[j, 1], X[k, 0], X[k, 1]
    ax, ay, bx, by = qx - px, qy - py, sx - px, sy - py
    den = 2.0 * (ax * by - ay * bx)
    if den != 0.0:
        a2, b2 = ax * ax + ay * ay, bx * bx + by * by
        c[0], c[1] = px + (by * a2 - ay * b2) / den, py + (ax * b2 - bx * a2) / den
    else:  # collinear: the circle on the farthest pair (the first such pair on ties)
        dpq, dps, dqs = _d2(px, py, qx, qy), _d2(px, py, sx, sy), _d2(qx, qy, sx, sy)
        if dpq >= dps and dpq >= dqs:
            c[0], c[1] = (px + qx) / 2, (py + qy) / 2
        elif dps >= dqs:
            c[0], c[1] = (px + sx) / 2, (py + sy) / 2
        else:
            c[0], c[1] = (qx + sx) / 2, (qy + sy) / 2
    return max(_d2(px, py, c[0], c[1]), _d2(qx, qy, c[0], c[1]), _d2(sx, sy, c[0], c[1]))


@jit
def _welzl(X, tol):
    """The smallest circle's centre around the rows of ``X`` (iterative Welzl)."""
    n = X.shape[0]
    c = np.array([X[0, 0], X[0, 1], tol])
    r2 = 0.0
    i = _first_outside(X, 0, n, c, r2)
    while i < n:
        c[0], c[1], r2 = X[i, 0], X[i, 1], 0.0
        j = _first_outside(X, 0, i, c, r2)
        while j < i:
            c[0], c[1] = (X[i, 0] + X[j, 0]) / 2, (X[i, 1] + X[j, 1]) / 2
            r2 = _d2(X[i, 0], X[i, 1], c[0], c[1])
            k = _first_outside(X, 0, j, c, r2)
            while k < j:
                r2 = _circle_of_three(X, i, j, k, c)
                k = _first_outside(X, k + 1, j, c, r2)
            j = _first_outside(X, j + 1, i, c, r2)
        i = _first_outside(X, i + 1, n, c, r2)
    return c[0], c[1]


def smallest_circle_centre(X: Any) -> tuple[float, float]:
    """The centre of the smallest circle around the 2-D points ``X`` ``(n, 2)``, ``n >= 1``
    (found to a relative tolerance of 1e-12 of the points' span)."""
    P = np.asarray(X, dtype=float)
    order = np.random.default_rng(0).permutation(len(P))
    span = float(np.ptp(P, axis=0).max())
    cx, cy = _welzl(np.ascontiguousarray(P[order]), (1e-12 * span) ** 2)
    return float(cx), float(cy)
