"""The orientation metrics compiled: one rotation's error, callable from compiled code.

:func:`rotation_error` computes, for one rotation (a 9-tuple row by row) and the
target, the metric selected by :func:`metric_code` (see
:mod:`moik.kinematics.orientation` for the metrics and their papers); the numpy
formulas there are the oracle it is tested against (to ~1e-15). The ZYX angles
follow scipy's ``Rotation.from_matrix(...).as_euler("ZYX")`` step by step
(Shepperd's quaternion, then Bernardes & Viollet's angles, gimbal-lock rule
included). :func:`rotation_errors` evaluates a batch.
"""

from __future__ import annotations

import math

import numpy as np

from moik._jit import jit, kernel_array
from moik.exceptions import UnknownNameError

EOSMA_EULER, ZYX_EULER, ZYX_EULER_FREE_GAMMA, FROBENIUS, GEODESIC = 0, 1, 2, 3, 4
_CODES = {"eosma-euler": EOSMA_EULER, "zyx-euler": ZYX_EULER,
          "zyx-euler-free-gamma": ZYX_EULER_FREE_GAMMA, "frobenius": FROBENIUS,
          "geodesic": GEODESIC}


def metric_code(name: str) -> int:
    """The integer that selects metric ``name`` in :func:`rotation_error`.

    Raises:
        UnknownNameError: listing the valid metric names.
    """
    if not isinstance(name, str) or name not in _CODES:
        raise UnknownNameError("orientation metric", name, list(_CODES))
    return _CODES[name]


def metric_target(name: str, R_t: np.ndarray) -> np.ndarray:
    """The target angles :func:`rotation_error` compares with, shape ``(3,)``.

    The paper's Euler angles of ``R_t`` for the Euler metrics, zeros for the matrix
    metrics. Computed by the same compiled code as the angles of each candidate,
    so a candidate with the target's rotation has an error of exactly 0 (numpy's
    vectorised ``arctan2`` may differ from it by an ulp).
    """
    out = np.zeros(3)
    _target_angles(metric_code(name), kernel_array(R_t), out)
    return out


@jit
def _atan_ratio_c(num, den):
    sign = math.copysign(1.0, den)
    return math.atan2(num * sign, den * sign)


@jit
def eosma_euler_angles(rot):
    """EOSMA Eq. 26 angles of the rotation ``rot`` (nine entries, row by row)."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = rot
    return (_atan_ratio_c(-r12, r22), _atan_ratio_c(r02, math.hypot(r00, r01)),
            _atan_ratio_c(-r01, r00))


@jit
def zyx_euler_angles(rot):
    """ZYX angles ``(alpha, beta, gamma)`` of ``rot`` as scipy's ``as_euler("ZYX")``."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = rot
    trace = r00 + r11 + r22
    if r00 >= r11 and r00 >= r22 and r00 >= trace:  # Shepperd: the largest of the four
        x, y, z, w = 1.0 - trace + 2.0 * r00, r10 + r01, r20 + r02, r21 - r12
    elif r11 >= r22 and r11 >= trace:
        x, y, z, w = r10 + r01, 1.0 - trace + 2.0 * r11, r21 + r12, r02 - r20
    elif r22 >= trace:
        x, y, z, w = r20 + r02, r21 + r12, 1.0 - trace + 2.0 * r22, r10 - r01
    else:
        x, y, z, w = r21 - r12, r02 - r20, r10 - r01, 1.0 + trace
    norm = math.sqrt(x * x + y * y + z * z + w * w)
    x, y, z, w = x / norm, y / norm, z / norm, w / norm
    a, b, c, d = w - y, x + z, y + w, z - x  # intrinsic ZYX = extrinsic xyz reversed
    half_sum = math.atan2(b, a)
    half_diff = math.atan2(d, c)
    beta = 2.0 * math.atan2(math.hypot(c, d), math.hypot(a, b))
    if abs(beta) <= 1e-7:  # gimbal lock: the third angle is set to zero
        alpha, gamma = 2.0 * half_sum, 0.0
    elif abs(beta - math.pi) <= 1e-7:
        alpha, gamma = 2.0 * half_diff, 0.0
    else:
        alpha, gamma = half_sum + half_diff, half_sum - half_diff
    return _wrap_pi(alpha), _wrap_pi(beta - math.pi / 2), _wrap_pi(gamma)


