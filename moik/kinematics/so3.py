"""SO(3) maths on arrays: exp and log maps, the left Jacobian and its inverse, the pose residual.

Pure functions on numpy arrays, batched over leading axes, without validation
(callers pass float arrays of the documented shapes). Notation: a rotation
vector ``phi`` (unit axis times angle, rad), ``t = |phi|`` and ``[phi]`` its
skew matrix (``[phi] v = phi x v``). References: J. Sola, J. Deray,
D. Atchuthan, "A micro Lie theory for state estimation in robotics",
arXiv:1812.01537 (2018), the SO(3) example (exp, log, left and right
Jacobians and their inverses, closed forms); T. D. Barfoot, *State Estimation
for Robotics* (2017), Section 7.1 (the same identities, left-Jacobian
convention).

* exp (Rodrigues): ``exp(phi) = I + (sin t / t) [phi] + ((1 - cos t) / t^2) [phi]^2``.
* log: ``theta = atan2(|v|, trace(R) - 1)`` with ``v = (R32 - R23, R13 - R31,
  R21 - R12)`` (``|v| = 2 sin theta``, ``trace - 1 = 2 cos theta``: accurate at
  small angles, unlike ``arccos``), ``log(R) = (theta / |v|) v`` (limit ``v / 2``).
  Within 1e-3 rad of ``pi`` ``v`` loses the axis; there the axis comes from
  the symmetric part ``(M + M^T) / 2 = cos t I + (1 - cos t) a a^T``.
* left Jacobian, ``d exp(phi) = [J_l(phi) d phi] exp(phi)``:
  ``J_l(phi) = I + ((1 - cos t) / t^2) [phi] + ((t - sin t) / t^3) [phi]^2``.
* its inverse, ``d log(R) = J_l^{-1}(log R) w`` for ``dR = [w] R`` (a
  world-frame angular velocity): ``J_l^{-1}(phi) = I - [phi] / 2 + c(t) [phi]^2``,
  ``c = 1/t^2 - (1 + cos t) / (2 t sin t)`` (``c -> 1/12`` as ``t -> 0``).
* pose residual of a point ``(p, R)`` towards a target ``(p_t, R_t)`` with a
  characteristic length ``L``: ``r = [(p - p_t) / L, log(R R_t^T)]`` (one
  length ``L`` of position error weighs like one radian), and its exact
  Jacobian from the geometric one ``[J_v; J_w]``: ``[J_v / L; J_l^{-1}(r_rot) J_w]``.

The solver's compiled Levenberg-Marquardt calls the compiled kernels
(:func:`log_into`, :func:`inverse_left_jacobian_times`) and the least-squares
polish the batched functions built on them (:mod:`moik.solver.lm`,
:mod:`moik.solver.polish`); the geodesic orientation error is :func:`rotation_angle`.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit, kernel_array

SMALL_ANGLE = 1e-6  # below it the Jacobians use their series limits
LOG_NEAR_PI = 1e-3  # within it of pi the log map reads the axis from the symmetric part
JACOBIAN_NEAR_PI = 1e-6  # within it of pi the inverse left Jacobian is the identity


def skew(phi: np.ndarray) -> np.ndarray:
    """``[phi]``: skew matrices ``(..., 3, 3)`` of vectors ``(..., 3)``, ``[phi] v = phi x v``."""
    phi = np.asarray(phi, dtype=float)
    out = np.zeros(phi.shape + (3,))
    out[..., 0, 1], out[..., 0, 2] = -phi[..., 2], phi[..., 1]
    out[..., 1, 0], out[..., 1, 2] = phi[..., 2], -phi[..., 0]
    out[..., 2, 0], out[..., 2, 1] = -phi[..., 1], phi[..., 0]
    return out


def exp(phi: np.ndarray) -> np.ndarray:
    """Rotation matrices ``(..., 3, 3)`` of rotation vectors ``(..., 3)`` (Rodrigues).

    Near ``t = 0`` the coefficients use their series ``1 - t^2/6`` and ``1/2 - t^2/24``.
    """
    phi = np.asarray(phi, dtype=float)
    t = np.linalg.norm(phi, axis=-1)
    small = t < SMALL_ANGLE
    ts = np.where(small, 1.0, t)
    a = np.where(small, 1.0 - t**2 / 6.0, np.sin(ts) / ts)
    b = np.where(small, 0.5 - t**2 / 24.0, (1.0 - np.cos(ts)) / ts**2)
    K = skew(phi)
    return np.eye(3) + a[..., None, None] * K + b[..., None, None] * (K @ K)


def _skew_part_and_angle(M: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(v, |v|, theta)`` of rotations ``M (n, 3, 3)`` (see the module docstring)."""
    v = np.stack([M[:, 2, 1] - M[:, 1, 2], M[:, 0, 2] - M[:, 2, 0], M[:, 1, 0] - M[:, 0, 1]],
                 axis=1)
    norm_v = np.sqrt(np.einsum("ij,ij->i", v, v))
    theta = np.arctan2(norm_v, np.einsum("ijj->i", M) - 1.0)
    return v, norm_v, theta


