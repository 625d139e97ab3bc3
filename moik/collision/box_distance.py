"""Signed distances of boxes: capsule-box, box-box, box-half-space (the maths of
:mod:`moik.collision.distance`, whose module doc states what each kernel returns and why
it is exact)."""

from __future__ import annotations

import math

from moik._jit import jit
from moik.collision.distance import _PARALLEL, _segment


@jit
def _to_box(P, x, y, z):
    """World point ``(x, y, z)`` in the frame of the box pose ``P``."""
    dx, dy, dz = x - P[0, 3], y - P[1, 3], z - P[2, 3]
    return (P[0, 0] * dx + P[1, 0] * dy + P[2, 0] * dz,
            P[0, 1] * dx + P[1, 1] * dy + P[2, 1] * dz,
            P[0, 2] * dx + P[1, 2] * dy + P[2, 2] * dz)


@jit
def _from_box(P, x, y, z):
    """Point ``(x, y, z)`` of the box frame ``P`` in world coordinates."""
    return (P[0, 3] + P[0, 0] * x + P[0, 1] * y + P[0, 2] * z,
            P[1, 3] + P[1, 0] * x + P[1, 1] * y + P[1, 2] * z,
            P[2, 3] + P[2, 0] * x + P[2, 1] * y + P[2, 2] * z)


@jit
def _cut(p, d, bound):
    """The parameter where ``p + t d`` crosses ``bound`` if it is in (0, 1), else 2."""
    if d == 0.0:
        return 2.0
    t = (bound - p) / d
    return t if 0.0 < t < 1.0 else 2.0


@jit
def segment_box_sq(p, d, e):
    """``min_t |p + t d - box|^2`` over ``t in [0, 1]`` for the box ``|x_i| <= e_i``.

    ``f(t) = sum_i max(|p_i + t d_i| - e_i, 0)^2`` is convex and quadratic between the
    (at most six) parameters where a coordinate crosses a face; each piece is minimised
    exactly. Returns ``(f_min, t_min)``. (No allocation: the pieces start at 0 and at
    each crossing and end at the next crossing or 1.)
    """
    cuts = (0.0, _cut(p[0], d[0], -e[0]), _cut(p[0], d[0], e[0]), _cut(p[1], d[1], -e[1]),
            _cut(p[1], d[1], e[1]), _cut(p[2], d[2], -e[2]), _cut(p[2], d[2], e[2]))
    best, best_t = math.inf, 0.0
    for j in range(7):
        lo = cuts[j]
        if lo > 1.0:
            continue
        hi = 1.0
        for k in range(7):
            if lo < cuts[k] < hi:
                hi = cuts[k]
        mid = 0.5 * (lo + hi)
        num, den, active = 0.0, 0.0, 0
        for i in range(3):
            x = p[i] + mid * d[i]
            if x > e[i]:
                num += (p[i] - e[i]) * d[i]
                den += d[i] * d[i]
                active += 1
            elif x < -e[i]:
                num += (p[i] + e[i]) * d[i]
                den += d[i] * d[i]
                active += 1
        if active == 0:  # this piece runs inside the box: they meet (exactly 0, no rounding)
            return 0.0, mid
        t = lo if den == 0.0 else min(max(-num / den, lo), hi)
        f = 0.0
        for i in range(3):
            x = p[i] + t * d[i]
            g = max(abs(x) - e[i], 0.0)
            f += g * g
        if f < best:
            best, best_t = f, t
    return best, best_t


