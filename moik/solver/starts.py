"""The one start loop around :func:`moik.solver.lm.lm_start`, and the weighted-sum front.

:func:`run_starts` runs the compiled Levenberg-Marquardt from the rows of ``starts`` in
turn on one :class:`~moik.solver.context.IKContext`; its ``policy`` says what becomes
of each end: collected when it converged and is new (modulo 2 pi; optionally only after
an FK re-check within the tolerances), or kept per row (``found=None``: a projection).
Every caller uses it: :class:`~moik.solver.session.SolveSession` (re-checked starts), the batch
(:func:`run_batch`, one context re-targeted per target), the Pareto projector and
branch enumeration (:mod:`moik.solver.pareto_search`) and :func:`multistart`.
:func:`lm_front` solves the weighted-sum scalarisations of an unreachable pose's front.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from moik._jit import jit, kernel_array
from moik.collision.compiled import checks_pairs, end_distance, end_scratch
from moik.kinematics.criteria import joint_distance
from moik.kinematics.criteria_kernels import wrapped_distance
from moik.kinematics.rotation_metrics import geodesic_angle
from moik.problems.targets import Target
from moik.robots.chain import Robot
from moik.robots.fk_kernels import fk_pose_into
from moik.solver.context import NO_STOP, ik_context, lm_workspace, retarget
from moik.solver.lm import FRONT_STALL_RATIO, STALL_RATIO, copy_into, lm_start

# policy flags of run_starts
CHECK = 1  # a converged end is a solution only if an FK re-check puts it within tolerance
PATIENT = 2  # no start is abandoned for slow progress (a start near a solution)
UNLIMITED = 2**62  # a budget that never stops the loop


@jit
def is_new(ctx, found, n_found, q):
    """Whether ``q`` is farther than ``ctx.distinct`` from each of ``found[:n_found]``."""
    for k in range(n_found):
        if wrapped_distance(found[k], q, ctx.chain.joint_types) <= ctx.distinct:
            return False
    return True


def is_distinct(robot: Robot, q: np.ndarray, others: list[np.ndarray], threshold: float) -> bool:
    """Whether ``q`` is farther than ``threshold`` from every row of ``others``
    (:func:`~moik.kinematics.criteria.joint_distance`, the distance :func:`is_new` uses)."""
    return not others or bool(np.all(joint_distance(robot, q, np.array(others)) > threshold))


@jit
def recheck(ctx, ws, q):
    """Position error (robot unit) and geodesic orientation error (rad) of ``q`` into
    ``ws.err``, by an FK pass of their own (not the optimizer's residual); whether both
    are within ``ctx``'s tolerances."""
    T, err, pt = ws.T, ws.err, ctx.target.position
    fk_pose_into(ctx.chain.origins, ctx.chain.joint_types, q, T)
    d0, d1, d2 = T[0, 3] - pt[0], T[1, 3] - pt[1], T[2, 3] - pt[2]
    err[0] = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    err[1] = 0.0
    if ctx.target.has_rotation:
        rot = (T[0, 0], T[0, 1], T[0, 2], T[1, 0], T[1, 1], T[1, 2], T[2, 0], T[2, 1], T[2, 2])
        err[1] = geodesic_angle(rot, ctx.target.rotation)
    return err[0] <= ctx.tol_position and err[1] <= ctx.tol_orientation


@jit
def keep_found(ctx, ws, found, n_found, q):
    """Append ``q`` (its re-checked errors from ``ws.err``) to ``found`` if new; the count."""
    if not is_new(ctx, found, n_found, q):
        return n_found
    dof = q.shape[0]
    copy_into(q, found[n_found])
    found[n_found, dof], found[n_found, dof + 1] = ws.err[0], ws.err[1]
    return n_found + 1


@jit
def solution_cost(ctx):
    """The largest cost ``0.5 |r|^2`` of an end within both of ``ctx``'s tolerances (an end
    costing more cannot be a solution; one costing less is re-checked)."""
    tp, to = ctx.tol_position * ctx.chain.inv_reach, ctx.tol_orientation
    return 0.5 * (tp * tp + to * to)


@jit
def improve_best(ctx, ws, best, q):
    """``best = [scaled error, q]`` replaced by ``q`` when its re-checked (``ws.err``)
    error ``pos / L + ori`` is smaller."""
    scaled = ws.err[0] * ctx.chain.inv_reach + ws.err[1]
    if scaled < best[0]:
        best[0] = scaled
        copy_into(q, best[1:])


@jit
def run_starts(ctx, starts, policy, found, best, ends):
    """Levenberg-Marquardt from the rows of ``starts`` in turn (each row is left where its
    start ended, within the limits).

    Args:
        ctx: The solve's :class:`~moik.solver.context.IKContext`.
        starts: ``(n, dof)`` starts, overwritten by the ends.
        policy: ``(flags, budget)``: :data:`CHECK`, :data:`PATIENT` or'd; no start begins
            once ``budget`` FK evaluations are spent.
        found: ``(want, dof + 2)`` solutions, each ``[q, position error, orientation
            error]`` (the errors NaN when not re-checked); the rows known before are
            filled, the others NaN. New ends (farther than ``ctx.distinct`` from every
            other, modulo 2 pi) are appended until it is full. ``None``: a projection,
            every row is run (whatever the budget) and only ``ends`` is written; numba
            compiles that case alone (no re-check, collision test or bookkeeping: the
            Pareto search's cold start compiles less), ``best`` is then ``None`` too.
        best: ``[value, q]`` (``dof + 1``), replaced by a smaller candidate: without
            :data:`CHECK` the lowest-cost end (value: its cost ``0.5 |r|^2``); with it the
            re-checked new solutions, or the lowest-cost end when none was new (value:
            ``pos / L + ori``). With :data:`CHECK`, an end that did not converge but whose
            cost could be within the tolerances (a start may stall between the stop and
            the tolerance) is re-checked too, and a solution when it is within them.
        ends: ``(n, 3)``: each start's (converged, cost, distance), written for the
            starts run; distance: the smallest signed distance of an end that passed
            the pose test when ``ctx.collision`` has pairs (an end below
            ``ctx.clearance`` is rejected: the loop goes on), else NaN.

    Returns:
        ``(n_found, n_eval, n_used)``: solutions known now, FK evaluations, starts run.
    """
    flags, budget = policy
    n, dof = starts.shape
    stall_ratio = 1.0 if flags & PATIENT else STALL_RATIO
    scale = (ctx.chain.inv_reach, 1.0)
    ws = lm_workspace(dof)
    if found is None:  # a projection (the branch numba keeps for found=None, and only it)
        n_eval = 0
        for s in range(n):
            conv, cost, ne = lm_start(ctx, ws, starts[s], scale, stall_ratio)
            n_eval += ne
            ends[s, 0], ends[s, 1], ends[s, 2] = conv, cost, np.nan
        return 0, n_eval, n
    want, check = found.shape[0], flags & CHECK != 0
    tol_cost = solution_cost(ctx)
    collide = checks_pairs(ctx.collision)
    scratch = end_scratch(ctx.collision)
    n_known = 0
    while n_known < want and not np.isnan(found[n_known, 0]):
        n_known += 1
    n_found, n_eval, used, low, low_cost = n_known, 0, 0, -1, np.inf
    for s in range(n):
        if n_found >= want or n_eval >= budget:
            break
        used += 1
        q = starts[s]
        conv, cost, ne = lm_start(ctx, ws, q, scale, stall_ratio)
        n_eval += ne
        ends[s, 0], ends[s, 1], ends[s, 2] = conv, cost, np.nan
        if cost < low_cost:
            low, low_cost = s, cost
        if not (conv or (check and cost <= tol_cost)):
            continue
        if check and not recheck(ctx, ws, q):
            continue
        if collide:
            ends[s, 2] = end_distance(ctx.collision, q, scratch, ctx.clearance)
            if not ends[s, 2] >= ctx.clearance:  # in collision (or NaN): not a solution
                continue
        if not check:
            ws.err[0], ws.err[1] = np.nan, np.nan
        n_before = n_found
        n_found = keep_found(ctx, ws, found, n_found, q)
        if check and n_found > n_before:
            improve_best(ctx, ws, best, q)
    if low < 0:
        return n_found, n_eval, used
    if not check:
        if low_cost < best[0]:
            best[0] = low_cost
            copy_into(starts[low], best[1:])
    elif n_found == n_known:
        recheck(ctx, ws, starts[low])
        improve_best(ctx, ws, best, starts[low])
    return n_found, n_eval, used


@jit(nogil=True)
def run_batch(ctx, starts, targets, policy, found, n_evals):
    """:func:`run_starts` for target ``i`` (``targets = (rotations (n, 3, 3), positions
    (n, 3))``) from the rows of ``starts[i]``, into ``found[i]`` (``(n, want, dof + 2)``);
    a target already solved (``found[i, 0]`` filled) or out of budget is skipped, and the
    budget of ``policy`` counts each target's ``n_evals[i]`` (accumulated). Releases the
    GIL (threads run it on chunks of a batch, each with a context of its own)."""
    flags, budget = policy
    n, k, dof = starts.shape
    best, ends = np.empty(dof + 1), np.empty((k, 3))
    for i in range(n):
        if not np.isnan(found[i, 0, 0]) or n_evals[i] >= budget:
            continue
        retarget(ctx, targets[0][i], targets[1][i])
        best[0] = np.inf
        _, ne, _ = run_starts(ctx, starts[i], (flags, budget - n_evals[i]), found[i], best,
                              ends)
        n_evals[i] += ne


@jit
def lm_front(ctx, Q0, weights, budget, out_Q):
    """Weighted-sum scalarisations of (position, orientation) error, one per weight.

    Weight ``w`` minimises ``0.5 (w |p - p_t|^2 / L^2 + (1 - w) |log(R R_t^T)|^2)``
    from every row of ``Q0`` and from the previous weight's answer; the lowest
    cost end goes to ``out_Q[i]``. ``ctx`` has a rotation and :data:`NO_STOP`. No
    start begins once ``budget`` FK evaluations are spent: the weights left keep the
    previous weight's answer. Returns the number of FK evaluations.
    """
    n, dof = Q0.shape
    q = np.empty(dof)
    ws = lm_workspace(dof)
    n_eval = 0
    for i in range(weights.shape[0]):
        scale = (ctx.chain.inv_reach * np.sqrt(weights[i]), np.sqrt(1.0 - weights[i]))
        best = np.inf
        if i > 0 and n_eval >= budget:
            copy_into(out_Q[i - 1], out_Q[i])
            continue
        for s in range(n + (1 if i > 0 else 0)):
            if s > 0 and n_eval >= budget:
                break
            copy_into(Q0[s] if s < n else out_Q[i - 1], q)
            _, cost, ne = lm_start(ctx, ws, q, scale, FRONT_STALL_RATIO)
            n_eval += ne
            if cost < best:
                best = cost
                copy_into(q, out_Q[i])
    return n_eval


def found_table(want: int, dof: int, known=(), errors=()) -> np.ndarray:
    """The ``found`` table of :func:`run_starts`: the ``known`` rows (and their
    ``errors``) first, the rest NaN."""
    table = np.full((want, dof + 2), np.nan)
    for k in range(min(len(known), want)):
        table[k, :dof] = known[k]
        if len(errors):
            table[k, dof:] = errors[k]
    return table


@dataclass(frozen=True)
class MultiStartResult:
    """Outcome of :func:`multistart`.

    Attributes:
        solutions: ``(k, dof)`` distinct solutions (known ones first), within the limits.
        best_q: The lowest-cost end of any start (the solution or the nearest miss).
        best_cost: Its cost ``0.5 |r|^2`` (residual scaled by ``1 / L``).
        n_eval: FK + Jacobian evaluations.
        starts_used: Rows of ``Q0`` tried before enough solutions were found.
    """

    solutions: np.ndarray
    best_q: np.ndarray
    best_cost: float
    n_eval: int
    starts_used: int


def multistart(robot: Robot, target: Target, Q0: np.ndarray, *, stop_position: float,
               stop_orientation: float, want: int = 1, distinct: float = 0.1,
               known: np.ndarray | None = None, max_iter: int = 30,
               patient: bool = False, max_evals: int = UNLIMITED) -> MultiStartResult:
    """Levenberg-Marquardt from the rows of ``Q0`` until ``want`` distinct solutions are known
    (:func:`run_starts` without re-check).

    Args:
        robot, target: The problem (``L = robot.reach``).
        Q0: Starts ``(n, dof)``, tried in order (each clipped into the limits).
        stop_position, stop_orientation: A start has converged when its errors
            (robot unit, rad) are at most these.
        want: Solutions wanted in all (``known`` included).
        distinct: Joint-space distance (revolute joints modulo 2 pi) above which two
            solutions count as distinct.
        known: Solutions found before (not searched for again).
        max_iter: Iterations per start (see :mod:`moik.solver.lm` for the extensions).
        patient: Never abandon a start for slow progress (for starts known to be
            near a solution, such as the current configuration).
        max_evals: No new start begins once this many FK evaluations are spent.
    """
    ctx = ik_context(robot, target, stop=(stop_position, stop_orientation), distinct=distinct,
                     max_iter=max_iter)
    starts = np.array(Q0, dtype=np.float64, order="C", copy=True)
    found = found_table(want, robot.dof, () if known is None else known)
    best = np.full(robot.dof + 1, np.inf)
    n_found, n_eval, used = run_starts(ctx, starts, (PATIENT if patient else 0, max_evals),
                                       found, best, np.empty((len(starts), 3)))
    return MultiStartResult(found[:n_found, :robot.dof], best[1:], float(best[0]), int(n_eval),
                            int(used))


def front(robot: Robot, target: Target, Q0: np.ndarray, weights: np.ndarray,
          max_iter: int = 100, budget: int = UNLIMITED) -> tuple[np.ndarray, int]:
    """Joint vectors ``(len(weights), dof)`` minimising each weighted sum (:func:`lm_front`,
    no start begun past ``budget`` evaluations).

    Returns them with the number of FK evaluations. ``target`` must have a rotation.
    """
    ctx = ik_context(robot, target, stop=(NO_STOP, NO_STOP), max_iter=max_iter)
    out = np.empty((len(weights), robot.dof))
    n_eval = lm_front(ctx, kernel_array(Q0), kernel_array(weights), budget, out)
    return out, int(n_eval)
