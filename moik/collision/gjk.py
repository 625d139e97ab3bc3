"""Signed distances of convex hulls (meshes' hulls) to the other shapes, compiled: GJK.

The exact stage of a mesh link: its collision mesh's convex hull (a
:class:`~moik.collision.shapes.ConvexHull`, vertices in its own frame) holds the mesh, so
the hull's distance to another shape is at most the mesh's: a pair whose hull distance
keeps the clearance keeps it for the mesh too (sound), and a hull is as close to the mesh
as a convex set can be (tight where the mesh is convex near the contact).

Distances of a hull to a sphere, a capsule, a box or another hull are computed by the
Gilbert-Johnson-Keerthi algorithm on the Minkowski difference of the two *cores* (the hull's
vertices, a box's corners, a sphere's centre, a capsule's segment; spheres and capsules add
their radius afterwards), with the closest point of each simplex by Voronoi regions
(Gilbert, Johnson & Keerthi, IEEE J. Robotics Autom. 4(2), 1988; Ericson, *Real-Time
Collision Detection*, 2005, Sections 5.1.5, 5.1.6 and 9.5). Each iteration gives an upper
bound ``|v|`` and a lower bound ``v . w / |v|`` of the cores' distance; the returned
distance is the lower bound (never above the true distance: a separated answer is never
larger than the truth), reached within :data:`REL_TOL` of the upper one.

When the cores overlap, the returned depth is the overlap of the two sets along the line
of their centres (an upper bound of the true penetration depth: the signed distance is
never overestimated), with that line as the normal. Against a half-space the distance is
the deepest vertex's, exact.

Every function returns ``(d, nx, ny, nz, ax, ay, az, bx, by, bz)`` as the kernels of
:mod:`moik.collision.distance` do. Shapes are read from a
:class:`~moik.collision.compiled.CollisionSet` ``cs`` and world poses ``W``: a hull ``k``
has ``cs.sizes[k] = (hull index, bounding radius, 0)`` and its vertices
``cs.hull_points[start:end]`` with ``(start, end) = cs.hull_ranges[hull index]``.
"""

from __future__ import annotations

import math

import numpy as np

from moik._jit import jit
from moik.collision.distance import BOX, CAPSULE, HALFSPACE, HULL, segment_points

MAX_ITER = 64  # GJK iterations (a polytope pair converges in far fewer)
REL_TOL = 1e-9  # stop when the lower and upper bounds of |v|^2 agree to this fraction
_TINY = 1e-30  # |v|^2 below this: the cores touch


@jit
def _radius(cs, k):
    """Radius added to shape ``k``'s core (spheres and capsules; 0 for boxes and hulls)."""
    kind = cs.kinds[k]
    return cs.sizes[k, 0] if kind <= CAPSULE else 0.0  # SPHERE, CAPSULE


@jit
def support(cs, W, k, dx, dy, dz):
    """The point of shape ``k``'s core farthest along ``(dx, dy, dz)`` (world frame)."""
    P, kind = W[k], cs.kinds[k]
    # the direction in the shape's frame
    lx = P[0, 0] * dx + P[1, 0] * dy + P[2, 0] * dz
    ly = P[0, 1] * dx + P[1, 1] * dy + P[2, 1] * dz
    lz = P[0, 2] * dx + P[1, 2] * dy + P[2, 2] * dz
    x, y, z = 0.0, 0.0, 0.0
    if kind == CAPSULE:
        h = cs.sizes[k, 1]
        z = h if lz >= 0.0 else -h
    elif kind == BOX:
        x = cs.sizes[k, 0] if lx >= 0.0 else -cs.sizes[k, 0]
        y = cs.sizes[k, 1] if ly >= 0.0 else -cs.sizes[k, 1]
        z = cs.sizes[k, 2] if lz >= 0.0 else -cs.sizes[k, 2]
    elif kind == HULL:
        h = int(cs.sizes[k, 0])
        start, end = cs.hull_ranges[h, 0], cs.hull_ranges[h, 1]
        V = cs.hull_points
        best = -np.inf
        for i in range(start, end):
            s = V[i, 0] * lx + V[i, 1] * ly + V[i, 2] * lz
            if s > best:
                best, x, y, z = s, V[i, 0], V[i, 1], V[i, 2]
    return (P[0, 0] * x + P[0, 1] * y + P[0, 2] * z + P[0, 3],
            P[1, 0] * x + P[1, 1] * y + P[1, 2] * z + P[1, 3],
            P[2, 0] * x + P[2, 1] * y + P[2, 2] * z + P[2, 3])


