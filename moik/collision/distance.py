"""Exact signed distances between the primitives, compiled (the maths; no validation).

Every shape is given by its kind, its world pose ``P (4, 4)`` and its sizes ``s (3,)``
(:mod:`moik.collision.shapes`): a sphere ``(r, 0, 0)`` centred at the pose's origin, a
capsule ``(r, h, 0)`` (the points within ``r`` of the segment from ``-h z`` to ``+h z`` of
the pose), a box ``(hx, hy, hz)`` (half extents along the pose's axes) and a half-space
(the points with ``z <= 0`` in the pose's frame: a table top whose outward normal is the
pose's z axis). A sphere is a capsule with ``h = 0``, so three kernels cover every pair:
segment-segment, segment-box and box-box, each with a closed form for the half-space.

Each kernel returns ``(d, nx, ny, nz, ax, ay, az, bx, by, bz)``: the signed distance ``d``
(negative: penetration depth, the shortest translation that separates the shapes), the
unit normal ``n`` from shape A to shape B, and witness points ``a`` on A and ``b`` on B
with ``b - a = d n``. Separated shapes give their closest points (the gradient of ``d``
with respect to a rigid motion of B is then exactly ``n`` at ``b``; Ericson,
*Real-Time Collision Detection*, 2005, Sections 5.1.9 and 5.5). Exactness:

* capsule-capsule, sphere-anything: the distance of the inner segments (points) minus the
  radii, exact signed (the Minkowski sum with a ball adds its radius to the depth);
* capsule-box separated: the squared distance of the segment to the box is a convex
  piecewise quadratic in the segment parameter with at most six breakpoints, minimised
  exactly on each piece; penetrating: the depth of the zonotope ``box - segment`` (its
  facet normals are the box axes and their cross products with the segment), exact;
* box-box: separated (a separating axis among the 15 of the SAT exists), the minimum of
  the segment-box distances of the 24 edges, exact; penetrating, the smallest overlap on
  the 15 axes, which is the exact depth of the zonotope ``A - B``. The witness points of
  a penetrating pair are the deepest support point of A and that point moved by ``d n``;
  the gradient there is the contact-normal approximation, not an exact derivative;
* anything against a half-space: the deepest point of the shape along the normal, exact.

:func:`~moik.collision.pairs.pair_bound` is the broad phase: a lower bound on a pair's
signed distance from bounding spheres (a half-space: the plane distance of the other
shape's sphere), which holds for penetrating pairs too (a shape lies in its sphere, so
separating the spheres separates the shapes). A pair whose bound exceeds the smallest
distance known cannot be the minimum, and is not evaluated
(:func:`moik.collision.kernels.min_distance_of`).

Modules: this one holds the segment kernels (capsule-capsule, sphere-anything, capsule
against a half-space), :mod:`moik.collision.box_distance` the box kernels,
:mod:`moik.collision.pairs` the broad-phase bound and :func:`~moik.collision.pairs.pair_distance`,
which dispatches a pair to its kernel.
"""

from __future__ import annotations

import math

from moik._jit import jit

_PARALLEL = 1e-12  # |u x v|^2 below this: the two directions give no separating axis
SPHERE, CAPSULE, BOX, HALFSPACE = 0, 1, 2, 3  # shape kinds, in the order the pairs take them
HULL = 4  # a convex hull of points (moik.collision.gjk)


@jit
def _segment(P, s):
    """Centre, unit axis and half length of a capsule (or sphere: h = 0) of pose ``P``."""
    return P[0, 3], P[1, 3], P[2, 3], P[0, 2], P[1, 2], P[2, 2], s[1]


