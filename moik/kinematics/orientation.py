"""Orientation conventions of the papers and rotation-error metrics, vectorized.

Metrics (name -> error between rotation batches ``R (n, 3, 3)`` and one target
``R_t (3, 3)``):

* ``"eosma-euler"``: EOSMA paper Eq. 26 Euler angles
  ``(atan(-a_y/a_z), atan(a_x/sqrt(n_x^2+s_x^2)), atan(-s_x/n_x))`` (``atan``,
  not ``atan2``; ``0/0`` is taken as angle 0, ``x/0`` as +-pi/2) and the L2
  error of Eq. 30 in radians. Several rotations share the same angles (e.g.
  ``diag(1, -1, -1)`` and the identity both give (0, 0, 0)); use it to
  reproduce the paper, not for real tasks.
* ``"zyx-euler"``: MO-m-PSO paper Eqs. 11-13, ``R = Rz(alpha) Ry(beta) Rx(gamma)``
  via :mod:`scipy.spatial.transform`, and the mean absolute error of Eq. 14
  (radians). The paper's Eq. 11 prints ``r13`` where its own Eq. 16 example
  (beta = -30 deg from r31 = 0.5) needs ``r31``; we use the standard ``r31``.
  Angle differences are not wrapped, as in the paper.
* ``"zyx-euler-free-gamma"``: Eq. 14 without its gamma term (MO-m-PSO Section
  4.4, the circle path with gamma free).
* ``"frobenius"``: ``||R - R_t||_F``, MChOA paper Eq. 6.
* ``"geodesic"``: the rotation angle of ``R_t^T R`` in ``[0, pi]`` (radians),
  the default for users: no wrap-around, no gimbal lock, a true metric.

The numpy functions below are the formulas as written (and the oracle of the
tests); what runs when a population is evaluated is the compiled
:func:`~moik.kinematics.rotation_metrics.rotation_error`, which computes the same
numbers (to ~1e-15); :func:`orientation_error` calls it through
:func:`~moik.kinematics.rotation_metrics.rotation_errors`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from moik._jit import jit, kernel_array
from moik.exceptions import NonFiniteError, ShapeError, TargetError, UnknownNameError
from moik.kinematics.rotation_metrics import metric_code, metric_target, rotation_errors
from moik.kinematics.so3 import rotation_angle


def _rotation():
    """scipy's Rotation, imported on first use: ``import moik`` and a solve need not pay
    scipy.spatial's import (start-up time, not an import cycle)."""
    from scipy.spatial.transform import Rotation

    return Rotation


def _atan_ratio(num: np.ndarray, den: np.ndarray) -> np.ndarray:
    """``atan(num/den)`` as MATLAB's ``atan`` of the quotient, with ``0/0 -> 0``.

    Computed as ``atan2(num * s, den * s)`` with ``s = copysign(1, den)``: the
    same value in ``[-pi/2, pi/2]`` without a division (``x/0 -> +-pi/2``).
    """
    sign = np.copysign(1.0, den)
    return np.arctan2(num * sign, den * sign)


def eosma_euler(R: np.ndarray) -> np.ndarray:
    """EOSMA Eq. 26 Euler angles ``(alpha, beta, gamma)`` of ``R (..., 3, 3)``."""
    out = np.empty(R.shape[:-2] + (3,))
    out[..., 0] = _atan_ratio(-R[..., 1, 2], R[..., 2, 2])
    out[..., 1] = _atan_ratio(R[..., 0, 2], np.hypot(R[..., 0, 0], R[..., 0, 1]))
    out[..., 2] = _atan_ratio(-R[..., 0, 1], R[..., 0, 0])
    return out


def zyx_euler(R: np.ndarray) -> np.ndarray:
    """MO-m-PSO Eqs. 11-13: ``(alpha, beta, gamma)`` with ``R = Rz Ry Rx``."""
    R = np.asarray(R, dtype=float)
    flat = R.reshape(-1, 3, 3)
    angles = _rotation().from_matrix(flat).as_euler("ZYX")
    return angles.reshape(R.shape[:-2] + (3,))


