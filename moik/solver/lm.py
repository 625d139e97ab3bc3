"""Compiled multi-start Levenberg-Marquardt IK: the solver's first stage.

One start at a time, entirely in compiled code (numba, :mod:`moik._jit`): each
iteration is one FK + Jacobian pass (:func:`moik.kinematics.jacobian.pose_jacobian_into`),
the exact pose residual ``r = [(p - p_t) / L, log(R R_t^T)]`` with its Jacobian
``[J_v / L; J_l^{-1}(r_rot) J_w]`` (:mod:`moik.kinematics.so3`), and a Cholesky
solve of the damped normal equations

    (J^T J + lambda (diag(J^T J) + mu)) delta = -J^T r

(Levenberg 1944; Marquardt 1963, with Marquardt's diagonal scaling; ``mu``, 1e-9
of the mean diagonal, keeps a redundant arm's singular ``J^T J`` invertible). A
trial point is projected onto the joint limits and kept when the cost
``0.5 |r|^2`` decreases (``lambda /= 3``), else ``lambda *= 4``. A revolute
joint that steps past a limit is first moved by the multiple of 2 pi that brings
it back inside (the same arm configuration: on arms with +-180 deg joints, such as
the Puma 560, clipping there instead stops 3 of 4 random starts short of the
pose); otherwise joints at a limit whose step points outwards are held there and
the step is solved for the others (an active-set projection, as in dogbox). Every
iterate is within the limits.

A start is abandoned (and the next one taken) when ``lambda`` exceeds 1e8, after
``max_iter`` iterations, or when its cost has not halved over the last 2
iterations (a local minimum that is not a solution: measured on 400 random poses
of six arms, abandoning starts this early halves the median time against 10
iterations, and no pose goes unsolved); a start that is already
close (errors ~1e-5) is given up to 300 more iterations, since LM converges only
linearly near a singular configuration. Starts come from the caller (seeded
numpy draws: the kernels draw nothing).

The same kernel computes the weighted-sum scalarisations
``w |p - p_t|^2 / L^2 + (1 - w) |log(R R_t^T)|^2`` of an unreachable pose's
(position error, orientation error) front. Every kernel reads the solve's constants
from an :class:`~moik.solver.context.IKContext` and writes into an
:class:`~moik.solver.context.LMWorkspace`; the loops over starts and weights, and
their Python entries, are in :mod:`moik.solver.starts`.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit
from moik.kinematics.jacobian import pose_jacobian_into
from moik.kinematics.so3 import inverse_left_jacobian_times, log_into
from moik.robots.transforms import PRISMATIC

LAMBDA0 = 1e-3
LAMBDA_MAX = 1e8
STALL_WINDOW = 2  # iterations over which a start must halve its cost
STALL_RATIO = 0.5
EXTRA_ITER = 300  # more iterations for a start that is close but converging slowly
NEAR_COST = 1e-10  # 0.5 |r|^2 below which a start counts as close (errors ~1e-5)
FRONT_STALL_RATIO = 0.999  # a front scalarisation runs until it stops improving


@jit
def residual(ctx, ws, q, scale, r, Jr):
    """Scaled residual ``r (6,)`` and its Jacobian ``Jr (6, dof)`` at ``q``; returns ``0.5 |r|^2``.

    Position rows are scaled by ``scale[0]`` (``1 / L``, times ``sqrt(w)`` on a front),
    rotation rows by ``scale[1]``; without a target rotation they are zero. ``ws.T``,
    ``ws.J`` and ``ws.M`` are scratch.
    """
    s_pos, s_rot = scale
    T, J, M, pt, Rt = ws.T, ws.J, ws.M, ctx.target.position, ctx.target.rotation
    pose_jacobian_into(ctx.chain.origins, ctx.chain.joint_types, q, T, J)
    dof = q.shape[0]
    for a in range(3):
        r[a] = (T[a, 3] - pt[a]) * s_pos
        for j in range(dof):
            Jr[a, j] = J[a, j] * s_pos
    cost = r[0] * r[0] + r[1] * r[1] + r[2] * r[2]
    if not ctx.target.has_rotation:
        for a in range(3, 6):
            r[a] = 0.0
            for j in range(dof):
                Jr[a, j] = 0.0
        return 0.5 * cost
    for a in range(3):  # M = R Rt^T
        for b in range(3):
            M[a, b] = T[a, 0] * Rt[b, 0] + T[a, 1] * Rt[b, 1] + T[a, 2] * Rt[b, 2]
    phi = r[3:6]
    log_into(M, phi)
    inverse_left_jacobian_times(phi, J[3:6], Jr[3:6])
    for a in range(3, 6):
        r[a] *= s_rot
        cost += r[a] * r[a]
        for j in range(dof):
            Jr[a, j] *= s_rot
    return 0.5 * cost


@jit
def cholesky_solve(A, b, x):
    """Solve ``A x = b`` for symmetric positive definite ``A`` (overwritten by its factor).

    Returns False (and leaves ``x`` undefined) when ``A`` is not positive definite.
    """
    n = b.shape[0]
    for j in range(n):
        s = A[j, j]
        for k in range(j):
            s -= A[j, k] * A[j, k]
        if not s > 0.0:
            return False
        d = np.sqrt(s)
        A[j, j] = d
        for i in range(j + 1, n):
            s = A[i, j]
            for k in range(j):
                s -= A[i, k] * A[j, k]
            A[i, j] = s / d
    for i in range(n):
        s = b[i]
        for k in range(i):
            s -= A[i, k] * x[k]
        x[i] = s / A[i, i]
    for i in range(n - 1, -1, -1):
        s = x[i]
        for k in range(i + 1, n):
            s -= A[k, i] * x[k]
        x[i] = s / A[i, i]
    return True


@jit
def copy_into(src, dst):
    """``dst[:len(src)] = src`` by a loop: a slice assignment would compile numba's
    shape-mismatch error path (string formatting), seconds of the first run."""
    for j in range(src.shape[0]):
        dst[j] = src[j]


@jit
def into_limits(v, kind, lo, hi):
    """Joint value ``v`` moved into ``[lo, hi]``: a revolute joint by the multiple of 2 pi
    that brings it inside, when one does (the same arm configuration), else clipped."""
    if v < lo or v > hi:
        if kind != PRISMATIC:
            turn = 2.0 * np.pi
            if v < lo:
                w = v + turn * np.ceil((lo - v) / turn)
            else:
                w = v - turn * np.ceil((v - hi) / turn)
            if lo <= w <= hi:
                return w
        return min(max(v, lo), hi)
    return v


@jit
def damped_step(ctx, ws, lam, q):
    """The damped Gauss-Newton step ``ws.step`` from ``ws.JtJ`` and ``ws.g``, joints at a
    limit that would leave it held fixed (a revolute joint whose range spans a full turn
    is never held: it wraps round). Returns False when the system is not solvable."""
    JtJ, g, A, gb, blocked, step = ws.JtJ, ws.g, ws.A, ws.gb, ws.blocked, ws.step
    lo, hi, types = ctx.chain.lower, ctx.chain.upper, ctx.chain.joint_types
    dof = q.shape[0]
    mean_diag = 0.0
    for i in range(dof):
        mean_diag += JtJ[i, i]
    mu = 1e-9 * max(mean_diag / dof, 1e-12)
    for i in range(dof):
        for j in range(dof):
            A[i, j] = JtJ[i, j]
        A[i, i] += lam * (JtJ[i, i] + mu)
    if not cholesky_solve(A, g, step):
        return False
    held = False
    for i in range(dof):
        blocked[i] = ((q[i] <= lo[i] and step[i] < 0.0) or (q[i] >= hi[i] and step[i] > 0.0)) and (
            types[i] == PRISMATIC or hi[i] - lo[i] < 2.0 * np.pi)
        held = held or blocked[i]
    if not held:
        return True
    for i in range(dof):  # solve for the free joints only
        for j in range(dof):
            A[i, j] = 0.0 if (blocked[i] or blocked[j]) else JtJ[i, j]
        A[i, i] = 1.0 if blocked[i] else A[i, i] + lam * (JtJ[i, i] + mu)
        gb[i] = 0.0 if blocked[i] else g[i]
    return cholesky_solve(A, gb, step)


@jit(inline=True)
def lm_start(ctx, ws, q, scale, stall_ratio):
    """Levenberg-Marquardt from ``q`` (clipped into the limits; updated in place).

    Converged means position error <= ``ctx.stop_position`` (robot unit) and
    orientation error <= ``ctx.stop_orientation`` (rad); a negative
    ``stop_position`` never converges (front scalarisations). ``scale``: the
    residual's ``(position, rotation)`` row scales (:func:`residual`); ``stall_ratio``:
    the cost must fall below this fraction every :data:`STALL_WINDOW` iterations
    (1: never abandoned for slow progress). Returns ``(converged, cost, n_eval)``.
    """
    dof = q.shape[0]
    lo, hi, types = ctx.chain.lower, ctx.chain.upper, ctx.chain.joint_types
    r, Jr, rt, Jrt, trial = ws.r, ws.Jr, ws.rt, ws.Jrt, ws.trial
    JtJ, g, step = ws.JtJ, ws.g, ws.step
    stop_pos, stop_ori, max_iter = ctx.stop_position, ctx.stop_orientation, ctx.max_iter
    s_pos, s_rot = scale
    for j in range(dof):
        q[j] = min(max(q[j], lo[j]), hi[j])
    cost = residual(ctx, ws, q, scale, r, Jr)
    n_eval = 1
    if not np.isfinite(cost):
        return False, cost, n_eval
    stop_p2, stop_o2 = stop_pos * stop_pos * s_pos * s_pos, stop_ori * stop_ori * s_rot * s_rot
    lam, check_cost, limit = LAMBDA0, cost, max_iter
    for it in range(max_iter + EXTRA_ITER + 1):
        if stop_pos >= 0.0 and r[0] * r[0] + r[1] * r[1] + r[2] * r[2] <= stop_p2 and (
                r[3] * r[3] + r[4] * r[4] + r[5] * r[5] <= stop_o2):
            return True, cost, n_eval
        near = cost < NEAR_COST
        if it > 0 and it % STALL_WINDOW == 0 and not near:
            if cost > stall_ratio * check_cost:
                break
            check_cost = cost
        if it >= limit:
            if near and limit == max_iter:
                limit = max_iter + EXTRA_ITER
            else:
                break
        for i in range(dof):  # normal equations
            s = 0.0
            for k in range(6):
                s -= Jr[k, i] * r[k]
            g[i] = s
            for j in range(i, dof):
                s = 0.0
                for k in range(6):
                    s += Jr[k, i] * Jr[k, j]
                JtJ[i, j] = s
                JtJ[j, i] = s
        accepted = False
        while lam < LAMBDA_MAX:
            if damped_step(ctx, ws, lam, q):
                for j in range(dof):
                    trial[j] = into_limits(q[j] + step[j], types[j], lo[j], hi[j])
                cost_t = residual(ctx, ws, trial, scale, rt, Jrt)
                n_eval += 1
                if cost_t < cost:
                    copy_into(trial, q)
                    copy_into(rt, r)
                    for a in range(6):
                        copy_into(Jrt[a], Jr[a])
                    cost = cost_t
                    lam = max(lam / 3.0, 1e-12)
                    accepted = True
                    break
            lam *= 4.0
        if not accepted:
            break
    return False, cost, n_eval
