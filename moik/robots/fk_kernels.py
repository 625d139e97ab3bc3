"""Compiled forward kinematics of serial chains, and the plain-numpy DH reference.

Every chain moik knows (standard or modified DH rows with angle offsets and
prismatic joints, URDF chains, chains with locked joints) is evaluated in the
general form ``F_0 M_1(q_1) F_1 ... M_n(q_n) F_n`` (:mod:`moik.robots.transforms`),
given by a :class:`~moik.robots.transforms.KinematicChain`: the constants ``F_0 .. F_n``, the joint
types and, for per-joint frames, the transforms ``P_j`` from each joint's motion
frame to its displayed frame.

The kernels are numba functions (:mod:`moik._jit`). The pose is kept as twelve
scalars (rotation rows, then position) through the chain: a revolute joint
right-multiplies by ``Rz(q)``, which mixes only the first two rotation columns
(12 multiplications), a prismatic joint adds ``q`` times the z column, and each
constant ``F_j`` is one 3x4 affine product. Single-configuration kernels
(``*_into``: ``q (dof,)`` in, a preallocated ``out`` written) are meant to be
called from other compiled code; the batched ones loop over the rows of
``Q (n, dof)``, each row computed by the same code, so a row's result does not
depend on the batch it is in.

:func:`fk_reference` is the textbook per-joint DH matrix product in numpy, the
oracle that tests compare the kernels with. The joints' sines and cosines come from
:mod:`moik.robots.trig`.
"""

from __future__ import annotations

import math

import numpy as np

from moik._jit import jit
from moik.robots.transforms import PRISMATIC
from moik.robots.trig import TRIG_MAX, sin_cos, sin_cos_inline

BLOCK = 64  # rows per block of the batched kernels (their workspace stays in L1)
_BLOCK_MIN = 4  # fewer rows than this go through the single-row kernel


@jit
def pose_state(T):
    """The ``(4, 4)`` transform ``T`` as the twelve-scalar pose state (rotation rows, then
    position). Callers pass ``F[k]``: one compiled version for every ``k`` (an index
    argument would compile once more for the literal ``0``)."""
    return (T[0, 0], T[0, 1], T[0, 2], T[1, 0], T[1, 1], T[1, 2],
            T[2, 0], T[2, 1], T[2, 2], T[0, 3], T[1, 3], T[2, 3])


@jit
def rotate_z(t, s, c):
    """Pose state ``t`` right-multiplied by ``Rz(q)``, given ``s, c = sin q, cos q``."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22, px, py, pz = t
    return (c * r00 + s * r01, c * r01 - s * r00, r02,
            c * r10 + s * r11, c * r11 - s * r10, r12,
            c * r20 + s * r21, c * r21 - s * r20, r22, px, py, pz)


@jit
def translate_z(t, q):
    """Pose state ``t`` right-multiplied by ``Tz(q)``."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22, px, py, pz = t
    return (r00, r01, r02, r10, r11, r12, r20, r21, r22,
            px + q * r02, py + q * r12, pz + q * r22)


