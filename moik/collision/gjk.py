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
def _solve_small(G: np.ndarray, rhs: np.ndarray, n: int, mu: np.ndarray) -> bool:
    """``G[:n, :n] mu = rhs[:n]`` for ``n <= 3`` by Cramer's rule; False when singular."""
    if n == 1:
        if G[0, 0] <= 1e-300:
            return False
        mu[0] = rhs[0] / G[0, 0]
        return True
    if n == 2:
        det = G[0, 0] * G[1, 1] - G[0, 1] * G[1, 0]
        if abs(det) <= 1e-300:
            return False
        mu[0] = (rhs[0] * G[1, 1] - G[0, 1] * rhs[1]) / det
        mu[1] = (G[0, 0] * rhs[1] - rhs[0] * G[1, 0]) / det
        return True
    c0 = G[1, 1] * G[2, 2] - G[1, 2] * G[2, 1]
    c1 = G[1, 0] * G[2, 2] - G[1, 2] * G[2, 0]
    c2 = G[1, 0] * G[2, 1] - G[1, 1] * G[2, 0]
    det = G[0, 0] * c0 - G[0, 1] * c1 + G[0, 2] * c2
    if abs(det) <= 1e-300:
        return False
    for col in range(3):
        d = 0.0
        for row in range(3):
            # the determinant with column ``col`` replaced by rhs, expanded along that column
            r1, r2 = (row + 1) % 3, (row + 2) % 3
            a1, a2 = (col + 1) % 3, (col + 2) % 3
            minor = G[r1, a1] * G[r2, a2] - G[r1, a2] * G[r2, a1]
            d += rhs[row] * minor
        mu[col] = d / det
    return True


@jit
def _closest_on_simplex(S: np.ndarray, k: int, out: np.ndarray) -> int:
    """The point of the simplex ``S[:k]`` nearest the origin into ``out``; its face's
    vertices are moved to the front of ``S``; returns their number.

    Every face is tried (the affine projection of the origin with positive barycentric
    weights and the smallest norm wins). A point chosen wrongly (near-singular faces) is
    still a point of the simplex: GJK converges more slowly, its bound stays valid."""
    best, best_mask = np.inf, 0
    E = np.empty((3, 3))
    G = np.empty((3, 3))
    rhs = np.empty(3)
    mu = np.empty(3)
    lam = np.empty(4)
    idx = np.empty(4, dtype=np.int64)
    x = np.empty(3)
    for mask in range(1, 1 << k):
        m = 0
        for i in range(k):
            if mask & (1 << i):
                idx[m] = i
                m += 1
        if m == 1:
            lam[0] = 1.0
        else:
            for a in range(m - 1):
                for c in range(3):
                    E[a, c] = S[idx[a + 1], c] - S[idx[0], c]
            for a in range(m - 1):
                rhs[a] = -(E[a, 0] * S[idx[0], 0] + E[a, 1] * S[idx[0], 1]
                           + E[a, 2] * S[idx[0], 2])
                for b in range(m - 1):
                    G[a, b] = E[a, 0] * E[b, 0] + E[a, 1] * E[b, 1] + E[a, 2] * E[b, 2]
            if not _solve_small(G, rhs, m - 1, mu):
                continue
            lam[0] = 1.0
            for a in range(m - 1):
                lam[a + 1] = mu[a]
                lam[0] -= mu[a]
        positive = True
        for a in range(m):
            if lam[a] <= 0.0:
                positive = False
        if not positive:
            continue
        for c in range(3):
            x[c] = 0.0
            for a in range(m):
                x[c] += lam[a] * S[idx[a], c]
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
    keep = np.empty((4, 3))
    for i in range(k):
        if best_mask & (1 << i):
            keep[m] = S[i]
            m += 1
    S[:m] = keep[:m]
    return m


@jit
def hull_distance_bound(A: np.ndarray, ra: float, B: np.ndarray, rb: float,
                        enough: float = np.inf) -> float:
    """A lower bound on the distance between ``hull(A) + ra`` and ``hull(B) + rb``
    (``(n, 3)`` points, same frame); ``-inf`` when the hulls are not separated. It
    returns as soon as the bound reaches ``enough`` (default: converged)."""
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
                if lower - ra - rb - MARGIN >= enough:
                    break
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
