"""Compiled GJK: a guaranteed lower bound on the distance between two convex hulls.

A convex body here is the convex hull of a point set, swept by a sphere of radius ``r``
(``r = 0``: the hull itself; a capsule is its two end points and its radius, a sphere its
centre and radius, a box its eight corners). :func:`hull_distance_bound` runs GJK
(Gilbert, Johnson, Keerthi 1988) on the Minkowski difference ``A - B``: each iteration
keeps a simplex of support points, its point ``v`` closest to the origin (found by trying
every face of the simplex: the affine projection with all barycentric weights positive
and the smallest norm), and the new support point ``w`` of ``A - B`` in direction ``-v``.

What it returns is a *lower* bound, never an estimate: for every point ``x`` of
``A - B``, ``x . v >= w . v`` (``w`` is the support point), so the hulls are at least
``w . v / |v|`` apart; the largest such bound met is returned, minus the radii and a
rounding margin (:data:`MARGIN`). When the hulls intersect (or GJK cannot separate them
within :data:`MAX_ITERATIONS`) the bound is ``-inf``: the caller keeps its own (bounding
shape) distance. The tests check it against coal on meshes.

A half-space ``n . x <= c`` (a table) against a hull: the exact signed distance is
``min over the points of (n . p - c) - r`` (:func:`halfspace_distance`).
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit

MAX_ITERATIONS = 64
MARGIN = 1e-12  # m subtracted from every bound (rounding of the dot products)
REL_TOL = 1e-9  # stop when the upper and lower bounds agree to this fraction


@jit
def _support(P: np.ndarray, d0: float, d1: float, d2: float) -> int:
    best, arg = -np.inf, 0
    for i in range(P.shape[0]):
        s = P[i, 0] * d0 + P[i, 1] * d1 + P[i, 2] * d2
        if s > best:
            best, arg = s, i
    return arg


@jit
def _closest_on_simplex(S: np.ndarray, k: int, out: np.ndarray) -> int:
    """The point of the simplex ``S[:k]`` nearest the origin into ``out``; its face's
    vertices are moved to the front of ``S``; returns their number."""
    best, best_mask = np.inf, 0
    E = np.zeros((3, 3))
    for mask in range(1, 1 << k):
        idx = np.zeros(4, dtype=np.int64)
        m = 0
        for i in range(k):
            if mask & (1 << i):
                idx[m] = i
                m += 1
        lam = np.zeros(4)
        if m == 1:
            lam[0] = 1.0
        else:
            p0 = S[idx[0]]
            for a in range(m - 1):
                for c in range(3):
                    E[a, c] = S[idx[a + 1], c] - p0[c]
            G = np.zeros((m - 1, m - 1))
            rhs = np.zeros(m - 1)
            for a in range(m - 1):
                rhs[a] = -(E[a, 0] * p0[0] + E[a, 1] * p0[1] + E[a, 2] * p0[2])
                for b in range(m - 1):
                    G[a, b] = E[a, 0] * E[b, 0] + E[a, 1] * E[b, 1] + E[a, 2] * E[b, 2]
            if abs(np.linalg.det(G)) <= 1e-300:
                continue
            mu = np.linalg.solve(G, rhs)
            lam[0] = 1.0 - mu.sum()
            for a in range(m - 1):
                lam[a + 1] = mu[a]
        if lam[:m].min() <= 0.0:
            continue
        x = np.zeros(3)
        for a in range(m):
            x += lam[a] * S[idx[a]]
        n2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2]
        if n2 < best:
            best, best_mask = n2, mask
            out[:] = x
    if best_mask == 0:  # numerically degenerate: keep the nearest vertex
        j = 0
        for i in range(k):
            if S[i] @ S[i] < S[j] @ S[j]:
                j = i
        out[:] = S[j]
        S[0] = S[j].copy()
        return 1
    m = 0
    keep = np.zeros((4, 3))
    for i in range(k):
        if best_mask & (1 << i):
            keep[m] = S[i]
            m += 1
    S[:m] = keep[:m]
    return m


@jit
def hull_distance_bound(A: np.ndarray, ra: float, B: np.ndarray, rb: float) -> float:
    """A lower bound on the distance between ``hull(A) + ra`` and ``hull(B) + rb``
    (``(n, 3)`` points, same frame); ``-inf`` when the hulls are not separated."""
    S = np.zeros((4, 3))
    v = A[0] - B[0]
    S[0] = v
    k = 1
    lower = -np.inf
    for _ in range(MAX_ITERATIONS):
        vv = v @ v
        if vv <= 1e-30:
            return -np.inf  # the origin is in the difference: the hulls touch
        w = A[_support(A, -v[0], -v[1], -v[2])] - B[_support(B, v[0], v[1], v[2])]
        vw = v @ w
        if vw > 0.0:
            bound = vw / np.sqrt(vv)
            if bound > lower:
                lower = bound
        if vv - vw <= REL_TOL * vv:
            break
        if k == 4:
            return -np.inf
        S[k] = w
        k += 1
        k = _closest_on_simplex(S, k, v)
        if k == 4:
            return -np.inf  # the origin is inside the tetrahedron
    if lower == -np.inf:
        return -np.inf
    return lower - ra - rb - MARGIN


@jit
def halfspace_distance(P: np.ndarray, r: float, normal: np.ndarray, offset: float) -> float:
    """The signed distance of ``hull(P) + r`` from the half-space ``normal . x <= offset``
    (``normal`` a unit vector): negative when they overlap, by the depth."""
    best = np.inf
    for i in range(P.shape[0]):
        s = P[i, 0] * normal[0] + P[i, 1] * normal[1] + P[i, 2] * normal[2] - offset
        if s < best:
            best = s
    return best - r
