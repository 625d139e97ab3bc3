"""Geometric Jacobian of a robot, compiled, in the same pass as the pose.

For joint ``j`` with unit axis ``z_j`` through the point ``o_j`` (base frame)
and end-effector position ``p``: a revolute column is
``[z_j x (p - o_j); z_j]``, a prismatic column ``[z_j; 0]`` (Siciliano et al.,
*Robotics*, Eq. 3.30). Joint ``j`` moves along the local z axis of the chain
``F_0 M_1 F_1 ... F_{j-1}``, so ``z_j`` and ``o_j`` are that partial product's z
column and position, read while the FK kernel walks the chain: the Jacobian costs
one FK plus a cross product per joint.

:func:`pose_jacobian_into` (one joint vector, preallocated outputs) is callable
from other compiled code; it takes the arrays of :attr:`Robot.kinematic_chain`.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit
from moik.robots.chain import Robot
from moik.robots.fk_kernels import PRISMATIC, compose, move_joint, pose_state, store_pose


@jit
def pose_jacobian_into(F, types, q, T, J):
    """Pose ``T (4, 4)`` and geometric Jacobian ``J (6, dof)`` of ``q (dof,)``, written in place.

    ``F`` and ``types`` are ``KinematicChain.origins`` and ``.joint_types``.
    """
    t = pose_state(F[0])
    dof = types.size
    for j in range(dof):  # the joint's axis point and direction, kept in J for now
        J[0, j], J[1, j], J[2, j] = t[9], t[10], t[11]
        J[3, j], J[4, j], J[5, j] = t[2], t[5], t[8]
        t = compose(move_joint(t, types[j], q[j]), pose_state(F[j + 1]))
    px, py, pz = t[9], t[10], t[11]
    for j in range(dof):
        zx, zy, zz = J[3, j], J[4, j], J[5, j]
        if types[j] == PRISMATIC:
            J[0, j], J[1, j], J[2, j] = zx, zy, zz
            J[3, j], J[4, j], J[5, j] = 0.0, 0.0, 0.0
        else:  # z_j x (p - o_j)
            ax, ay, az = px - J[0, j], py - J[1, j], pz - J[2, j]
            J[0, j] = zy * az - zz * ay
            J[1, j] = zz * ax - zx * az
            J[2, j] = zx * ay - zy * ax
    store_pose(t, T)


@jit
def poses_and_jacobians(F, types, Q):
    """Poses ``(n, 4, 4)`` and Jacobians ``(n, 6, dof)`` of ``Q (n, dof)``."""
    n = Q.shape[0]
    T = np.empty((n, 4, 4))
    J = np.empty((n, 6, types.size))
    for i in range(n):
        pose_jacobian_into(F, types, Q[i], T[i], J[i])
    return T, J


@jit
def parts_and_jacobians(F, types, Q):
    """Rotations ``(n, 3, 3)``, positions ``(n, 3)`` and Jacobians ``(n, 6, dof)`` of ``Q``."""
    n = Q.shape[0]
    R = np.empty((n, 3, 3))
    p = np.empty((n, 3))
    J = np.empty((n, 6, types.size))
    T = np.empty((4, 4))
    for i in range(n):
        pose_jacobian_into(F, types, Q[i], T, J[i])
        for a in range(3):
            p[i, a] = T[a, 3]
            for b in range(3):
                R[i, a, b] = T[a, b]
    return R, p, J


def parts_and_jacobian(robot: Robot, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """End-effector rotations, positions and Jacobians of a 2-D batch (no finiteness check).

    Returns:
        ``(R, p, J)``: ``(n, 3, 3)``, ``(n, 3)`` and ``(n, 6, dof)`` (see
        :func:`pose_and_jacobian`).
    """
    chain = robot.kinematic_chain
    return parts_and_jacobians(chain.origins, chain.joint_types, robot.kernel_batch(Q))


def pose_and_jacobian(robot: Robot, q) -> tuple[np.ndarray, np.ndarray]:
    """End-effector pose(s) and geometric Jacobian(s).

    Args:
        robot: The arm.
        q: ``(dof,)`` or ``(n, dof)`` joint values.

    Returns:
        ``(T, J)``: poses ``(4, 4)`` / ``(n, 4, 4)`` and Jacobians ``(6, dof)`` /
        ``(n, 6, dof)``; rows are linear velocity (robot unit per unit joint
        motion) then angular velocity (rad per unit joint motion), in the base frame.
    """
    Q = robot.check_q(q)
    chain = robot.kinematic_chain
    T, J = poses_and_jacobians(chain.origins, chain.joint_types, Q[None] if Q.ndim == 1 else Q)
    return (T[0], J[0]) if Q.ndim == 1 else (T, J)


def jacobian(robot: Robot, q) -> np.ndarray:
    """Geometric Jacobian ``(6, dof)`` or ``(n, 6, dof)`` (see :func:`pose_and_jacobian`)."""
    return pose_and_jacobian(robot, q)[1]