@jit
def capsule_box(PA, sA, PB, sB):
    """Signed distance and witnesses of a capsule (or sphere) A and a box B, exact."""
    cx, cy, cz, ux, uy, uz, h = _segment(PA, sA)
    r = sA[0]
    x0, y0, z0 = _to_box(PB, cx - h * ux, cy - h * uy, cz - h * uz)
    x1, y1, z1 = _to_box(PB, cx + h * ux, cy + h * uy, cz + h * uz)
    f, t = segment_box_sq((x0, y0, z0), (x1 - x0, y1 - y0, z1 - z0), (sB[0], sB[1], sB[2]))
    if f > 0.0:
        lx, ly, lz = x0 + t * (x1 - x0), y0 + t * (y1 - y0), z0 + t * (z1 - z0)
        ax, ay, az = _from_box(PB, lx, ly, lz)
        bx, by, bz = _from_box(PB, min(max(lx, -sB[0]), sB[0]), min(max(ly, -sB[1]), sB[1]),
                               min(max(lz, -sB[2]), sB[2]))
        delta = math.sqrt(f)
        nx, ny, nz = (bx - ax) / delta, (by - ay) / delta, (bz - az) / delta
        return (delta - r, nx, ny, nz, ax + r * nx, ay + r * ny, az + r * nz, bx, by, bz)
    # penetration: the depth of the zonotope box - segment, over its facet normals
    gx, gy, gz = h * ux, h * uy, h * uz
    ox, oy, oz = PB[0, 3] - cx, PB[1, 3] - cy, PB[2, 3] - cz
    best, nx, ny, nz = math.inf, 1.0, 0.0, 0.0
    for k in range(6):
        if k < 3:
            mx, my, mz = PB[0, k], PB[1, k], PB[2, k]
        else:
            bx_, by_, bz_ = PB[0, k - 3], PB[1, k - 3], PB[2, k - 3]
            mx, my, mz = by_ * uz - bz_ * uy, bz_ * ux - bx_ * uz, bx_ * uy - by_ * ux
            norm2 = mx * mx + my * my + mz * mz
            if norm2 < _PARALLEL:
                continue
            norm = math.sqrt(norm2)
            mx, my, mz = mx / norm, my / norm, mz / norm
        reach = abs(mx * gx + my * gy + mz * gz)
        for i in range(3):
            reach += sB[i] * abs(mx * PB[0, i] + my * PB[1, i] + mz * PB[2, i])
        off = mx * ox + my * oy + mz * oz
        overlap = reach - abs(off)
        if overlap < best:
            best = overlap
            sign = 1.0 if off >= 0.0 else -1.0
            nx, ny, nz = sign * mx, sign * my, sign * mz
    d = -best - r
    w = 1.0 if nx * ux + ny * uy + nz * uz >= 0.0 else -1.0  # A's deepest point along n
    ax, ay, az = cx + w * gx + r * nx, cy + w * gy + r * ny, cz + w * gz + r * nz
    return d, nx, ny, nz, ax, ay, az, ax + d * nx, ay + d * ny, az + d * nz


@jit
def _box_corner(P, s, k):
    """Corner ``k`` (0..7, bits = signs along x, y, z) of the box ``(P, s)``, world frame."""
    x = s[0] if k & 1 else -s[0]
    y = s[1] if k & 2 else -s[1]
    z = s[2] if k & 4 else -s[2]
    return _from_box(P, x, y, z)


@jit
def _box_edges_to_box(PA, sA, PB, sB):
    """Smallest edge-to-box distance of the 12 edges of A against the box B (separated)."""
    best, bt, bi, bj = math.inf, 0.0, 0, 0
    eB = (sB[0], sB[1], sB[2])
    for i in range(8):
        for axis in range(3):
            j = i | (1 << axis)
            if j == i:
                continue
            ax, ay, az = _box_corner(PA, sA, i)
            cx, cy, cz = _box_corner(PA, sA, j)
            x0, y0, z0 = _to_box(PB, ax, ay, az)
            x1, y1, z1 = _to_box(PB, cx, cy, cz)
            f, t = segment_box_sq((x0, y0, z0), (x1 - x0, y1 - y0, z1 - z0), eB)
            if f < best:
                best, bt, bi, bj = f, t, i, j
    return best, bt, bi, bj