@jit
def _copy_row(S, i, j):
    S[i, 0], S[i, 1], S[i, 2] = S[j, 0], S[j, 1], S[j, 2]


@jit
def _keep(S, A, B, lam, n):
    """Drop the simplex vertices of zero weight (kept in order); the new count."""
    m = 0
    for i in range(n):
        if lam[i] > 0.0:
            if m != i:
                _copy_row(S, m, i)
                _copy_row(A, m, i)
                _copy_row(B, m, i)
            lam[m] = lam[i]
            m += 1
    return m


@jit
def _dot(S, i, j):
    return S[i, 0] * S[j, 0] + S[i, 1] * S[j, 1] + S[i, 2] * S[j, 2]


@jit
def _segment(S, i, j, lam):
    """Weights of the closest point to the origin on segment ``S[i] S[j]`` into
    ``lam[i], lam[j]`` (Ericson 5.1.2)."""
    ab = _dot(S, j, j) - 2.0 * _dot(S, i, j) + _dot(S, i, i)  # |B - A|^2
    t = (_dot(S, i, i) - _dot(S, i, j)) / ab if ab > 0.0 else 0.0  # -A . (B - A) / |B - A|^2
    t = min(max(t, 0.0), 1.0)
    lam[i], lam[j] = 1.0 - t, t


@jit
def _triangle(S, i, j, k, lam):
    """Weights of the closest point to the origin on triangle ``S[i] S[j] S[k]`` into
    ``lam[i], lam[j], lam[k]`` (Ericson 5.1.5, ``ClosestPtPointTriangle`` with ``p = 0``)."""
    aa, ab, ac = _dot(S, i, i), _dot(S, i, j), _dot(S, i, k)
    bb, bc, cc = _dot(S, j, j), _dot(S, j, k), _dot(S, k, k)
    lam[i], lam[j], lam[k] = 0.0, 0.0, 0.0
    d1, d2 = aa - ab, aa - ac  # (b - a) . (p - a), (c - a) . (p - a)
    if d1 <= 0.0 and d2 <= 0.0:
        lam[i] = 1.0
        return
    d3, d4 = ab - bb, ab - bc  # (b - a) . (p - b), (c - a) . (p - b)
    if d3 >= 0.0 and d4 <= d3:
        lam[j] = 1.0
        return
    vc = d1 * d4 - d3 * d2
    if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:
        v = d1 / (d1 - d3)
        lam[i], lam[j] = 1.0 - v, v
        return
    d5, d6 = ac - bc, ac - cc  # (b - a) . (p - c), (c - a) . (p - c)
    if d6 >= 0.0 and d5 <= d6:
        lam[k] = 1.0
        return
    vb = d5 * d2 - d1 * d6
    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:
        w = d2 / (d2 - d6)
        lam[i], lam[k] = 1.0 - w, w
        return
    va = d3 * d6 - d5 * d4
    if va <= 0.0 and (d4 - d3) >= 0.0 and (d5 - d6) >= 0.0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        lam[j], lam[k] = 1.0 - w, w
        return
    total = va + vb + vc
    if not total > 0.0:  # a degenerate (flat) triangle: its best edge
        _segment(S, i, j, lam)
        return
    v, w = vb / total, vc / total
    lam[i], lam[j], lam[k] = 1.0 - v - w, v, w


