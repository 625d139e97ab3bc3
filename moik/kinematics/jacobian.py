"""Geometric Jacobian of a robot, batched, for local polishing.

For joint ``j`` with unit axis ``z_j`` through the point ``o_j`` (base frame)
and end-effector position ``p``: a revolute column is
``[z_j x (p - o_j); z_j]``, a prismatic column ``[z_j; 0]`` (Siciliano et al.,
*Robotics*, Eq. 3.30). The axes come from the same FK kernel pass as the
pose, so the Jacobian costs about one FK plus a cross product.
"""

from __future__ import annotations

import numpy as np

from moik.robots.chain import Robot
from moik.robots.dh import assemble, run_steps


def kernel_jacobian(robot: Robot, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray,
                                                           np.ndarray, np.ndarray]:
    """Kernel state and geometric Jacobians of a 2-D batch, without validation.

    Returns:
        ``(xy, z, p, J)``: the FK kernel's x + i*y rotation columns (complex
        ``(3, n)``), z column ``(3, n)``, position ``(3, n)`` and the Jacobians
        ``(n, 6, dof)`` (see :func:`pose_and_jacobian`).
    """
    axes: list = []
    xy, z, p, _ = run_steps(robot._steps, Q, robot._offsets, axes=axes)
    zs = np.stack([a[0] for a in axes], axis=-1)  # (3, n, dof)
    arm = p[:, :, None] - np.stack([a[1] for a in axes], axis=-1)
    J = np.empty((Q.shape[0], 6, robot.dof))
    J[:, 0] = zs[1] * arm[2] - zs[2] * arm[1]  # z_j x (p - o_j), written out
    J[:, 1] = zs[2] * arm[0] - zs[0] * arm[2]
    J[:, 2] = zs[0] * arm[1] - zs[1] * arm[0]
    J[:, 3:] = zs.transpose(1, 0, 2)
    prismatic = robot.is_prismatic
    if prismatic.any():
        J[:, :3, prismatic] = J[:, 3:, prismatic]
        J[:, 3:, prismatic] = 0.0
    return xy, z, p, J


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
    single = Q.ndim == 1
    xy, z, p, J = kernel_jacobian(robot, Q[None] if single else Q)
    T = assemble(xy, z, p)
    return (T[0], J[0]) if single else (T, J)


def jacobian(robot: Robot, q) -> np.ndarray:
    """Geometric Jacobian ``(6, dof)`` or ``(n, 6, dof)`` (see :func:`pose_and_jacobian`)."""
    return pose_and_jacobian(robot, q)[1]
