"""Batched distances of a robot's shapes and a scene's, compiled (the maths of a model).

A compiled collision set (:class:`~moik.collision.compiled.CollisionSet`, every kernel's
first argument ``cs``) is the arm's :class:`~moik.robots.chain_model.ChainModel` (``cs.chain``)
and the shapes of a robot and of a scene in one list: kind,
``body`` (0 the base frame, ``j`` the frame of joint ``j`` as :meth:`Robot.frames`
numbers them, ``-1`` the world), local pose ``(4, 4)`` in that frame, sizes ``(3,)``;
and the pairs ``(p, 2)`` of shape indices to evaluate. For each joint vector the chain
is walked once (as :func:`moik.robots.fk_kernels.fk_frames_into` does, recording the joint
axes on the way, as :mod:`moik.kinematics.jacobian` does), every shape is placed in the
world, and every pair goes through :func:`moik.collision.pairs.pair_distance`.

Gradient of a pair's signed distance ``d`` with respect to ``q`` (witness points
``a`` on A, ``b`` on B, unit normal ``n`` from A to B): ``dd/dq_j = n . (v_j(b) - v_j(a))``
where ``v_j(x) = z_j x (x - o_j)`` for a revolute joint ``j`` (``z_j`` for a prismatic
one) if joint ``j`` moves the shape's body, else 0 (Siciliano et al., *Robotics*,
Eq. 3.30, applied at the witness points). Exact for separated pairs (envelope
theorem); for penetrating box pairs the contact-normal approximation
(:mod:`moik.collision.distance`).
"""

from __future__ import annotations

import numpy as np
from numba.extending import overload

from moik._jit import jit
from moik.collision.distance import CAPSULE, HULL, capsule_capsule
from moik.collision.gjk import convex_pair, hull_capsule_bound, hulls_bound
from moik.collision.pairs import pair_bound, pair_distance
from moik.robots.fk_kernels import copy_pose, world_frames
from moik.robots.transforms import PRISMATIC


@jit
def place_shapes(frames, body, local, W):
    """World poses ``W (m, 4, 4)`` of shapes on bodies (``body < 0``: already in the world)."""
    for k in range(body.size):
        if body[k] < 0:
            copy_pose(local[k], W, k)
            continue
        A, L = frames[body[k]], local[k]
        for r in range(3):
            for c in range(4):
                W[k, r, c] = A[r, 0] * L[0, c] + A[r, 1] * L[1, c] + A[r, 2] * L[2, c]
            W[k, r, 3] += A[r, 3]
        W[k, 3, 0], W[k, 3, 1], W[k, 3, 2], W[k, 3, 3] = 0.0, 0.0, 0.0, 1.0


def primitive_pair(cs, W, a, b, limit):
    """:func:`shape_pair` of two primitives: their exact kernel
    (:func:`~moik.collision.pairs.pair_distance`). For a
    :class:`~moik.collision.compiled.CompoundSet` (every such pair but capsule-capsule is a
    compound's bound, only a lower bound needed) the overload below compiles capsule-capsule
    exactly as :func:`~moik.collision.pairs.pair_distance` does it and every other pair
    through GJK and the support function (:func:`~moik.collision.gjk.convex_pair`: a lower
    bound), so that the box and half-space closed forms are not compiled for it."""
    kinds, sizes = cs.kinds, cs.sizes
    return pair_distance(kinds[a], W[a], sizes[a], kinds[b], W[b], sizes[b])


@overload(primitive_pair)
def _primitive_pair(cs, W, a, b, limit):
    if not getattr(cs, "bounds_only", False):
        return primitive_pair

    def bounds(cs, W, a, b, limit):
        kinds, sizes = cs.kinds, cs.sizes
        if kinds[a] > CAPSULE or kinds[b] > CAPSULE:
            return convex_pair(cs, W, a, b, limit)
        if kinds[a] <= kinds[b]:  # as pair_distance orders them
            return capsule_capsule(W[a], sizes[a], W[b], sizes[b])
        d, nx, ny, nz, bx, by, bz, ax, ay, az = capsule_capsule(W[b], sizes[b], W[a], sizes[a])
        return d, -nx, -ny, -nz, ax, ay, az, bx, by, bz
    return bounds


@jit
def shape_pair(cs, W, a, b, limit):
    """Signed distance, normal and witnesses of shapes ``a`` and ``b`` placed at ``W``: GJK
    for a pair with a hull (:func:`~moik.collision.gjk.convex_pair`, which may return a
    lower bound of the distance once it reaches ``limit``), else :func:`primitive_pair`."""
    if cs.kinds[a] == HULL or cs.kinds[b] == HULL:
        return convex_pair(cs, W, a, b, limit)
    return primitive_pair(cs, W, a, b, limit)