def rotation_from_zyx(alpha: float, beta: float, gamma: float) -> np.ndarray:
    """``Rz(alpha) Ry(beta) Rx(gamma)`` (MO-m-PSO convention), radians."""
    return _rotation().from_euler("ZYX", [alpha, beta, gamma]).as_matrix()


def rotation_from_eosma_euler(alpha: float, beta: float, gamma: float) -> np.ndarray:
    """A rotation whose Eq. 26 angles are ``(alpha, beta, gamma)``.

    Eq. 26 is the intrinsic XYZ decomposition
    ``R = Rx(alpha) Ry(beta) Rz(gamma)`` restricted to ``atan`` ranges; for
    angles in ``(-pi/2, pi/2)`` this matrix reproduces them exactly.
    """
    return _rotation().from_euler("XYZ", [alpha, beta, gamma]).as_matrix()


def euler_error_l2(R: np.ndarray, angles_t: np.ndarray) -> np.ndarray:
    """EOSMA Eq. 30: L2 norm of Eq. 26 angle differences."""
    return np.sqrt(np.sum((eosma_euler(R) - angles_t) ** 2, axis=-1))


def euler_error_mae(R: np.ndarray, angles_t: np.ndarray) -> np.ndarray:
    """MO-m-PSO Eq. 14: mean absolute ZYX angle difference."""
    return np.mean(np.abs(zyx_euler(R) - angles_t), axis=-1)


def euler_error_mae_free_gamma(R: np.ndarray, angles_t: np.ndarray) -> np.ndarray:
    """MO-m-PSO Eq. 14 with gamma free (Section 4.4, the circle path:
    "alpha = beta = 0, gamma free"): the gamma term is dropped, the divisor
    stays 3 so values compare with Eq. 14."""
    d = np.abs(zyx_euler(R) - angles_t)
    return (d[..., 0] + d[..., 1]) / 3.0


def frobenius_error(R: np.ndarray, R_t: np.ndarray) -> np.ndarray:
    """MChOA Eq. 6: Frobenius norm ``||R - R_t||_F``."""
    return np.sqrt(np.sum((R - R_t) ** 2, axis=(-2, -1)))


def geodesic_error(R: np.ndarray, R_t: np.ndarray) -> np.ndarray:
    """Angle of ``M = R_t^T R`` in ``[0, pi]``, accurate near 0 and near pi.

    :func:`moik.kinematics.so3.rotation_angle`: ``atan2(|v|, trace(M) - 1)``
    with ``v`` the skew part of ``M`` (``|v| = 2 sin(angle)``, ``trace - 1 =
    2 cos(angle)``); unlike ``arccos((trace - 1) / 2)`` it loses no precision at
    small angles and never sees an argument pushed past +-1 by rounding.
    """
    return rotation_angle(np.swapaxes(R_t, -1, -2) @ R)


# metric name -> (target representation from a rotation matrix, error function)
_METRICS: dict[str, tuple[Callable, Callable]] = {
    "eosma-euler": (eosma_euler, euler_error_l2),
    "zyx-euler": (zyx_euler, euler_error_mae),
    "zyx-euler-free-gamma": (zyx_euler, euler_error_mae_free_gamma),
    "frobenius": (lambda R: R, frobenius_error),
    "geodesic": (lambda R: R, geodesic_error),
}


def available_metrics() -> list[str]:
    """Names accepted by :func:`orientation_metric`."""
    return list(_METRICS)


def orientation_metric(name: str) -> tuple[Callable, Callable]:
    """``(target_repr, error)`` of metric ``name``.

    ``target_repr(R_t)`` turns the target rotation into what ``error(R,
    target_repr(R_t))`` compares against (Euler angles for the paper metrics,
    the matrix for the others).

    Raises:
        UnknownNameError: listing the valid metric names.
    """
    try:
        return _METRICS[name]
    except (KeyError, TypeError):
        raise UnknownNameError("orientation metric", name, _METRICS) from None