@jit
def _side(S, i, j, k, m):
    """Whether the origin and ``S[m]`` are on opposite sides of plane ``S[i] S[j] S[k]``
    (the origin outside that face of the tetrahedron), or the tetrahedron is flat."""
    ux, uy, uz = S[j, 0] - S[i, 0], S[j, 1] - S[i, 1], S[j, 2] - S[i, 2]
    vx, vy, vz = S[k, 0] - S[i, 0], S[k, 1] - S[i, 1], S[k, 2] - S[i, 2]
    nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    s_origin = -(nx * S[i, 0] + ny * S[i, 1] + nz * S[i, 2])
    s_other = (nx * (S[m, 0] - S[i, 0]) + ny * (S[m, 1] - S[i, 1])
               + nz * (S[m, 2] - S[i, 2]))
    return s_other == 0.0 or s_origin * s_other < 0.0  # a flat tetrahedron: every face


@jit
def _point(S, lam, n):
    """``sum lam[i] S[i]`` over the first ``n`` rows."""
    x = y = z = 0.0
    for i in range(n):
        x += lam[i] * S[i, 0]
        y += lam[i] * S[i, 1]
        z += lam[i] * S[i, 2]
    return x, y, z


@jit
def _closest(S, n, lam):
    """Weights of the closest point to the origin of the simplex ``S[:n]`` (the zero ones
    mark the vertices to drop); whether the origin is inside a tetrahedron (then the
    weights are those of its closest face, for a caller that knows better: a tetrahedron
    flat to rounding error can seem to hold the origin)."""
    for i in range(4):
        lam[i] = 0.0
    if n == 1:
        lam[0] = 1.0
    elif n == 2:
        _segment(S, 0, 1, lam)
    elif n == 3:
        _triangle(S, 0, 1, 2, lam)
    else:
        faces = ((0, 1, 2, 3), (0, 1, 3, 2), (0, 2, 3, 1), (1, 2, 3, 0))
        trial = np.zeros(4)
        inside = True
        for f in range(4):
            i, j, k, m = faces[f]
            if _side(S, i, j, k, m):
                inside = False
        best = np.inf
        for f in range(4):
            i, j, k, m = faces[f]
            if not inside and not _side(S, i, j, k, m):
                continue
            for t in range(4):
                trial[t] = 0.0
            _triangle(S, i, j, k, trial)
            x, y, z = _point(S, trial, 4)
            d = x * x + y * y + z * z
            if d < best:
                best = d
                for t in range(4):
                    lam[t] = trial[t]
        return inside
    return False