@jit
def distance_scratch(cs):
    """Scratch of :func:`min_distance_of` for ``cs``: ``(frames (dof + 1, 4, 4), axes
    (dof, 6), W (m, 4, 4), bounds (p,))``."""
    dof = cs.chain.joint_types.size
    return (np.empty((dof + 1, 4, 4)), np.empty((dof, 6)), np.empty((cs.body.size, 4, 4)),
            np.empty(cs.pairs.shape[0]))


@jit
def place_all(cs, q, scratch):
    """Every shape of ``cs`` placed in the world at ``q`` (into ``scratch``'s ``W``)."""
    frames, axes, W = scratch[0], scratch[1], scratch[2]
    world_frames(cs.chain, q, frames, axes)
    place_shapes(frames, cs.body, cs.local, W)


@jit
def _part_bound(cs, W, part, other):
    """A lower bound of the distance of a compound's part (a hull) to shape ``other`` (the
    other side's bound, or its own single shape): capsule to capsule or to hull, else the
    bounding spheres."""
    kind = cs.kinds[other]
    if kind == HULL:
        return hulls_bound(cs, W, part, other)
    if kind <= CAPSULE:
        return hull_capsule_bound(cs, W, part, other)
    return pair_bound(cs.kinds, W, cs.sizes, part, other)


@jit
def _parts_bound(cs, W, a, b):
    """A lower bound of the distance of shapes ``a`` and ``b`` (parts): their hulls'
    capsules when both are hulls, else their bounding spheres."""
    if cs.kinds[a] == HULL and cs.kinds[b] == HULL:
        return hulls_bound(cs, W, a, b)
    return pair_bound(cs.kinds, W, cs.sizes, a, b)


@jit
def _live_parts(cs, W, first, count, other, cap):
    """The parts ``first .. first + count`` that may come below ``cap`` of shape ``other``,
    as the bits of an int64."""
    mask = 0
    for i in range(count):
        if count == 1 or _part_bound(cs, W, first + i, other) < cap:
            mask |= 1 << i
    return mask