@jit
def box_box(PA, sA, PB, sB):
    """Signed distance and witnesses of two boxes (exact; see the module doc)."""
    ox, oy, oz = PB[0, 3] - PA[0, 3], PB[1, 3] - PA[1, 3], PB[2, 3] - PA[2, 3]
    best, nx, ny, nz, separated = math.inf, 1.0, 0.0, 0.0, False
    for k in range(15):
        if k < 3:
            mx, my, mz = PA[0, k], PA[1, k], PA[2, k]
        elif k < 6:
            mx, my, mz = PB[0, k - 3], PB[1, k - 3], PB[2, k - 3]
        else:
            i, j = (k - 6) // 3, (k - 6) % 3
            a0, a1, a2 = PA[0, i], PA[1, i], PA[2, i]
            b0, b1, b2 = PB[0, j], PB[1, j], PB[2, j]
            mx, my, mz = a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0
            norm2 = mx * mx + my * my + mz * mz
            if norm2 < _PARALLEL:
                continue
            norm = math.sqrt(norm2)
            mx, my, mz = mx / norm, my / norm, mz / norm
        reach = 0.0
        for i in range(3):
            reach += sA[i] * abs(mx * PA[0, i] + my * PA[1, i] + mz * PA[2, i])
            reach += sB[i] * abs(mx * PB[0, i] + my * PB[1, i] + mz * PB[2, i])
        off = mx * ox + my * oy + mz * oz
        overlap = reach - abs(off)
        if overlap < 0.0:
            separated = True
            break
        if overlap < best:
            best = overlap
            sign = 1.0 if off >= 0.0 else -1.0
            nx, ny, nz = sign * mx, sign * my, sign * mz
    if separated:
        fa, ta, ia, ja = _box_edges_to_box(PA, sA, PB, sB)
        fb, tb, ib, jb = _box_edges_to_box(PB, sB, PA, sA)
        if fa <= fb:  # an edge of A nearest to B
            p0, p1, Q, sQ, t, f, flip = _box_corner(PA, sA, ia), _box_corner(PA, sA, ja), PB, \
                sB, ta, fa, False
        else:
            p0, p1, Q, sQ, t, f, flip = _box_corner(PB, sB, ib), _box_corner(PB, sB, jb), PA, \
                sA, tb, fb, True
        ex, ey, ez = (p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1]),
                      p0[2] + t * (p1[2] - p0[2]))
        lx, ly, lz = _to_box(Q, ex, ey, ez)
        qx, qy, qz = _from_box(Q, min(max(lx, -sQ[0]), sQ[0]), min(max(ly, -sQ[1]), sQ[1]),
                               min(max(lz, -sQ[2]), sQ[2]))
        delta = math.sqrt(f)
        if flip:  # the edge point is on B, the box point on A
            ex, ey, ez, qx, qy, qz = qx, qy, qz, ex, ey, ez
        nx, ny, nz = (qx - ex) / delta, (qy - ey) / delta, (qz - ez) / delta
        return delta, nx, ny, nz, ex, ey, ez, qx, qy, qz
    d = -best
    ax, ay, az = _support_box(PA, sA, nx, ny, nz)
    return d, nx, ny, nz, ax, ay, az, ax + d * nx, ay + d * ny, az + d * nz


@jit
def _support_box(P, s, nx, ny, nz):
    """The corner of the box ``(P, s)`` farthest along ``n``."""
    x = s[0] if nx * P[0, 0] + ny * P[1, 0] + nz * P[2, 0] >= 0.0 else -s[0]
    y = s[1] if nx * P[0, 1] + ny * P[1, 1] + nz * P[2, 1] >= 0.0 else -s[1]
    z = s[2] if nx * P[0, 2] + ny * P[1, 2] + nz * P[2, 2] >= 0.0 else -s[2]
    return _from_box(P, x, y, z)


@jit
def box_halfspace(PA, sA, PB):
    """Signed distance of a box A to the half-space ``z <= 0`` of pose PB (exact)."""
    mx, my, mz = PB[0, 2], PB[1, 2], PB[2, 2]
    ax, ay, az = _support_box(PA, sA, -mx, -my, -mz)
    d = mx * (ax - PB[0, 3]) + my * (ay - PB[1, 3]) + mz * (az - PB[2, 3])
    return d, -mx, -my, -mz, ax, ay, az, ax - d * mx, ay - d * my, az - d * mz
