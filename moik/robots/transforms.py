"""General serial chains: fixed transforms between joints that move along local z.

Any serial chain of 1-DOF joints can be written as
``F_0 M_1(q_1) F_1 M_2(q_2) ... M_n(q_n) F_n`` where each ``F_j`` is a constant
rigid transform and ``M_j`` is ``Rz(q_j)`` (revolute) or ``Tz(q_j)``
(prismatic). URDF chains, DH chains and chains with locked joints all take this
form, which the compiled FK kernels of :mod:`moik.robots.fk_kernels` evaluate. This
module builds the constants (elementary transforms with exact values at
multiples of pi/2, DH rows to origins, locked joints, base and tool transforms
folded in), holds them as the kernels take them (:class:`KinematicChain`) and
has the plain-numpy reference FK of a general chain.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

REVOLUTE = 0
PRISMATIC = 1


@dataclass(frozen=True)
class KinematicChain:
    """The constants of ``F_0 M_1(q_1) F_1 ... M_n(q_n) F_n``, as the kernels take them.

    All arrays are C-contiguous and read-only (one array type for the kernels).

    Attributes:
        origins: ``(dof + 1, 4, 4)`` fixed transforms ``F_0 .. F_n``.
        joint_types: ``(dof,)`` int64, :data:`REVOLUTE` (``M = Rz(q)``) or
            :data:`PRISMATIC` (``M = Tz(q)``).
        link_frames: ``(dof, 4, 4)`` transforms ``P_j``: frame ``j`` (for plotting)
            is ``F_0 M_1 F_1 ... M_j P_j``; the DH frames for DH robots, ``P_j = F_j``
            for general chains.
    """

    origins: np.ndarray
    joint_types: np.ndarray
    link_frames: np.ndarray

    def __post_init__(self) -> None:
        for key, dtype in (("origins", np.float64), ("joint_types", np.int64),
                           ("link_frames", np.float64)):
            arr = np.array(getattr(self, key), dtype=dtype, order="C", copy=True)
            arr.setflags(write=False)
            object.__setattr__(self, key, arr)

    def __reduce__(self):
        # through the constructor, so unpickled arrays are read-only again (numpy
        # pickles them writeable, which the kernels would see as another type)
        return KinematicChain, (self.origins, self.joint_types, self.link_frames)

    @property
    def dof(self) -> int:
        """Number of joints."""
        return self.joint_types.size


def with_base_tool(origins: np.ndarray, base: np.ndarray, tool: np.ndarray) -> np.ndarray:
    """``origins`` with ``F_0 <- base F_0`` and ``F_n <- F_n tool`` (a copy).

    An identity ``base`` or ``tool`` leaves its constant untouched (bit for bit).
    """
    out = np.array(origins, dtype=float)
    eye = np.eye(4)
    if not np.array_equal(base, eye):
        out[0] = base @ out[0]
    if not np.array_equal(tool, eye):
        out[-1] = out[-1] @ tool
    return out


def exact_cos_sin(angle: float) -> tuple[float, float]:
    """cos/sin of ``angle`` with exact values at multiples of pi/2."""
    quarter = angle / (np.pi / 2)
    k = round(quarter)
    if abs(quarter - k) < 1e-12:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return float(np.cos(angle)), float(np.sin(angle))


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


def _dh_pre_post(a, alpha, d, theta, prismatic, convention: str
                 ) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """Each DH row as ``pre_j M_j(q_j) post_j``."""
    pre, post = [], []
    for j in range(len(a)):
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
    return pre, post


def dh_to_origins(a, alpha, d, theta, prismatic, convention: str) -> np.ndarray:
    """The fixed transforms ``F_0 .. F_n`` of a DH chain, shape ``(n + 1, 4, 4)``.

    Standard row: ``Rz(theta) Rz(q) Tz(d) Tx(a) Rx(alpha)`` (revolute) or
    ``Rz(theta) Tz(d) Tz(q) Tx(a) Rx(alpha)`` (prismatic); modified row:
    ``Rx(alpha) Tx(a) Rz(theta) Rz(q) Tz(d)`` or ``... Rz(theta) Tz(d) Tz(q)``.
    """
    pre, post = _dh_pre_post(a, alpha, d, theta, prismatic, convention)
    n = len(a)
    origins = [pre[0]] + [post[j] @ pre[j + 1] for j in range(n - 1)] + [post[-1]]
    return np.array(origins)


def dh_link_frames(a, alpha, d, theta, prismatic, convention: str) -> np.ndarray:
    """``P_j`` with DH frame ``j`` = ``F_0 M_1 F_1 ... M_j P_j``, shape ``(n, 4, 4)``.

    The DH frame of joint ``j`` is the product of the first ``j`` DH matrices:
    the chain up to joint ``j``'s motion, then the rest of that row (``post_j``),
    without the start of the next row that ``F_j`` also holds.
    """
    return np.array(_dh_pre_post(a, alpha, d, theta, prismatic, convention)[1])


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
    """Straightforward FK of a general chain: 4x4 products, joint by joint (test oracle)."""
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
