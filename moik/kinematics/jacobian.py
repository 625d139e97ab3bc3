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
    Q2 = Q[None] if single else Q
    axes: list = []
    xy, z, p, _ = run_steps(robot._steps, Q2, robot._offsets, axes=axes)
    zs = np.stack([a[0] for a in axes], axis=-1)  # (3, n, dof)
    origins = np.stack([a[1] for a in axes], axis=-1)
    prismatic = robot.is_prismatic
    linear = np.cross(zs, p[:, :, None] - origins, axis=0)
    linear[:, :, prismatic] = zs[:, :, prismatic]
    angular = np.where(prismatic, 0.0, zs)
    J = np.concatenate([linear, angular], axis=0).transpose(1, 0, 2)  # (n, 6, dof)
    T = assemble(xy, z, p)
    return (T[0], J[0]) if single else (T, J)


def jacobian(robot: Robot, q) -> np.ndarray:
    """Geometric Jacobian ``(6, dof)`` or ``(n, 6, dof)`` (see :func:`pose_and_jacobian`)."""
    return pose_and_jacobian(robot, q)[1]