@jit
def _wrap_pi(angle):
    """``angle`` into ``[-pi, pi]`` by one turn at most (scipy keeps ``pi`` as ``pi``)."""
    if angle < -math.pi:
        return angle + 2 * math.pi
    if angle > math.pi:
        return angle - 2 * math.pi
    return angle


@jit
def geodesic_angle(rot, R_t):
    """Geodesic angle (rad) between ``rot`` (a 9-tuple row by row) and ``R_t (3, 3)``."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = rot
    # geodesic: M = R_t^T R, angle = atan2(|skew(M)|, trace(M) - 1)
    m00 = R_t[0, 0] * r00 + R_t[1, 0] * r10 + R_t[2, 0] * r20
    m11 = R_t[0, 1] * r01 + R_t[1, 1] * r11 + R_t[2, 1] * r21
    m22 = R_t[0, 2] * r02 + R_t[1, 2] * r12 + R_t[2, 2] * r22
    m01 = R_t[0, 0] * r01 + R_t[1, 0] * r11 + R_t[2, 0] * r21
    m10 = R_t[0, 1] * r00 + R_t[1, 1] * r10 + R_t[2, 1] * r20
    m02 = R_t[0, 0] * r02 + R_t[1, 0] * r12 + R_t[2, 0] * r22
    m20 = R_t[0, 2] * r00 + R_t[1, 2] * r10 + R_t[2, 2] * r20
    m12 = R_t[0, 1] * r02 + R_t[1, 1] * r12 + R_t[2, 1] * r22
    m21 = R_t[0, 2] * r01 + R_t[1, 2] * r11 + R_t[2, 2] * r21
    vx, vy, vz = m21 - m12, m02 - m20, m10 - m01
    return math.atan2(math.sqrt(vx * vx + vy * vy + vz * vz), m00 + m11 + m22 - 1.0)


@jit
def rotation_error(code, rot, R_t, angles_t):
    """Error of metric ``code`` (:func:`metric_code`) between ``rot`` and the target.

    Args:
        code: Metric code.
        rot: The rotation, a 9-tuple row by row.
        R_t: Target rotation ``(3, 3)`` (matrix metrics).
        angles_t: Target angles ``(3,)`` from :func:`metric_target` (Euler metrics).
    """
    if code == EOSMA_EULER:
        e0, e1, e2 = eosma_euler_angles(rot)
        d0, d1, d2 = e0 - angles_t[0], e1 - angles_t[1], e2 - angles_t[2]
        return math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    if code in (ZYX_EULER, ZYX_EULER_FREE_GAMMA):
        e0, e1, e2 = zyx_euler_angles(rot)
        d0, d1 = abs(e0 - angles_t[0]), abs(e1 - angles_t[1])
        if code == ZYX_EULER_FREE_GAMMA:
            return (d0 + d1) / 3.0
        return (d0 + d1 + abs(e2 - angles_t[2])) / 3.0
    if code == FROBENIUS:
        acc = 0.0
        for k in range(9):
            diff = rot[k] - R_t[k // 3, k % 3]
            acc += diff * diff
        return math.sqrt(acc)
    return geodesic_angle(rot, R_t)


@jit
def _target_angles(code, R_t, out):
    rot = (R_t[0, 0], R_t[0, 1], R_t[0, 2], R_t[1, 0], R_t[1, 1], R_t[1, 2],
           R_t[2, 0], R_t[2, 1], R_t[2, 2])
    if code == EOSMA_EULER:
        out[0], out[1], out[2] = eosma_euler_angles(rot)
    elif code in (ZYX_EULER, ZYX_EULER_FREE_GAMMA):
        out[0], out[1], out[2] = zyx_euler_angles(rot)


@jit
def rotation_errors(code, R, R_t, angles_t, out):
    """:func:`rotation_error` of every ``R[i] (3, 3)``, into ``out (n,)``."""
    for i in range(R.shape[0]):
        rot = (R[i, 0, 0], R[i, 0, 1], R[i, 0, 2], R[i, 1, 0], R[i, 1, 1], R[i, 1, 2],
               R[i, 2, 0], R[i, 2, 1], R[i, 2, 2])
        out[i] = rotation_error(code, rot, R_t, angles_t)
