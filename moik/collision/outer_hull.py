"""A convex polytope with few vertices that holds a point set's convex hull.

The exact stage measures a pair of hulls with GJK (:mod:`moik.collision.gjk`), whose
support search runs over every vertex of a hull: a high-poly collision mesh (a visual
mesh shipped as the collision one, thousands of vertices per slab) makes each distance
tens of times slower than a collision mesh of a few hundred triangles. A hull with more
than :data:`MAX_EXACT_VERTICES` vertices is therefore replaced by an *enclosing* polytope
(cutting planes): it starts from the six planes across the hull's principal axes, each
at the hull's extent, and adds, for the vertices of the current polytope farthest
outside the hull, the hull's own facet planes that cut them off the most, until no
vertex is more than ``tol`` outside the hull's facet planes (:data:`OUTER_TOL`, 0.5 mm)
or :data:`MAX_PLANES` planes are used. Every plane is a supporting plane of the points
(its offset is their largest projection), so the polytope holds the hull: a distance
measured on it never exceeds the mesh's, the soundness of the exact stage stands, and it
gives away about ``tol`` of clearance (a vertex at a corner can lie a little farther from
the hull than from its facet planes; tests/collision/test_outer_hull.py bounds it by
``2 tol``). A hull whose replacement would not have
fewer vertices, or that is flat, is kept as it is.
"""

from __future__ import annotations

import numpy as np

MAX_EXACT_VERTICES = 128  # hulls up to this many vertices are kept exactly
OUTER_TOL = 5e-4  # m: how far a vertex of the replacement may lie outside the hull's facets
MAX_PLANES = 600  # planes of a replacement at most (about twice as many vertices)
_BATCH = 8  # vertices cut off per round, and a quarter of the planes so far
_GROW = 1e-9  # relative outward push of the replacement's vertices (rounding of qhull)


def enclosing_polytope(points: np.ndarray, *, max_exact: int = MAX_EXACT_VERTICES,
                       tol: float = OUTER_TOL) -> np.ndarray:
    """The vertices of a convex polytope holding ``points`` ``(n, 3)``: their hull's own
    vertices when there are at most ``max_exact`` of them, else those of the cutting-plane
    polytope described in the module docstring (fewer vertices, at most about ``tol``
    outside the hull)."""
    from scipy.spatial import ConvexHull, HalfspaceIntersection, QhullError

    P = np.asarray(points, dtype=float)
    try:
        hull = ConvexHull(P)
    except (QhullError, ValueError):
        return P
    V = P[hull.vertices]
    if len(V) <= max_exact:
        return V
    N, h = hull.equations[:, :3], -hull.equations[:, 3]
    centre = V.mean(axis=0)
    _, axes = np.linalg.eigh(np.cov((V - centre).T))
    D = np.vstack([axes.T, -axes.T])
    try:
        while True:
            offsets = (V @ D.T).max(axis=0)  # supporting planes of the points themselves
            W = HalfspaceIntersection(np.c_[D, -offsets], centre).intersections
            excess = W @ N.T - h
            worst = excess.max(axis=1)
            if worst.max() <= tol or len(D) >= MAX_PLANES:
                break
            cut = {int(np.argmax(excess[i])) for i in np.argsort(-worst)[:_BATCH + len(D) // 4]
                   if worst[i] > tol}
            D = np.vstack([D, N[sorted(cut)]])
        W = centre + (W - centre) * (1.0 + _GROW)
        outer = ConvexHull(W)
    except (QhullError, ValueError):
        return V
    W = W[outer.vertices]
    inside = (V @ outer.equations[:, :3].T + outer.equations[:, 3]).max() <= 0.0
    return W if inside and len(W) < len(V) else V