@jit
def gjk(cs, W, a, b, limit):
    """Distance bounds of the cores of shapes ``a`` and ``b`` and their closest points:
    ``(lower, upper, pa (3,), pb (3,), touching)``. Stops as soon as ``lower`` reaches
    ``limit`` (the cores are then known to be at least that far apart)."""
    S, A, B = np.empty((4, 3)), np.empty((4, 3)), np.empty((4, 3))
    lam = np.zeros(4)
    dx = W[a, 0, 3] - W[b, 0, 3]
    dy = W[a, 1, 3] - W[b, 1, 3]
    dz = W[a, 2, 3] - W[b, 2, 3]
    if dx * dx + dy * dy + dz * dz < _TINY:
        dx, dy, dz = 1.0, 0.0, 0.0
    # first vertex: the support along -(centre difference), i.e. towards each other
    ax, ay, az = support(cs, W, a, -dx, -dy, -dz)
    bx, by, bz = support(cs, W, b, dx, dy, dz)
    A[0, 0], A[0, 1], A[0, 2] = ax, ay, az
    B[0, 0], B[0, 1], B[0, 2] = bx, by, bz
    S[0, 0], S[0, 1], S[0, 2] = ax - bx, ay - by, az - bz
    n, lam[0] = 1, 1.0
    vx, vy, vz = S[0, 0], S[0, 1], S[0, 2]
    lower, touching = -np.inf, False  # no bound yet
    for _ in range(MAX_ITER):
        vv = vx * vx + vy * vy + vz * vz
        if vv < _TINY:
            touching = True
            break
        ax, ay, az = support(cs, W, a, -vx, -vy, -vz)
        bx, by, bz = support(cs, W, b, vx, vy, vz)
        wx, wy, wz = ax - bx, ay - by, az - bz
        vw = vx * wx + vy * wy + vz * wz
        lower = max(lower, vw / math.sqrt(vv))
        if vv - vw <= REL_TOL * vv or n == 4 or (lower >= limit and lower > 0.0):
            break
        duplicate = False
        for i in range(n):
            if S[i, 0] == wx and S[i, 1] == wy and S[i, 2] == wz:
                duplicate = True
        if duplicate:
            break
        S[n, 0], S[n, 1], S[n, 2] = wx, wy, wz
        A[n, 0], A[n, 1], A[n, 2] = ax, ay, az
        B[n, 0], B[n, 1], B[n, 2] = bx, by, bz
        n += 1
        if _closest(S, n, lam) and lower <= 0.0:  # the origin inside: the cores overlap
            touching = True
            break
        n = _keep(S, A, B, lam, n)  # (a seeming inside with a positive lower bound: flat)
        vx, vy, vz = _point(S, lam, n)
    pa, pb = np.empty(3), np.empty(3)
    pa[0], pa[1], pa[2] = _point(A, lam, n)
    pb[0], pb[1], pb[2] = _point(B, lam, n)
    upper = math.sqrt(vx * vx + vy * vy + vz * vz)
    return lower, upper, pa, pb, touching or lower <= 0.0


@jit
def _overlap(cs, W, a, b):
    """Depth of the cores' overlap along the line of the shapes' centres (a, b), an upper
    bound of their penetration depth, with that unit direction from A to B."""
    nx = W[b, 0, 3] - W[a, 0, 3]
    ny = W[b, 1, 3] - W[a, 1, 3]
    nz = W[b, 2, 3] - W[a, 2, 3]
    norm = math.sqrt(nx * nx + ny * ny + nz * nz)
    if norm < 1e-15:
        nx, ny, nz, norm = 0.0, 0.0, 1.0, 1.0
    nx, ny, nz = nx / norm, ny / norm, nz / norm
    ax, ay, az = support(cs, W, a, nx, ny, nz)
    bx, by, bz = support(cs, W, b, -nx, -ny, -nz)
    depth = (ax - bx) * nx + (ay - by) * ny + (az - bz) * nz
    return max(depth, 0.0), nx, ny, nz, ax, ay, az


@jit
def _capsule_in_world(cs, W, k):
    """Centre, unit axis, half length and radius of hull ``k``'s capsule, in the world."""
    c = cs.hull_caps[int(cs.sizes[k, 0])]
    P = W[k]
    px = P[0, 0] * c[0] + P[0, 1] * c[1] + P[0, 2] * c[2] + P[0, 3]
    py = P[1, 0] * c[0] + P[1, 1] * c[1] + P[1, 2] * c[2] + P[1, 3]
    pz = P[2, 0] * c[0] + P[2, 1] * c[1] + P[2, 2] * c[2] + P[2, 3]
    ux = P[0, 0] * c[3] + P[0, 1] * c[4] + P[0, 2] * c[5]
    uy = P[1, 0] * c[3] + P[1, 1] * c[4] + P[1, 2] * c[5]
    uz = P[2, 0] * c[3] + P[2, 1] * c[4] + P[2, 2] * c[5]
    return (px, py, pz), (ux, uy, uz), c[6], c[7]


