"""Batched Denavit-Hartenberg forward kinematics: the fast kernel and a reference.

A DH joint transform is a product of elementary motions: standard DH
``Rz(theta) Tz(d) Tx(a) Rx(alpha)``, modified (Craig) DH
``Rx(alpha) Tx(a) Rz(theta) Tz(d)``. :func:`compile_steps` turns DH rows into
that sequence once, dropping identities (``a = 0``, ``alpha = 0``, fixed
``d = 0``) and using exact 0/+-1 cosines for twists that are multiples of pi/2.
:func:`run_steps` applies the sequence to a whole batch at once.

Why it is fast: numpy costs ~0.3-0.9 us per call on a (3, 100) array, so the
number of array operations decides the cost at the batch sizes metaheuristics
use. Right-multiplying the accumulated pose by ``Rz(theta)`` changes only its
x and y rotation columns and does so like a complex product,
``(x + i y) * exp(-i theta)``; the kernel keeps those two columns as one
complex ``(3, n)`` array, so a joint rotation is a single operation. The
``exp(-i theta)`` factors come from one ``tan`` of the half angles,
``(1 - i t) / (1 + i t)`` with ``t = tan(theta / 2)`` (numpy's float64 ``tan``
is SIMD-vectorised, its ``sin``/``cos``/complex ``exp`` are not; the identity
is exact to ~2 ulp). Positions from ``Tx`` accumulate in a complex array
(only its real part is used) so no strided real-part views are read.
"""

from __future__ import annotations

import numpy as np


def exact_cos_sin(angle: float) -> tuple[float, float]:
    """cos/sin of ``angle`` with exact values at multiples of pi/2."""
    quarter = angle / (np.pi / 2)
    k = round(quarter)
    if abs(quarter - k) < 1e-12:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return float(np.cos(angle)), float(np.sin(angle))


def compile_steps(a, alpha, d, theta, prismatic, convention: str) -> tuple[tuple, tuple]:
    """Elementary motions of a DH chain, identities removed.

    Returns:
        ``(steps, joint_ends)``: the motions, each a tuple ``(kind, ...)``, and
        the index of the last motion of each joint (every joint has one).
    """
    steps: list[tuple] = []
    ends: list[int] = []
    for j in range(len(a)):
        if prismatic[j]:
            rz = ("rz_fixed", np.exp(-1j * theta[j])) if theta[j] != 0.0 else None
            tz = ("tz_var", j, d[j])
        else:
            rz = ("rz", j)
            tz = ("tz", d[j]) if d[j] != 0.0 else None
        tx = ("tx", a[j]) if a[j] != 0.0 else None
        ca, sa = exact_cos_sin(alpha[j])
        rx = None if (ca, sa) == (1.0, 0.0) else ("rx", ca, sa)
        order = [rz, tz, tx, rx] if convention == "standard" else [rx, tx, rz, tz]
        steps.extend(s for s in order if s is not None)
        ends.append(len(steps) - 1)
    return tuple(steps), tuple(ends)


def joint_rotations(Q: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """``exp(-i (q_j + theta_j))`` for every joint, shape ``(dof, n)``."""
    t = np.tan(0.5 * Q.T + (0.5 * theta)[:, None])
    it = 1j * t
    return (1.0 - it) / (1.0 + it)


def run_steps(steps: tuple, Q: np.ndarray, theta: np.ndarray, joint_ends: tuple = (),
              axes: list | None = None):
    """Apply compiled motions to a batch of joint vectors ``Q (n, dof)``.

    Args:
        steps: From :func:`compile_steps`.
        Q: Joint values, 2-D.
        theta: Joint angle offsets, added to revolute joint values.
        joint_ends: If given, the state after each of these step indices is
            recorded (for per-joint frames).
        axes: If a list is given, ``(z, origin)`` of each joint's motion axis in
            the base frame is appended to it, in joint order (for Jacobians).

    Returns:
        ``(xy, z, p, frames)``: x + i*y rotation columns (complex ``(3, n)``),
        z column ``(3, n)``, position ``(3, n)`` and the recorded states.
    """
    n = Q.shape[0]
    rot = joint_rotations(Q, theta)
    xy = np.empty((3, n), dtype=complex)
    xy[:] = ((1.0,), (1.0j,), (0.0,))
    z = np.empty((3, n))
    z[:] = ((0.0,), (0.0,), (1.0,))
    p_xy = np.zeros((3, n), dtype=complex)  # Tx contributions (real part)
    p_z = np.zeros((3, n))  # Tz contributions
    tmp_c = np.empty((3, n), dtype=complex)
    tmp_r = np.empty((3, n))
    frames = []
    for k, step in enumerate(steps):
        kind = step[0]
        if kind == "rz":
            xy *= rot[step[1]]
            if axes is not None:
                axes.append((z.copy(), p_xy.real + p_z))
        elif kind == "tx":  # p += a * Re(xy); a complex factor -i*y gives p += y * Im(xy)
            np.multiply(xy, step[1], out=tmp_c)
            p_xy += tmp_c
        elif kind == "tz":
            np.multiply(z, step[1], out=tmp_r)
            p_z += tmp_r
        elif kind == "rx":
            _, ca, sa = step
            if ca == 0.0:  # alpha = +-pi/2: y' = sa z, z' = -sa y
                y = xy.imag.copy()
                if sa > 0:
                    xy.imag = z
                    np.negative(y, out=y)
                else:
                    np.negative(z, out=xy.imag)
                z = y
            elif sa == 0.0:  # alpha = pi
                np.negative(xy.imag, out=xy.imag)
                np.negative(z, out=z)
            else:
                y = xy.imag.copy()
                xy.imag = ca * y + sa * z
                z = ca * z - sa * y
        elif kind == "tz_var":
            if axes is not None:
                axes.append((z.copy(), p_xy.real + p_z))
            p_z += (Q[:, step[1]] + step[2]) * z
        elif kind == "rz_fixed":
            xy *= step[1]
        else:  # rot: right-multiply by a constant 3x3 rotation (columns c_xy, c_z)
            _, c_xy, c_z = step
            x, y = xy.real.copy(), xy.imag.copy()
            xy = x * c_xy[0] + y * c_xy[1] + z * c_xy[2]
            z = x * c_z[0] + y * c_z[1] + z * c_z[2]
        if k in joint_ends:
            frames.append((xy.copy(), z.copy(), p_xy.real + p_z))
    return xy, z, p_xy.real + p_z, frames


def assemble(xy: np.ndarray, z: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Homogeneous transforms ``(n, 4, 4)`` from kernel state."""
    n = p.shape[1]
    T = np.empty((n, 4, 4))
    T[:, :3, 0] = xy.real.T
    T[:, :3, 1] = xy.imag.T
    T[:, :3, 2] = z.T
    T[:, :3, 3] = p.T
    T[:, 3] = (0.0, 0.0, 0.0, 1.0)
    return T


def fk_reference(a, alpha, d, theta, prismatic, convention: str, Q: np.ndarray) -> np.ndarray:
    """Straightforward FK: one 4x4 matrix per joint, multiplied in turn.

    Independent of the kernel above (plain ``cos``/``sin`` of all joints at
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
