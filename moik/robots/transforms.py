"""General serial chains: fixed transforms between joints that move along local z.

Any serial chain of 1-DOF joints can be written as
``F_0 M_1(q_1) F_1 M_2(q_2) ... M_n(q_n) F_n`` where each ``F_j`` is a constant
rigid transform and ``M_j`` is ``Rz(q_j)`` (revolute) or ``Tz(q_j)``
(prismatic). URDF chains, DH chains and chains with locked joints all take this
form. :func:`fixed_steps` decomposes a constant transform into the elementary
motions of the FK kernel (:mod:`moik.robots.dh`): ``Tx Ty Tz`` then the
rotation, as one ``Rz`` or ``Rx``, as an exact ZXZ product for axis-aligned
rotations, or else as one general 3x3 step; identities are skipped, so
axis-aligned URDF origins cost almost nothing.
"""

from __future__ import annotations

import warnings

import numpy as np
from scipy.spatial.transform import Rotation

from moik.robots.dh import exact_cos_sin


def rot_x(angle: float) -> np.ndarray:
    """4x4 rotation about x."""
    c, s = exact_cos_sin(angle)
    T = np.eye(4)
    T[1:3, 1:3] = [[c, -s], [s, c]]
    return T


def rot_z(angle: float) -> np.ndarray:
    """4x4 rotation about z."""
    c, s = exact_cos_sin(angle)
    T = np.eye(4)
    T[0:2, 0:2] = [[c, -s], [s, c]]
    return T


def translation(x: float = 0.0, y: float = 0.0, z: float = 0.0) -> np.ndarray:
    """4x4 translation."""
    T = np.eye(4)
    T[:3, 3] = (x, y, z)
    return T


def joint_motion(q: float, prismatic: bool) -> np.ndarray:
    """``Rz(q)`` or ``Tz(q)`` as a 4x4 matrix."""
    return translation(z=q) if prismatic else rot_z(q)


def _rz_step(angle: float) -> tuple | None:
    c, s = exact_cos_sin(angle)
    if (c, s) == (1.0, 0.0):
        return None
    return ("rz_fixed", complex(c, -s))


def fixed_steps(F: np.ndarray) -> list[tuple]:
    """Kernel steps equal to right-multiplying by the constant transform ``F``."""
    steps: list[tuple] = []
    x, y, z = (float(v) for v in F[:3, 3])
    if x != 0.0:
        steps.append(("tx", x))
    if y != 0.0:  # p += y * Im(xy) = Re(xy * (-i y)): a complex "tx" step
        steps.append(("tx", complex(0.0, -y)))
    if z != 0.0:
        steps.append(("tz", z))
    R = F[:3, :3]
    if np.array_equal(R, np.eye(3)):
        return steps
    if R[2, 2] == 1.0 and not R[2, :2].any() and not R[:2, 2].any():  # pure Rz
        steps.append(_rz_step(float(np.arctan2(R[1, 0], R[0, 0]))))
    elif R[0, 0] == 1.0 and not R[0, 1:].any() and not R[1:, 0].any():  # pure Rx
        steps.append(_rx_step(float(np.arctan2(R[2, 1], R[1, 1]))))
    elif np.all(np.isin(R, (-1.0, 0.0, 1.0))):  # signed permutation: exact ZXZ angles
        with warnings.catch_warnings():  # gimbal lock cases are exact here
            warnings.simplefilter("ignore", UserWarning)
            phi, theta, psi = Rotation.from_matrix(R).as_euler("ZXZ")
        steps.extend(s for s in (_rz_step(phi), _rx_step(theta), _rz_step(psi)) if s is not None)
    else:  # general rotation: one 3x3 step (Euler angles lose accuracy near gimbal lock)
        steps.append(("rot", R[:, 0] + 1j * R[:, 1], R[:, 2].copy()))
    return [s for s in steps if s is not None]


def _rx_step(angle: float) -> tuple | None:
    ca, sa = exact_cos_sin(angle)
    return None if (ca, sa) == (1.0, 0.0) else ("rx", ca, sa)


def compile_general(origins: np.ndarray, prismatic) -> tuple[tuple, tuple]:
    """Kernel steps of ``F_0 M_1 F_1 ... M_n F_n``, and each joint's last step index."""
    steps: list[tuple] = fixed_steps(origins[0])
    ends: list[int] = []
    for j, is_prismatic in enumerate(prismatic):
        steps.append(("tz_var", j, 0.0) if is_prismatic else ("rz", j))
        steps.extend(fixed_steps(origins[j + 1]))
        ends.append(len(steps) - 1)
    return tuple(steps), tuple(ends)


def dh_to_origins(a, alpha, d, theta, prismatic, convention: str) -> np.ndarray:
    """The fixed transforms ``F_0 .. F_n`` of a DH chain, shape ``(n + 1, 4, 4)``.

    Standard row: ``Rz(theta) Rz(q) Tz(d) Tx(a) Rx(alpha)`` (revolute) or
    ``Rz(theta) Tz(d) Tz(q) Tx(a) Rx(alpha)`` (prismatic); modified row:
    ``Rx(alpha) Tx(a) Rz(theta) Rz(q) Tz(d)`` or ``... Rz(theta) Tz(d) Tz(q)``.
    """
    n = len(a)
    pre, post = [], []
    for j in range(n):
        if convention == "standard":
            if prismatic[j]:
                pre.append(rot_z(theta[j]) @ translation(z=d[j]))
                post.append(translation(x=a[j]) @ rot_x(alpha[j]))
            else:
                pre.append(rot_z(theta[j]))
                post.append(translation(z=d[j]) @ translation(x=a[j]) @ rot_x(alpha[j]))
        else:
            head = rot_x(alpha[j]) @ translation(x=a[j]) @ rot_z(theta[j])
            if prismatic[j]:
                pre.append(head @ translation(z=d[j]))
                post.append(np.eye(4))
            else:
                pre.append(head)
                post.append(translation(z=d[j]))
    origins = [pre[0]] + [post[j] @ pre[j + 1] for j in range(n - 1)] + [post[-1]]
    return np.array(origins)


def lock_joints(origins: np.ndarray, prismatic, locked: dict[int, float]
                ) -> tuple[np.ndarray, list[int]]:
    """Fold locked joints into the fixed transforms.

    Returns:
        The new ``origins`` and the indices of the joints that stay free.
    """
    new = [origins[0]]
    free = []
    for j in range(len(prismatic)):
        if j in locked:
            new[-1] = new[-1] @ joint_motion(locked[j], prismatic[j]) @ origins[j + 1]
        else:
            free.append(j)
            new.append(origins[j + 1])
    return np.array(new), free


def fk_general_reference(origins: np.ndarray, prismatic, Q: np.ndarray) -> np.ndarray:
    """Straightforward FK of a general chain: 4x4 products, joint by joint."""
    n = Q.shape[0]
    T = np.broadcast_to(origins[0], (n, 4, 4)).copy()
    for j, is_prismatic in enumerate(prismatic):
        M = np.broadcast_to(np.eye(4), (n, 4, 4)).copy()
        if is_prismatic:
            M[:, 2, 3] = Q[:, j]
        else:
            c, s = np.cos(Q[:, j]), np.sin(Q[:, j])
            M[:, 0, 0], M[:, 0, 1], M[:, 1, 0], M[:, 1, 1] = c, -s, s, c
        T = T @ M @ origins[j + 1]
    return T