@jit
def hulls_bound(cs, W, a, b):
    """A lower bound of the distance of hulls ``a`` and ``b``: their capsules' distance
    (:func:`~moik.collision.shapes.hull_capsules`)."""
    p, u, h, ra = _capsule_in_world(cs, W, a)
    q, v, k, rb = _capsule_in_world(cs, W, b)
    t, w = segment_points(p, u, h, q, v, k)
    dx = q[0] + w * v[0] - p[0] - t * u[0]
    dy = q[1] + w * v[1] - p[1] - t * u[1]
    dz = q[2] + w * v[2] - p[2] - t * u[2]
    return math.sqrt(dx * dx + dy * dy + dz * dz) - ra - rb


@jit
def hull_capsule_bound(cs, W, a, b):
    """A lower bound of the distance of hull ``a`` to sphere or capsule ``b``: its capsule's."""
    p, u, h, ra = _capsule_in_world(cs, W, a)
    P = W[b]
    q, v = (P[0, 3], P[1, 3], P[2, 3]), (P[0, 2], P[1, 2], P[2, 2])
    k = cs.sizes[b, 1] if cs.kinds[b] == CAPSULE else 0.0
    t, w = segment_points(p, u, h, q, v, k)
    dx = q[0] + w * v[0] - p[0] - t * u[0]
    dy = q[1] + w * v[1] - p[1] - t * u[1]
    dz = q[2] + w * v[2] - p[2] - t * u[2]
    return math.sqrt(dx * dx + dy * dy + dz * dz) - ra - cs.sizes[b, 0]


@jit
def hull_halfspace(cs, W, a, h):
    """Signed distance of shape ``a`` (a hull; or any other convex shape's core and radius,
    :func:`support`) to half-space ``h``: its deepest point's, exact."""
    P = W[h]
    nx, ny, nz = P[0, 2], P[1, 2], P[2, 2]
    px, py, pz = support(cs, W, a, -nx, -ny, -nz)
    d = nx * (px - P[0, 3]) + ny * (py - P[1, 3]) + nz * (pz - P[2, 3])
    r = _radius(cs, a)
    if r != 0.0:  # a sphere's or capsule's deepest point lies r below its core's
        px, py, pz, d = px - r * nx, py - r * ny, pz - r * nz, d - r
    return d, -nx, -ny, -nz, px, py, pz, px - d * nx, py - d * ny, pz - d * nz


@jit
def convex_pair(cs, W, a, b, limit):
    """Signed distance, normal (A to B) and witnesses of shapes ``a`` and ``b``, one of them
    a hull (the module doc; for two other convex shapes, their cores' GJK distance less
    their radii, which the compounds' bounds of a
    :class:`~moik.collision.compiled.CompoundSet` take). A distance of at least ``limit``
    may be returned as a lower bound of the distance, not the distance (GJK stops there)."""
    if cs.kinds[b] == HALFSPACE:
        return hull_halfspace(cs, W, a, b)
    if cs.kinds[a] == HALFSPACE:
        d, nx, ny, nz, ax, ay, az, bx, by, bz = hull_halfspace(cs, W, b, a)
        return d, -nx, -ny, -nz, bx, by, bz, ax, ay, az
    ra, rb = _radius(cs, a), _radius(cs, b)
    lower, upper, pa, pb, touching = gjk(cs, W, a, b, limit + ra + rb)
    if touching:
        depth, nx, ny, nz, ax, ay, az = _overlap(cs, W, a, b)
        d = -depth - ra - rb
        return (d, nx, ny, nz, ax + ra * nx, ay + ra * ny, az + ra * nz,
                ax + (ra + d) * nx, ay + (ra + d) * ny, az + (ra + d) * nz)
    nx, ny, nz = (pb[0] - pa[0]) / upper, (pb[1] - pa[1]) / upper, (pb[2] - pa[2]) / upper
    d = lower - ra - rb
    return (d, nx, ny, nz, pa[0] + ra * nx, pa[1] + ra * ny, pa[2] + ra * nz,
            pb[0] - rb * nx, pb[1] - rb * ny, pb[2] - rb * nz)
