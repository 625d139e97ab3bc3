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
from moik.problems.targets import Target
from moik.robots.chain import Robot
from moik.robots.transforms import PRISMATIC
from moik.solver.lm import FRONT_STALL_RATIO, STALL_RATIO, lm_start


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
        q[:] = Q0[s]
        conv, cost, ne = lm_start(F, types, lo, hi, q, Rt, pt, has_rot, inv_len, 1.0, stop_pos,
                                  stop_ori, max_iter, stall_ratio)
        n_eval += ne
        if cost < best_cost:
            best_cost = cost
            best_q[:] = q
        if conv:
            new = True
            for k in range(n_found):
                if wrapped_distance(out_Q[k], q, types) <= distinct:
                    new = False
                    break
            if new:
                out_Q[n_found] = q
                n_found += 1
    return n_found, n_eval, used, best_cost


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
            q[:] = Q0[s] if s < n else out_Q[i - 1]
            _, cost, ne = lm_start(F, types, lo, hi, q, Rt, pt, True, s_pos, s_rot, -1.0, -1.0,
                                   max_iter, FRONT_STALL_RATIO)
            n_eval += ne
            if cost < best:
                best = cost
                out_Q[i] = q
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
    if n_known:
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