@jit
def compose(t, f):
    """Pose state ``t`` right-multiplied by the constant pose state ``f``."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22, px, py, pz = t
    f00, f01, f02, f10, f11, f12, f20, f21, f22, f03, f13, f23 = f
    return (r00 * f00 + r01 * f10 + r02 * f20, r00 * f01 + r01 * f11 + r02 * f21,
            r00 * f02 + r01 * f12 + r02 * f22,
            r10 * f00 + r11 * f10 + r12 * f20, r10 * f01 + r11 * f11 + r12 * f21,
            r10 * f02 + r11 * f12 + r12 * f22,
            r20 * f00 + r21 * f10 + r22 * f20, r20 * f01 + r21 * f11 + r22 * f21,
            r20 * f02 + r21 * f12 + r22 * f22,
            px + r00 * f03 + r01 * f13 + r02 * f23, py + r10 * f03 + r11 * f13 + r12 * f23,
            pz + r20 * f03 + r21 * f13 + r22 * f23)


@jit
def move_joint(t, kind, q):
    """Pose state ``t`` right-multiplied by the joint motion ``Rz(q)`` or ``Tz(q)``."""
    if kind == PRISMATIC:
        return translate_z(t, q)
    s, c = sin_cos(q)
    return rotate_z(t, s, c)


@jit
def chain_pose(F, types, q):
    """End-effector pose of one joint vector ``q (dof,)`` as the twelve-scalar state.

    Returns ``(r00, r01, r02, r10, r11, r12, r20, r21, r22, px, py, pz)``.
    """
    t = pose_state(F[0])
    for j in range(types.size):
        t = compose(move_joint(t, types[j], q[j]), pose_state(F[j + 1]))
    return t


@jit
def store_pose(t, out):
    """Write the pose state ``t`` into the 4x4 ``out``."""
    out[0, 0], out[0, 1], out[0, 2], out[0, 3] = t[0], t[1], t[2], t[9]
    out[1, 0], out[1, 1], out[1, 2], out[1, 3] = t[3], t[4], t[5], t[10]
    out[2, 0], out[2, 1], out[2, 2], out[2, 3] = t[6], t[7], t[8], t[11]
    out[3, 0], out[3, 1], out[3, 2], out[3, 3] = 0.0, 0.0, 0.0, 1.0


@jit
def fk_pose_into(F, types, q, out):
    """End-effector pose of ``q (dof,)`` written into ``out (4, 4)``."""
    store_pose(chain_pose(F, types, q), out)


@jit
def fk_position_into(F, types, q, out):
    """End-effector position of ``q (dof,)`` written into ``out (3,)``."""
    t = chain_pose(F, types, q)
    out[0], out[1], out[2] = t[9], t[10], t[11]


# ---------------------------------------------------------------- batched, by blocks of rows
@jit
def block_state(W, b):
    """Pose state of row ``b`` of a block workspace."""
    return (W[0, b], W[1, b], W[2, b], W[3, b], W[4, b], W[5, b],
            W[6, b], W[7, b], W[8, b], W[9, b], W[10, b], W[11, b])


@jit
def block_position(W, b):
    """Position ``(x, y, z)`` of row ``b`` of a block workspace."""
    return W[9, b], W[10, b], W[11, b]


@jit
def block_rotation(W, b):
    """Rotation of row ``b`` of a block workspace, row-major 9-tuple."""
    return (W[0, b], W[1, b], W[2, b], W[3, b], W[4, b], W[5, b], W[6, b], W[7, b], W[8, b])


@jit
def _set_block_state(W, b, t):
    W[0, b], W[1, b], W[2, b], W[3, b], W[4, b], W[5, b] = t[0], t[1], t[2], t[3], t[4], t[5]
    W[6, b], W[7, b], W[8, b], W[9, b], W[10, b], W[11, b] = t[6], t[7], t[8], t[9], t[10], t[11]


@jit
def block_workspace(dof):
    """Scratch of :func:`chain_block`: the states, then joint values, sines, cosines."""
    return np.empty((12 + 3 * dof, BLOCK))


@jit
def chain_block(F, types, Q, start, m, W):
    """Poses of rows ``start .. start + m - 1`` of ``Q`` (``m <= BLOCK``) into ``W[:12, :m]``.

    Joint by joint over the whole block (structure of arrays), so the compiler
    vectorises the trigonometry and the products across rows. Each row gets the
    same operations as :func:`chain_pose`, so the result is bit for bit that of
    the single-row kernels (which also serve blocks of fewer than four rows); a
    row with a joint value beyond ``TRIG_MAX`` is recomputed by :func:`chain_pose`
    (libm trigonometry).
    """
    if m < _BLOCK_MIN:  # the block's loop set-up costs more than it saves
        for b in range(m):
            _set_block_state(W, b, chain_pose(F, types, Q[start + b]))
        return
    dof = types.size
    QT, SN, CS = W[12:12 + dof], W[12 + dof:12 + 2 * dof], W[12 + 2 * dof:12 + 3 * dof]
    for b in range(m):
        for j in range(dof):
            QT[j, b] = Q[start + b, j]
    far = 0
    for j in range(dof):
        if types[j] != PRISMATIC:
            qj, sj, cj = QT[j], SN[j], CS[j]
            for b in range(m):
                sj[b], cj[b] = sin_cos_inline(qj[b])
                far += abs(qj[b]) > TRIG_MAX
    f = pose_state(F[0])
    for b in range(m):
        _set_block_state(W, b, f)
    for j in range(dof):
        f = pose_state(F[j + 1])
        if types[j] == PRISMATIC:
            for b in range(m):
                _set_block_state(W, b, compose(translate_z(block_state(W, b), QT[j, b]), f))
        else:
            for b in range(m):
                _set_block_state(W, b, compose(rotate_z(block_state(W, b), SN[j, b], CS[j, b]),
                                               f))
    if far:
        for b in range(m):
            for j in range(dof):
                if types[j] != PRISMATIC and abs(QT[j, b]) > TRIG_MAX:
                    _set_block_state(W, b, chain_pose(F, types, Q[start + b]))
                    break


@jit
def fk_poses(F, types, Q, out):
    """End-effector poses of ``Q (n, dof)`` written into ``out (n, 4, 4)``."""
    W = block_workspace(types.size)
    for start in range(0, Q.shape[0], BLOCK):
        m = min(BLOCK, Q.shape[0] - start)
        chain_block(F, types, Q, start, m, W)
        for b in range(m):
            store_pose(block_state(W, b), out[start + b])


@jit
def fk_positions(F, types, Q, out):
    """End-effector positions of ``Q (n, dof)`` written into ``out (n, 3)``."""
    W = block_workspace(types.size)
    for start in range(0, Q.shape[0], BLOCK):
        m = min(BLOCK, Q.shape[0] - start)
        chain_block(F, types, Q, start, m, W)
        for b in range(m):
            out[start + b, 0], out[start + b, 1], out[start + b, 2] = W[9, b], W[10, b], W[11, b]


@jit
def fk_rotations_positions(F, types, Q, R, p):
    """End-effector rotations ``R (n, 3, 3)`` and positions ``p (n, 3)`` of ``Q``, in place."""
    W = block_workspace(types.size)
    for start in range(0, Q.shape[0], BLOCK):
        m = min(BLOCK, Q.shape[0] - start)
        chain_block(F, types, Q, start, m, W)
        for b in range(m):
            i = start + b
            R[i, 0, 0], R[i, 0, 1], R[i, 0, 2] = W[0, b], W[1, b], W[2, b]
            R[i, 1, 0], R[i, 1, 1], R[i, 1, 2] = W[3, b], W[4, b], W[5, b]
            R[i, 2, 0], R[i, 2, 1], R[i, 2, 2] = W[6, b], W[7, b], W[8, b]
            p[i, 0], p[i, 1], p[i, 2] = W[9, b], W[10, b], W[11, b]


@jit
def all_finite(x):
    """Whether every entry of the 1-D float array ``x`` is finite."""
    for v in x:  # noqa: SIM110 (a compiled early-exit loop)
        if not math.isfinite(v):
            return False
    return True


@jit
def joint_screen(Q, lower, upper, revolute, full_turn):
    """One pass over a joint batch ``Q (n, dof)``: 1 if an entry is NaN or inf; else 2 if
    its revolute values could look like degrees (one more than ``full_turn`` beyond its
    limits, or every one a whole number and some beyond ``full_turn`` in magnitude: the
    conditions of :func:`moik.robots.checks.warn_if_joint_degrees`, which words the
    warning); else 0."""
    n, dof = Q.shape
    far, whole, big, any_rev = False, True, False, False
    for i in range(n):
        for j in range(dof):
            v = Q[i, j]
            if not math.isfinite(v):
                return 1
            if revolute[j]:
                any_rev = True
                if upper[j] + full_turn < v or lower[j] - full_turn > v:
                    far = True
                if v != math.floor(v):
                    whole = False
                if abs(v) > full_turn:
                    big = True
    return 2 if any_rev and (far or (whole and big)) else 0


@jit
def fk_frames_into(F, P, types, q, out):
    """Base frame (identity) and every joint frame of ``q``, into ``out (dof + 1, 4, 4)``.

    ``P`` is ``KinematicChain.link_frames``.
    """
    out[0] = 0.0
    for k in range(4):
        out[0, k, k] = 1.0
    t = pose_state(F[0])
    for j in range(types.size):
        t = move_joint(t, types[j], q[j])
        store_pose(compose(t, pose_state(P[j])), out[j + 1])
        t = compose(t, pose_state(F[j + 1]))


@jit
def fk_frames(F, P, types, Q, out):
    """Frames of ``Q (n, dof)`` into ``out (n, dof + 1, 4, 4)`` (see :func:`fk_frames_into`)."""
    for i in range(Q.shape[0]):
        fk_frames_into(F, P, types, Q[i], out[i])


@jit(inline=True)
def copy_pose(T, out, k):
    """``out[k] = T`` for a ``(4, 4)`` pose, element by element: an array assignment would
    compile numba's shape-mismatch error message (string formatting, seconds of a first
    run) into every kernel that places shapes."""
    for r in range(4):
        for c in range(4):
            out[k, r, c] = T[r, c]


@jit
def world_frames(chain, q, frames, axes):
    """Frames ``(dof + 1, 4, 4)`` (frame 0 = the base) and joint axes ``(dof, 6)`` of ``q``
    (``chain``: a :class:`~moik.robots.chain_model.ChainModel`).

    ``axes[j] = (o_j, z_j)``: the point and direction of joint ``j + 1``'s axis.
    """
    F, P, types = chain.origins, chain.link_frames, chain.joint_types
    copy_pose(chain.base, frames, 0)
    t = pose_state(F[0])
    for j in range(types.size):
        axes[j, 0], axes[j, 1], axes[j, 2] = t[9], t[10], t[11]
        axes[j, 3], axes[j, 4], axes[j, 5] = t[2], t[5], t[8]
        t = move_joint(t, types[j], q[j])
        store_pose(compose(t, pose_state(P[j])), frames[j + 1])
        t = compose(t, pose_state(F[j + 1]))


def fk_reference(a, alpha, d, theta, prismatic, convention: str, Q: np.ndarray) -> np.ndarray:
    """Straightforward FK: one 4x4 matrix per joint, multiplied in turn (test oracle).

    Independent of the kernels above (plain ``cos``/``sin`` of all joints at
    once, the textbook DH matrices, then ``dof`` batched 4x4 products); the
    baseline for tests and ``benchmarks/fk.py``. ``Q`` is ``(n, dof)``.
    """
    n, dof = Q.shape
    prismatic = np.asarray(prismatic, dtype=bool)
    th = np.where(prismatic, theta, Q + theta)
    dd = np.where(prismatic, Q + d, d)
    ct, st = np.cos(th), np.sin(th)
    ca, sa = np.cos(alpha), np.sin(alpha)
    A = np.zeros((n, dof, 4, 4))
    if convention == "standard":  # Rz(theta) Tz(d) Tx(a) Rx(alpha)
        A[..., 0, 0], A[..., 0, 1], A[..., 0, 2], A[..., 0, 3] = ct, -st * ca, st * sa, a * ct
        A[..., 1, 0], A[..., 1, 1], A[..., 1, 2], A[..., 1, 3] = st, ct * ca, -ct * sa, a * st
        A[..., 2, 1], A[..., 2, 2], A[..., 2, 3] = sa, ca, dd
    else:  # Rx(alpha) Tx(a) Rz(theta) Tz(d)
        A[..., 0, 0], A[..., 0, 1], A[..., 0, 3] = ct, -st, a
        A[..., 1, 0], A[..., 1, 1], A[..., 1, 2], A[..., 1, 3] = st * ca, ct * ca, -sa, -sa * dd
        A[..., 2, 0], A[..., 2, 1], A[..., 2, 2], A[..., 2, 3] = st * sa, ct * sa, ca, ca * dd
    A[..., 3, 3] = 1.0
    T = A[:, 0]
    for j in range(1, dof):
        T = T @ A[:, j]
    return T