def rotation_angle(R: np.ndarray) -> np.ndarray:
    """Rotation angles ``|log(R)|`` in ``[0, pi]`` of ``R (..., 3, 3)``: shape ``(...)``.

    ``atan2(|v|, trace(R) - 1)``, accurate near 0 and near pi and never fed an
    argument pushed past +-1 by rounding (as ``arccos((trace - 1) / 2)`` is).
    """
    R = np.asarray(R, dtype=float)
    theta = _skew_part_and_angle(R.reshape(-1, 3, 3))[2]
    return theta.reshape(R.shape[:-2])[()]


def log(R: np.ndarray) -> np.ndarray:
    """Rotation vectors ``(..., 3)`` of rotation matrices ``R (..., 3, 3)`` (:func:`log_into`).

    ``(theta / |v|) v`` (limit ``v / 2`` at the identity); within ``LOG_NEAR_PI``
    of ``pi`` the axis comes from the symmetric part. At exactly ``pi`` the sign
    of the axis is arbitrary (both logs are the same rotation).
    """
    R = np.asarray(R, dtype=float)
    M = kernel_array(R.reshape(-1, 3, 3))
    out = np.empty((M.shape[0], 3))
    _logs(M, out)
    return out.reshape(R.shape[:-2] + (3,))


def left_jacobian(phi: np.ndarray) -> np.ndarray:
    """``J_l(phi)`` ``(..., 3, 3)`` of rotation vectors ``(..., 3)``.

    ``I + ((1 - cos t) / t^2) [phi] + ((t - sin t) / t^3) [phi]^2``; the series
    ``1/2 - t^2/24`` and ``1/6 - t^2/120`` below ``1e-4`` rad (where the closed
    forms cancel). Singular (not invertible) at ``t = 2 pi``.
    """
    phi = np.asarray(phi, dtype=float)
    t = np.linalg.norm(phi, axis=-1)
    small = t < 1e-4
    ts = np.where(small, 1.0, t)
    a = np.where(small, 0.5 - t**2 / 24.0, (1.0 - np.cos(ts)) / ts**2)
    b = np.where(small, 1.0 / 6.0 - t**2 / 120.0, (ts - np.sin(ts)) / ts**3)
    K = skew(phi)
    return np.eye(3) + a[..., None, None] * K + b[..., None, None] * (K @ K)


def inverse_left_jacobian(phi: np.ndarray) -> np.ndarray:
    """``J_l^{-1}(phi)`` ``(..., 3, 3)`` of rotation vectors ``(..., 3)``, closed form.

    ``I - [phi] / 2 + c(t) [phi]^2``, ``c = 1/t^2 - (1 + cos t) / (2 t sin t)``,
    written as ``(1 - c t^2) I - [phi] / 2 + c phi phi^T`` (``[phi]^2 = phi phi^T
    - t^2 I``); ``c = 1/12`` below ``SMALL_ANGLE``. Within ``JACOBIAN_NEAR_PI`` of
    ``pi``, where the log map it differentiates jumps (the axis flips sign) and
    ``(1 + cos t) / sin t`` is ``0 / 0`` in floating point, the identity is used.
    Computed by :func:`inverse_left_jacobian_times` applied to the identity.
    """
    phi = np.asarray(phi, dtype=float)
    flat = kernel_array(phi.reshape(-1, 3))
    out = np.empty((flat.shape[0], 3, 3))
    _inverse_left_jacobians(flat, out)
    return out.reshape(phi.shape + (3,))


def pose_residual(p: np.ndarray, R: np.ndarray | None, p_target: np.ndarray,
                  R_target: np.ndarray | None, length: float) -> np.ndarray:
    """Residuals ``[(p - p_t) / L, log(R R_t^T)]`` of a batch of points.

    Args:
        p: Positions ``(n, 3)``.
        R: Rotations ``(n, 3, 3)`` (ignored, may be ``None``, without ``R_target``).
        p_target: Target position ``(3,)``.
        R_target: Target rotation ``(3, 3)``, or ``None`` for a position target.
        length: Characteristic length ``L`` (the unit of ``p``).

    Returns:
        ``(n, 6)``, or ``(n, 3)`` (position rows only) without ``R_target``.
    """
    r_pos = (p - p_target) / length
    if R_target is None:
        return r_pos
    assert R is not None  # rotations come with a rotation target
    # R R_t^T written out by columns of R: (R R_t^T)_ab = sum_k R_ak (R_t)_bk
    M = (R[:, :, 0, None] * R_target[:, 0] + R[:, :, 1, None] * R_target[:, 1]
         + R[:, :, 2, None] * R_target[:, 2])
    return np.hstack([r_pos, log(M)])


