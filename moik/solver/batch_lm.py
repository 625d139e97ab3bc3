"""Batched multi-start Levenberg-Marquardt IK: many starts in one numpy pass.

The residual and its exact Jacobian are those of :mod:`moik.solver.polish`
(``[(p - p_t) / L, log(R R_t^T)]`` and ``[J_v / L; J_l^{-1}(r) J_w]``, from
:mod:`moik.kinematics.so3`), computed for a whole batch of joint vectors at
once: each iteration is one batched FK + Jacobian pass, one batched rotation
log and one batched linear solve, whatever the number of starts. The step of start ``i`` is

    (J_i^T J_i + lambda_i (diag(J_i^T J_i) + mu I)) delta_i = -J_i^T r_i

(Levenberg 1944, Marquardt 1963, with Marquardt's diagonal scaling; ``mu``, a
small multiple of the mean diagonal, keeps redundant arms' singular ``J^T J``
invertible). The trial point is projected onto the joint limits; it is kept
when the cost ``0.5 ||r||^2`` decreases (``lambda /= 3``), else rejected
(``lambda *= 4``), the usual trust-region-like control. Joints at a limit
whose step points outwards are held there and the step is solved for the
others (an active-set projection, as in dogbox). Starts are dropped
once within the stopping tolerances; every iterate is within the limits.

This is a fast first attempt for :func:`moik.solver.solve_ik`; the global
search (metaheuristic + bounded least squares) remains the fallback.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from moik.kinematics.jacobian import parts_and_jacobian
from moik.kinematics.so3 import pose_residual, pose_residual_jacobian
from moik.problems.targets import Target
from moik.robots.chain import Robot

_LAMBDA0 = 1e-3
_LAMBDA_MAX = 1e8


@dataclass(frozen=True)
class BatchLMResult:
    """Outcome of :func:`batch_lm`.

    Attributes:
        Q: Final joint vectors ``(n, dof)``, within the limits.
        position_error: ``(n,)`` position errors (robot unit) of the kernel FK.
        orientation_error: ``(n,)`` rotation-vector norms (rad), 0 without rotation.
        converged: ``(n,)`` whether each start met the stopping tolerances.
        n_eval: FK evaluations (one per start per iteration it was active).
    """

    Q: np.ndarray
    position_error: np.ndarray
    orientation_error: np.ndarray
    converged: np.ndarray
    n_eval: int


def _residuals(robot: Robot, target: Target, length: float, Q: np.ndarray):
    """Residuals ``(n, m)`` and exact Jacobians ``(n, m, dof)`` of a batch."""
    R, p, J = parts_and_jacobian(robot, Q)
    r = pose_residual(p, R, target.position, target.rotation, length)
    return r, pose_residual_jacobian(J, r, length)


def batch_lm(robot: Robot, target: Target, Q0: np.ndarray, *, length: float,
             stop_position: float, stop_orientation: float, max_iter: int = 30,
             stop_after: int | None = None) -> BatchLMResult:
    """Run Levenberg-Marquardt from every row of ``Q0`` at once.

    Args:
        robot: The arm.
        target: Position or pose target.
        Q0: Starts ``(n, dof)`` (clipped into the limits).
        length: Characteristic length ``L`` of the residual (robot unit).
        stop_position: A start is done when its position error is at most
            this (robot unit) ...
        stop_orientation: ... and its orientation error at most this (rad).
        max_iter: Iterations at most.
        stop_after: Stop the whole batch once this many starts are done
            (``None``: run every start to convergence or ``max_iter``).
    """
    Q = np.clip(np.array(Q0, dtype=float, ndmin=2), robot.lower, robot.upper)
    n, dof = Q.shape
    r, J = _residuals(robot, target, length, Q)
    n_eval = n
    cost = 0.5 * np.einsum("ij,ij->i", r, r)
    lam = np.full(n, _LAMBDA0)
    done = _within(r, length, stop_position, stop_orientation)
    active = ~done & np.isfinite(cost)
    eye = np.eye(dof)
    for _ in range(max_iter):
        if not active.any() or (stop_after is not None and done.sum() >= stop_after):
            break
        JtJ = J.transpose(0, 2, 1) @ J
        g = np.einsum("kmi,km->ki", J, r)
        diag = np.einsum("kii->ki", JtJ)
        mu = 1e-9 * np.maximum(diag.mean(axis=1), 1e-12)
        A = JtJ + lam[:, None, None] * (diag[:, :, None] * eye + mu[:, None, None] * eye)
        step = np.linalg.solve(A, -g[:, :, None])[:, :, 0]
        blocked = ((np.less_equal(Q, robot.lower) & (step < 0))
                   | (np.greater_equal(Q, robot.upper) & (step > 0)))
        if blocked.any():  # joints held at a limit: solve for the free ones only
            free = ~blocked
            A = A * free[:, :, None] * free[:, None, :] + blocked[:, :, None] * eye
            step = np.linalg.solve(A, -(g * free)[:, :, None])[:, :, 0]
        trial = np.clip(Q + step, robot.lower, robot.upper)
        r_t, J_t = _residuals(robot, target, length, trial)
        n_eval += int(active.sum())
        cost_t = 0.5 * np.einsum("ij,ij->i", r_t, r_t)
        better = active & (cost_t < cost)
        Q = np.where(better[:, None], trial, Q)
        r = np.where(better[:, None], r_t, r)
        J = np.where(better[:, None, None], J_t, J)
        cost = np.where(better, cost_t, cost)
        lam = np.where(better, np.maximum(lam / 3.0, 1e-12), np.where(active, 4.0 * lam, lam))
        done |= better & _within(r_t, length, stop_position, stop_orientation)
        active = ~done & (lam < _LAMBDA_MAX)
    pos = np.linalg.norm(r[:, :3], axis=1) * length
    ori = np.linalg.norm(r[:, 3:], axis=1) if r.shape[1] > 3 else np.zeros(n)
    return BatchLMResult(Q, pos, ori, done, n_eval)


def _within(r: np.ndarray, length: float, stop_position: float,
            stop_orientation: float) -> np.ndarray:
    pos_ok = np.einsum("ij,ij->i", r[:, :3], r[:, :3]) * length**2 <= stop_position**2
    if r.shape[1] == 3:
        return pos_ok
    return pos_ok & (np.einsum("ij,ij->i", r[:, 3:], r[:, 3:]) <= stop_orientation**2)