def orientation_error(R, R_t, metric: str = "geodesic") -> np.ndarray:
    """Orientation error of rotation(s) ``R`` w.r.t. the target ``R_t``.

    Args:
        R: ``(3, 3)`` or ``(n, 3, 3)`` rotation matrices.
        R_t: ``(3, 3)`` target rotation.
        metric: One of :func:`available_metrics`.

    Returns:
        Scalar or ``(n,)`` errors (radians for the angle metrics).
    """
    code = metric_code(metric)
    R = check_rotation(R, "R", batch=True)
    R_t = check_rotation(R_t, "R_t")
    R3 = kernel_array(R.reshape(-1, 3, 3))
    out = np.empty(R3.shape[0])
    rotation_errors(code, R3, R_t, metric_target(metric, R_t), out)
    return out[0] if R.ndim == 2 else out


@jit
def _all_rotations(R, atol):
    """Whether every ``R[i]`` is orthonormal with det +1, by numpy.allclose's rule
    (``|R^T R - I| <= atol + 1e-5 I`` entrywise, ``|det - 1| <= atol + 1e-5``)."""
    for i in range(R.shape[0]):
        M = R[i]
        for a in range(3):
            for b in range(3):
                g = M[0, a] * M[0, b] + M[1, a] * M[1, b] + M[2, a] * M[2, b]
                eye = 1.0 if a == b else 0.0
                if not abs(g - eye) <= atol + 1e-5 * eye:
                    return False
        det = (M[0, 0] * (M[1, 1] * M[2, 2] - M[1, 2] * M[2, 1])
               - M[0, 1] * (M[1, 0] * M[2, 2] - M[1, 2] * M[2, 0])
               + M[0, 2] * (M[1, 0] * M[2, 1] - M[1, 1] * M[2, 0]))
        if not abs(det - 1.0) <= atol + 1e-5:
            return False
    return True


@jit
def pose_matrix_status(T, atol):
    """Checks of a ``(4, 4)`` pose in one pass: 0 valid, 1 a NaN/inf entry, 2 a last row
    other than ``[0, 0, 0, 1]`` (numpy.allclose's rule), 3 a rotation block that is not
    orthonormal with det +1 (the rule of :func:`check_rotation`)."""
    for a in range(4):
        for b in range(4):
            if not np.isfinite(T[a, b]):
                return 1
    for b in range(4):
        want = 1.0 if b == 3 else 0.0
        if not abs(T[3, b] - want) <= 1e-8 + 1e-5 * want:
            return 2
    for a in range(3):
        for b in range(3):
            g = T[0, a] * T[0, b] + T[1, a] * T[1, b] + T[2, a] * T[2, b]
            eye = 1.0 if a == b else 0.0
            if not abs(g - eye) <= atol + 1e-5 * eye:
                return 3
    det = (T[0, 0] * (T[1, 1] * T[2, 2] - T[1, 2] * T[2, 1])
           - T[0, 1] * (T[1, 0] * T[2, 2] - T[1, 2] * T[2, 0])
           + T[0, 2] * (T[1, 0] * T[2, 1] - T[1, 1] * T[2, 0]))
    return 0 if abs(det - 1.0) <= atol + 1e-5 else 3


ROTATION_ATOL = 1e-6  # orthonormality tolerance of a given rotation matrix


def check_rotation(
    R, name: str = "rotation", *, batch: bool = False, atol: float = ROTATION_ATOL
) -> np.ndarray:
    """Validate a rotation matrix (or batch): shape, finiteness, orthonormality.

    Raises:
        ShapeError: wrong shape.
        NonFiniteError: NaN/inf entries.
        moik.exceptions.TargetError: not orthonormal with det +1 (within ``atol``).
    """
    R = np.array(R, dtype=float, order="C")
    ok = R.shape[-2:] == (3, 3) and (R.ndim == 2 or (batch and R.ndim == 3))
    if not ok:
        want = "(3, 3) or (n, 3, 3)" if batch else "(3, 3)"
        raise ShapeError(f"{name} must have shape {want}, got {R.shape}")
    if not np.all(np.isfinite(R)):
        raise NonFiniteError(f"{name} must be finite, got NaN or inf")
    if not _all_rotations(R.reshape(-1, 3, 3), atol):
        raise TargetError(f"{name} must be a rotation matrix (orthonormal, det +1)")
    return R