def pose_residual_jacobian(J: np.ndarray, residual: np.ndarray, length: float) -> np.ndarray:
    """Exact Jacobians ``[J_v / L; J_l^{-1}(r_rot) J_w]`` of :func:`pose_residual`.

    Args:
        J: Geometric Jacobians ``(n, 6, dof)`` (linear rows, then angular, base frame).
        residual: The residuals ``(n, 3)`` or ``(n, 6)`` at the same points.
        length: Characteristic length ``L``.

    Returns:
        ``(n, 3, dof)`` or ``(n, 6, dof)``, matching ``residual``.
    """
    J_pos = J[:, :3] / length
    if residual.shape[1] == 3:
        return J_pos
    r_rot = np.ascontiguousarray(residual[:, 3:])
    return np.concatenate([J_pos, inverse_left_jacobian(r_rot) @ J[:, 3:]], axis=1)


# ---------------------------------------------------------------- compiled kernels
# One rotation at a time, callable from compiled code (the solver's Levenberg-Marquardt);
# the batched functions above loop over them.


@jit
def log_into(M, out):
    """``log(M)`` of one rotation matrix ``M (3, 3)`` into ``out (3,)``; returns the angle.

    Away from ``pi`` the skew-part formula of the module docstring; within
    ``LOG_NEAR_PI`` of ``pi`` the axis comes from the symmetric part
    (``M + M^T = 2 (1 - cos t) a a^T + 2 cos t I``: the largest diagonal entry
    gives the best-conditioned component) with its sign from the skew part.
    """
    v0, v1, v2 = M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1]
    nv = np.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
    theta = np.arctan2(nv, M[0, 0] + M[1, 1] + M[2, 2] - 1.0)
    if theta > np.pi - LOG_NEAR_PI:
        # (M + M^T) / 2 = cos t I + (1 - cos t) a a^T: a_i^2 from the diagonal (the largest
        # one best conditioned), the other components from the off-diagonal sums
        ct = np.cos(theta)
        w = 1.0 - ct
        d0, d1, d2 = M[0, 0], M[1, 1], M[2, 2]
        if d0 >= d1 and d0 >= d2:
            a0 = np.sqrt(max(0.0, (d0 - ct) / w))
            a1, a2 = (M[0, 1] + M[1, 0]) / (2.0 * w * a0), (M[0, 2] + M[2, 0]) / (2.0 * w * a0)
        elif d1 >= d2:
            a1 = np.sqrt(max(0.0, (d1 - ct) / w))
            a0, a2 = (M[0, 1] + M[1, 0]) / (2.0 * w * a1), (M[1, 2] + M[2, 1]) / (2.0 * w * a1)
        else:
            a2 = np.sqrt(max(0.0, (d2 - ct) / w))
            a0, a1 = (M[0, 2] + M[2, 0]) / (2.0 * w * a2), (M[1, 2] + M[2, 1]) / (2.0 * w * a2)
        na = np.sqrt(a0 * a0 + a1 * a1 + a2 * a2)
        if a0 * v0 + a1 * v1 + a2 * v2 < 0.0:
            na = -na
        out[0], out[1], out[2] = a0 / na * theta, a1 / na * theta, a2 / na * theta
        return theta
    scale = 0.5 if nv == 0.0 else theta / nv
    out[0], out[1], out[2] = v0 * scale, v1 * scale, v2 * scale
    return theta


@jit
def inverse_left_jacobian_times(phi, A, out):
    """``out (3, k) = J_l^{-1}(phi) A`` for ``A (3, k)`` (formula of the module docstring)."""
    t2 = phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2]
    t = np.sqrt(t2)
    if t < SMALL_ANGLE:
        c, h = 1.0 / 12.0, 0.5
    elif t > np.pi - JACOBIAN_NEAR_PI:
        c, h, t2 = 0.0, 0.0, 0.0
    else:
        c, h = 1.0 / t2 - (1.0 + np.cos(t)) / (2.0 * t * np.sin(t)), 0.5
    d = 1.0 - c * t2  # J_l^{-1} = d I - h [phi] + c phi phi^T
    p0, p1, p2 = phi[0], phi[1], phi[2]
    m00, m01, m02 = d + c * p0 * p0, c * p0 * p1 + h * p2, c * p0 * p2 - h * p1
    m10, m11, m12 = c * p1 * p0 - h * p2, d + c * p1 * p1, c * p1 * p2 + h * p0
    m20, m21, m22 = c * p2 * p0 + h * p1, c * p2 * p1 - h * p0, d + c * p2 * p2
    for j in range(A.shape[1]):
        a, b, e = A[0, j], A[1, j], A[2, j]
        out[0, j] = m00 * a + m01 * b + m02 * e
        out[1, j] = m10 * a + m11 * b + m12 * e
        out[2, j] = m20 * a + m21 * b + m22 * e


@jit
def _logs(M, out):
    for i in range(M.shape[0]):
        log_into(M[i], out[i])


@jit
def _inverse_left_jacobians(phi, out):
    eye = np.eye(3)
    for i in range(phi.shape[0]):
        inverse_left_jacobian_times(phi[i], eye, out[i])