@jit
def pair_value(cs, W, k, limit):
    """The distance result of pair ``k`` (shapes placed at ``W``): its shapes' own; for a
    pair refined by compound parts (``cs.refine[k]``, :func:`moik.collision.shapes.refinements`),
    the smallest over its parts' pairs, unless the bounds' distance is already at least
    ``limit`` (then the bounds': a lower bound, enough to know the pair is not below
    ``limit``). Parts whose bound to the other side keeps ``limit`` are not measured (and
    when none comes below it the result is ``inf``: at least ``limit``)."""
    a, b = cs.pairs[k, 0], cs.pairs[k, 1]
    res = shape_pair(cs, W, a, b, limit)
    a0, na, b0, nb = cs.refine[k, 0], cs.refine[k, 1], cs.refine[k, 2], cs.refine[k, 3]
    if na == 0 or res[0] >= limit:
        return res
    live_a = _live_parts(cs, W, a0, na, b, limit)
    live_b = _live_parts(cs, W, b0, nb, a, limit)
    low, fi, fj = np.inf, -1, -1  # the parts' pair of the smallest bound is measured first
    for i in range(na):
        if live_a >> i & 1:
            for j in range(nb):
                if live_b >> j & 1:
                    lb = _parts_bound(cs, W, a0 + i, b0 + j)
                    if lb < low:
                        low, fi, fj = lb, i, j
    best = (np.inf, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if fi < 0 or low >= limit:
        return best
    best = shape_pair(cs, W, a0 + fi, b0 + fj, limit)
    for i in range(na):
        if not live_a >> i & 1:
            continue
        for j in range(nb):
            if not live_b >> j & 1 or (i == fi and j == fj):
                continue
            cap = min(best[0], limit)
            if _parts_bound(cs, W, a0 + i, b0 + j) >= cap:
                continue  # its distance is at least its bound: not below the smallest
            r = shape_pair(cs, W, a0 + i, b0 + j, cap)
            if r[0] < best[0]:
                best = r
    return best


@jit
def pair_distances(cs, Q, out):
    """Signed distance of every pair for every row of ``Q (n, dof)``, into ``out (n, p)``."""
    scratch = distance_scratch(cs)
    W = scratch[2]
    for i in range(Q.shape[0]):
        place_all(cs, Q[i], scratch)
        for k in range(cs.pairs.shape[0]):
            out[i, k] = pair_value(cs, W, k, np.inf)[0]


@jit
def pair_signs(cs, Q, touching, free):
    """Set ``touching[k]`` for every pair ``k`` in collision (distance below 0) in some row
    of ``Q (n, dof)``, and ``free[k]`` for every pair out of collision in some row; a pair
    with both set is not measured again, and the others only as far as their sign (limit
    0: the parts whose bounds keep apart are skipped)."""
    scratch = distance_scratch(cs)
    W = scratch[2]
    for i in range(Q.shape[0]):
        place_all(cs, Q[i], scratch)
        for k in range(cs.pairs.shape[0]):
            if touching[k] and free[k]:
                continue
            if pair_value(cs, W, k, 0.0)[0] < 0.0:
                touching[k] = True
            else:
                free[k] = True


@jit(nogil=True)
def min_distances(cs, Q, dmin, which):
    """Smallest pair distance ``dmin (n,)`` and the pair ``which (n,)`` that attains it.

    With no pairs, ``dmin`` is ``inf`` and ``which`` is -1. Releases the GIL (the batch's
    threads re-check their chunks' distances with it, :mod:`moik.solver.parallel`).
    """
    scratch = distance_scratch(cs)
    for i in range(Q.shape[0]):
        dmin[i], which[i] = min_distance_of(cs, Q[i], scratch)


@jit(nogil=True)
def distances_below(cs, Q, limit, out):
    """:func:`distance_below` of every row of ``Q (n, dof)`` into ``out (n,)`` (the clearance
    test of a batch's answers; releases the GIL as :func:`min_distances`)."""
    scratch = distance_scratch(cs)
    for i in range(Q.shape[0]):
        out[i] = distance_below(cs, Q[i], scratch, limit)[0]


@jit(inline=True)
def min_distance_of(cs, q, scratch):
    """Smallest pair distance of one joint vector and the pair attaining it (``inf``, -1:
    no pair); ``scratch`` from :func:`distance_scratch`."""
    return distance_below(cs, q, scratch, np.inf)


@jit
def distance_below(cs, q, scratch, limit):
    """Smallest pair distance of ``q`` and the pair attaining it when it is below ``limit``;
    else a number at least ``limit`` (``inf`` when no pair comes near it) and -1. The
    pairs whose bounds keep ``limit`` are not measured: the start loop's test of an end
    (``limit`` = the clearance) measures only the pairs that come close."""
    place_all(cs, q, scratch)
    W, bounds = scratch[2], scratch[3]
    kinds, sizes, pairs = cs.kinds, cs.sizes, cs.pairs
    first, low = -1, np.inf  # the pair of the smallest bound is evaluated first
    for k in range(pairs.shape[0]):
        lb = pair_bound(kinds, W, sizes, pairs[k, 0], pairs[k, 1])
        if cs.refine[k, 1] > 0 and lb < limit:  # a compound pair: its bounds' distance
            lb = max(lb, shape_pair(cs, W, pairs[k, 0], pairs[k, 1], limit)[0])
        bounds[k] = lb
        if first < 0 or lb < low:
            first, low = k, lb
    best, arg = np.inf, -1
    if first >= 0 and low < limit:
        best = pair_value(cs, W, first, limit)[0]
        arg = first if best < limit else -1
    for k in range(pairs.shape[0]):
        if k == first:
            continue
        cap = min(best, limit)
        if bounds[k] > cap:
            continue  # its distance is at least its bound: not below the minimum
        d = pair_value(cs, W, k, cap)[0]
        if d < best or (d == best and k < arg):  # the first pair attaining it, as in order
            best, arg = d, k
    return best, (arg if best < limit else -1)


@jit
def _point_velocity(axes, types, j, x, y, z):
    """Velocity of a point at ``(x, y, z)`` moved by joint ``j`` at unit speed."""
    ox, oy, oz, zx, zy, zz = axes[j, 0], axes[j, 1], axes[j, 2], axes[j, 3], axes[j, 4], axes[j, 5]
    if types[j] == PRISMATIC:
        return zx, zy, zz
    rx, ry, rz = x - ox, y - oy, z - oz
    return zy * rz - zz * ry, zz * rx - zx * rz, zx * ry - zy * rx


@jit
def min_distance_gradients(cs, Q, dmin, grad):
    """Smallest pair distance ``dmin (n,)`` and its gradient ``grad (n, dof)`` w.r.t. ``q``.

    The gradient is that of the pair attaining the minimum (the module doc); with no
    pairs ``dmin`` is ``inf`` and the gradient 0.
    """
    types = cs.chain.joint_types
    dof = types.size
    scratch = distance_scratch(cs)
    axes, W = scratch[1], scratch[2]
    body, pairs = cs.body, cs.pairs
    for i in range(Q.shape[0]):
        place_all(cs, Q[i], scratch)
        best, arg = np.inf, -1
        res = (np.inf, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        for k in range(pairs.shape[0]):
            r = pair_value(cs, W, k, best)
            if r[0] < best:
                best, arg, res = r[0], k, r
        dmin[i] = best
        grad[i] = 0.0
        if arg < 0:
            continue
        d, nx, ny, nz, ax, ay, az, bx, by, bz = res
        bodyA, bodyB = body[pairs[arg, 0]], body[pairs[arg, 1]]
        for j in range(dof):  # joint j (0-based) moves bodies j + 1 ..
            g = 0.0
            if bodyB > j:
                vx, vy, vz = _point_velocity(axes, types, j, bx, by, bz)
                g += nx * vx + ny * vy + nz * vz
            if bodyA > j:
                vx, vy, vz = _point_velocity(axes, types, j, ax, ay, az)
                g -= nx * vx + ny * vy + nz * vz
            grad[i, j] = g