@jit
def segment_points(p, u, h, q, v, k):
    """Closest points of the segments ``p + t u`` (|t| <= h) and ``q + w v`` (|w| <= k).

    ``u``, ``v`` are unit vectors; returns ``(t, w)`` (Ericson, Section 5.1.9, written for
    centred segments). Degenerate segments (h or k zero) and parallel ones are handled.
    """
    rx, ry, rz = p[0] - q[0], p[1] - q[1], p[2] - q[2]
    b = u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
    c = u[0] * rx + u[1] * ry + u[2] * rz
    f = v[0] * rx + v[1] * ry + v[2] * rz
    if h == 0.0 and k == 0.0:
        return 0.0, 0.0
    if h == 0.0:
        return 0.0, min(max(f, -k), k)
    if k == 0.0:
        return min(max(-c, -h), h), 0.0
    # t = (b f - c) / (1 - b^2), written by Lagrange's identity as
    # ((u x v) . (v x r)) / |u x v|^2: for nearly parallel segments 1 - b^2 and b f - c
    # cancel (at an angle of 2e-8 rad 1 - b^2 is 4e-16 with an error of 1e-16, so the
    # closest points and the distance were off by ~1e-8 and differed with the order of
    # the pair); the cross products keep their relative accuracy. Exactly parallel: t = 0,
    # then the clamps below pick a closest pair.
    cx, cy, cz = u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]
    denom = cx * cx + cy * cy + cz * cz
    t = 0.0
    if denom > 0.0:
        ex, ey, ez = v[1] * rz - v[2] * ry, v[2] * rx - v[0] * rz, v[0] * ry - v[1] * rx
        t = min(max((cx * ex + cy * ey + cz * ez) / denom, -h), h)
    w = b * t + f
    if w < -k:
        w = -k
        t = min(max(-b * k - c, -h), h)
    elif w > k:
        w = k
        t = min(max(b * k - c, -h), h)
    return t, w


@jit
def capsule_capsule(PA, sA, PB, sB):
    """Signed distance and witnesses of two capsules (spheres: h = 0), exact."""
    px, py, pz, ux, uy, uz, h = _segment(PA, sA)
    qx, qy, qz, vx, vy, vz, k = _segment(PB, sB)
    t, w = segment_points((px, py, pz), (ux, uy, uz), h, (qx, qy, qz), (vx, vy, vz), k)
    ax, ay, az = px + t * ux, py + t * uy, pz + t * uz
    bx, by, bz = qx + w * vx, qy + w * vy, qz + w * vz
    dx, dy, dz = bx - ax, by - ay, bz - az
    delta = math.sqrt(dx * dx + dy * dy + dz * dz)
    if delta > 0.0:
        nx, ny, nz = dx / delta, dy / delta, dz / delta
    else:  # the segments meet: any direction normal to A's axis
        nx, ny, nz = _normal_to(ux, uy, uz)
    rA, rB = sA[0], sB[0]
    return (delta - rA - rB, nx, ny, nz, ax + rA * nx, ay + rA * ny, az + rA * nz,
            bx - rB * nx, by - rB * ny, bz - rB * nz)


@jit
def _normal_to(ux, uy, uz):
    """A unit vector normal to ``u`` (``x`` when ``u`` is zero or along z)."""
    if abs(ux) < 0.9:
        nx, ny, nz = 0.0, -uz, uy  # e_x x u
    else:
        nx, ny, nz = uz, 0.0, -ux  # e_y x u
    norm = math.sqrt(nx * nx + ny * ny + nz * nz)
    return nx / norm, ny / norm, nz / norm


@jit
def capsule_halfspace(PA, sA, PB):
    """Signed distance of a capsule (or sphere) A to the half-space ``z <= 0`` of pose PB."""
    cx, cy, cz, ux, uy, uz, h = _segment(PA, sA)
    mx, my, mz = PB[0, 2], PB[1, 2], PB[2, 2]
    w = -1.0 if mx * ux + my * uy + mz * uz >= 0.0 else 1.0  # the lower end
    ex, ey, ez = cx + w * h * ux, cy + w * h * uy, cz + w * h * uz
    r = sA[0]
    ax, ay, az = ex - r * mx, ey - r * my, ez - r * mz
    d = mx * (ax - PB[0, 3]) + my * (ay - PB[1, 3]) + mz * (az - PB[2, 3])
    return d, -mx, -my, -mz, ax, ay, az, ax - d * mx, ay - d * my, az - d * mz
