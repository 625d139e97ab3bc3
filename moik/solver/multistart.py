"""Starts in turn and weighted-sum fronts: the loops around :func:`moik.solver.lm.lm_start`.

:func:`lm_multistart` runs the compiled Levenberg-Marquardt from one start after
another until enough distinct solutions (modulo 2 pi) are found; :func:`lm_front`
solves the weighted-sum scalarisations of an unreachable pose's front;
:func:`multistart` and :func:`front` are their Python entries.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from moik._jit import jit, kernel_array
from moik.kinematics.rotation_metrics import geodesic_angle
from moik.problems.targets import Target
from moik.robots.chain import Robot
from moik.robots.dh import fk_pose_into
from moik.robots.transforms import PRISMATIC
from moik.solver.lm import FRONT_STALL_RATIO, STALL_RATIO, copy_into, lm_start


@jit
def wrapped_distance(a, b, types):
    """Joint-space distance, revolute differences wrapped to ``[-pi, pi)``."""
    s = 0.0
    for j in range(a.shape[0]):
        d = b[j] - a[j]
        if types[j] != PRISMATIC:
            d = (d + np.pi) % (2.0 * np.pi) - np.pi
        s += d * d
    return np.sqrt(s)


@jit
def lm_multistart(F, types, lo, hi, Q0, Rt, pt, has_rot, inv_len, stop_pos, stop_ori,
                  max_iter, n_known, distinct, stall_ratio, max_evals, out_Q, best_q):
    """LM from the rows of ``Q0`` in turn until ``out_Q`` is full of distinct solutions.

    ``out_Q[:n_known]`` holds solutions known before; new ones (farther than
    ``distinct`` from every other, modulo 2 pi) are appended until
    ``len(out_Q)`` are known. The lowest-cost end of any start goes to ``best_q``.
    Returns ``(n_found, n_eval, starts_used, best_cost)`` (``n_found`` includes
    the known ones). No new start begins once ``max_evals`` FK evaluations are spent.
    """
    n, dof = Q0.shape
    want = out_Q.shape[0]
    n_found, n_eval, used, best_cost = n_known, 0, 0, np.inf
    q = np.empty(dof)
    for s in range(n):
        if n_found >= want or n_eval >= max_evals:
            break
        used += 1
        copy_into(Q0[s], q)
        conv, cost, ne = lm_start(F, types, lo, hi, q, Rt, pt, has_rot, inv_len, 1.0, stop_pos,
                                  stop_ori, max_iter, stall_ratio)
        n_eval += ne
        if cost < best_cost:
            best_cost = cost
            copy_into(q, best_q)
        if conv:
            new = True
            for k in range(n_found):
                if wrapped_distance(out_Q[k], q, types) <= distinct:
                    new = False
                    break
            if new:
                copy_into(q, out_Q[n_found])
                n_found += 1
    return n_found, n_eval, used, best_cost


@jit
def recheck_into(F, types, q, Rt, pt, has_rot, T, out):
    """Position error (robot unit) and geodesic orientation error (rad) of ``q`` into
    ``out (2,)``, by an FK pass of their own (not the optimizer's residual)."""
    fk_pose_into(F, types, q, T)
    d0, d1, d2 = T[0, 3] - pt[0], T[1, 3] - pt[1], T[2, 3] - pt[2]
    out[0] = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    out[1] = 0.0
    if has_rot:
        rot = (T[0, 0], T[0, 1], T[0, 2], T[1, 0], T[1, 1], T[1, 2], T[2, 0], T[2, 1], T[2, 2])
        out[1] = geodesic_angle(rot, Rt)


@jit
def starts_checked(F, types, lo, hi, Q0, Rt, pt, has_rot, inv_len, tol_pos, tol_ori,
                   stop_fraction, max_iter, distinct, stall_ratio, max_evals, found, found_err,
                   n_known, best):
    """:func:`lm_multistart` with the honest re-check fused in (one compiled call).

    LM runs from the rows of ``Q0`` in turn, stopping at ``stop_fraction`` of the
    tolerances; a converged end is re-checked by :func:`recheck_into` and appended to
    ``found`` (its errors to ``found_err``) when within ``(tol_pos, tol_ori)`` and farther
    than ``distinct`` from every solution in ``found`` (modulo 2 pi), until ``found`` is
    full. ``best`` (``dof + 1``: the scaled error ``pos / L + ori``, then q) is replaced by
    a re-checked candidate with a smaller error: the new solutions, or the lowest-cost end
    when none was new. No start begins once ``max_evals`` evaluations are spent.
    Returns ``(n_found, n_eval)``.
    """
    n, dof = Q0.shape
    want = found.shape[0]
    n_found, n_eval, low_cost = n_known, 0, np.inf
    q, low_q, T, err = np.empty(dof), np.empty(dof), np.empty((4, 4)), np.empty(2)
    for s in range(n):
        if n_found >= want or n_eval >= max_evals:
            break
        copy_into(Q0[s], q)
        conv, cost, ne = lm_start(F, types, lo, hi, q, Rt, pt, has_rot, inv_len, 1.0,
                                  stop_fraction * tol_pos, stop_fraction * tol_ori, max_iter,
                                  stall_ratio)
        n_eval += ne
        if cost < low_cost:
            low_cost = cost
            copy_into(q, low_q)
        if not conv:
            continue
        recheck_into(F, types, q, Rt, pt, has_rot, T, err)
        if err[0] > tol_pos or err[1] > tol_ori:
            continue
        new = True
        for k in range(n_found):
            if wrapped_distance(found[k], q, types) <= distinct:
                new = False
                break
        if new:
            copy_into(q, found[n_found])
            found_err[n_found, 0], found_err[n_found, 1] = err[0], err[1]
            n_found += 1
            scaled = err[0] * inv_len + err[1]
            if scaled < best[0]:
                best[0] = scaled
                copy_into(q, best, 1)
    if n_found == n_known and np.isfinite(low_cost):
        recheck_into(F, types, low_q, Rt, pt, has_rot, T, err)
        scaled = err[0] * inv_len + err[1]
        if scaled < best[0]:
            best[0] = scaled
            copy_into(low_q, best, 1)
    return n_found, n_eval


@jit
def lm_front(F, types, lo, hi, Q0, Rt, pt, inv_len, weights, max_iter, out_Q):
    """Weighted-sum scalarisations of (position, orientation) error, one per weight.

    Weight ``w`` minimises ``0.5 (w |p - p_t|^2 / L^2 + (1 - w) |log(R R_t^T)|^2)``
    from every row of ``Q0`` and from the previous weight's answer; the lowest
    cost end goes to ``out_Q[i]``. Returns the number of FK evaluations.
    """
    n, dof = Q0.shape
    q = np.empty(dof)
    n_eval = 0
    for i in range(weights.shape[0]):
        s_pos, s_rot = inv_len * np.sqrt(weights[i]), np.sqrt(1.0 - weights[i])
        best = np.inf
        for s in range(n + (1 if i > 0 else 0)):
            copy_into(Q0[s] if s < n else out_Q[i - 1], q)
            _, cost, ne = lm_start(F, types, lo, hi, q, Rt, pt, True, s_pos, s_rot, -1.0, -1.0,
                                   max_iter, FRONT_STALL_RATIO)
            n_eval += ne
            if cost < best:
                best = cost
                copy_into(q, out_Q[i])
    return n_eval


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


def _target_arrays(target: Target) -> tuple[np.ndarray, np.ndarray, bool]:
    has_rot = target.rotation is not None
    Rt = kernel_array(target.rotation if has_rot else np.eye(3))
    return Rt, kernel_array(target.position), has_rot


def multistart(robot: Robot, target: Target, Q0: np.ndarray, *, stop_position: float,
               stop_orientation: float, want: int = 1, distinct: float = 0.1,
               known: np.ndarray | None = None, max_iter: int = 30,
               patient: bool = False, max_evals: int = 2**62) -> MultiStartResult:
    """Levenberg-Marquardt from the rows of ``Q0`` until ``want`` distinct solutions are known.

    Args:
        robot, target: The problem (``L = robot.reach``).
        Q0: Starts ``(n, dof)``, tried in order (each clipped into the limits).
        stop_position, stop_orientation: A start has converged when its errors
            (robot unit, rad) are at most these.
        want: Solutions wanted in all (``known`` included).
        distinct: Joint-space distance (revolute joints modulo 2 pi) above which two
            solutions count as distinct.
        known: Solutions found before (not searched for again).
        max_iter: Iterations per start (see the module docstring for the extensions).
        patient: Never abandon a start for slow progress (for starts known to be
            near a solution, such as the current configuration).
        max_evals: No new start begins once this many FK evaluations are spent.
    """
    chain = robot.kinematic_chain
    Rt, pt, has_rot = _target_arrays(target)
    out = np.empty((want, robot.dof))
    n_known = 0 if known is None else min(len(known), want)
    if known is not None and n_known:
        out[:n_known] = known[:n_known]
    best = np.empty(robot.dof)
    n_found, n_eval, used, best_cost = lm_multistart(
        chain.origins, chain.joint_types, robot.lower, robot.upper, kernel_array(Q0), Rt, pt,
        has_rot, 1.0 / robot.reach, stop_position, stop_orientation, max_iter, n_known,
        distinct, 1.0 if patient else STALL_RATIO, max_evals, out, best)
    return MultiStartResult(out[:n_found], best, float(best_cost), int(n_eval), int(used))


def front(robot: Robot, target: Target, Q0: np.ndarray, weights: np.ndarray,
          max_iter: int = 100) -> tuple[np.ndarray, int]:
    """Joint vectors ``(len(weights), dof)`` minimising each weighted sum (:func:`lm_front`).

    Returns them with the number of FK evaluations. ``target`` must have a rotation.
    """
    chain = robot.kinematic_chain
    Rt, pt, _ = _target_arrays(target)
    out = np.empty((len(weights), robot.dof))
    n_eval = lm_front(chain.origins, chain.joint_types, robot.lower, robot.upper,
                      kernel_array(Q0), Rt, pt, 1.0 / robot.reach, kernel_array(weights),
                      max_iter, out)
    return out, int(n_eval)
