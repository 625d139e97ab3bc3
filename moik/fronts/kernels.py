"""Compiled pose errors and their gradients, for the scalarised subproblems of a front.

The two objectives of the bi-objective IK problem (:class:`moik.problems.BiObjectiveIK`,
MO-m-PSO Eq. 15) are the position error ``f1 = ||p(q) - p_t||`` and an orientation
error ``f2`` of :mod:`moik.kinematics.rotation_metrics`. The subproblems of
:mod:`moik.fronts.scalarised` work with their squares ``s1 = f1^2`` and ``s2 = f2^2``
(smooth where ``f1``, ``f2`` vanish, unlike the norms). :func:`squared_errors_and_gradients`
gives both and their gradients by central differences with step ``h`` in one compiled
call (``2 dof + 1`` forward kinematics, the FK kernel of :mod:`moik.robots.fk_kernels` and the
metric kernel of :mod:`moik.kinematics.rotation_metrics`, inlined): a truncation error
``O(h^2)`` and a rounding error ``O(1e-16 / h)`` per entry.
"""

from __future__ import annotations

import math

import numpy as np

from moik._jit import jit
from moik.kinematics.rotation_metrics import (
    EOSMA_EULER,
    ZYX_EULER,
    ZYX_EULER_FREE_GAMMA,
    eosma_euler_angles,
    rotation_error,
    zyx_euler_angles,
)
from moik.robots.fk_kernels import chain_pose


@jit
def pose_errors(chain, target, q):
    """``(f1, f2)``: position error and orientation error (the metric of ``target``, a
    :class:`~moik.kinematics.target_spec.TargetSpec`) of ``q`` on ``chain`` (a
    :class:`~moik.robots.chain_model.ChainModel`)."""
    t = chain_pose(chain.origins, chain.joint_types, q)
    p_t = target.position
    dx, dy, dz = t[9] - p_t[0], t[10] - p_t[1], t[11] - p_t[2]
    rot = (t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8])
    return (math.sqrt(dx * dx + dy * dy + dz * dz),
            rotation_error(target.code, rot, target.rotation, target.angles))


@jit
def batch_pose_errors(chain, target, Q, out):
    """:func:`pose_errors` of every row of ``Q (n, dof)`` into ``out (n, 2)``."""
    for i in range(Q.shape[0]):
        out[i, 0], out[i, 1] = pose_errors(chain, target, Q[i])


@jit
def squared_errors_and_gradients(chain, target, q, h, value, grad):
    """``s1 = f1^2``, ``s2 = f2^2`` into ``value (2,)``, their gradients into ``grad (2, dof)``.

    Central differences with step ``h`` (radians or the robot's length unit per joint).
    ``q`` is not modified (a copy is perturbed).
    """
    x = q.copy()
    f1, f2 = pose_errors(chain, target, x)
    value[0], value[1] = f1 * f1, f2 * f2
    for j in range(x.size):
        x[j] = q[j] + h
        a1, a2 = pose_errors(chain, target, x)
        x[j] = q[j] - h
        b1, b2 = pose_errors(chain, target, x)
        x[j] = q[j]
        grad[0, j] = (a1 * a1 - b1 * b1) / (2.0 * h)
        grad[1, j] = (a2 * a2 - b2 * b2) / (2.0 * h)


@jit
def pose_equations(chain, target, q, m, scale, out):
    """The equations of ``f_m = 0`` at ``q`` into ``out (3,)`` (see
    :meth:`moik.fronts.scalarised.ErrorModel.residual`): ``m = 0`` the position
    (divided by ``scale``), ``m = 1`` the orientation."""
    t = chain_pose(chain.origins, chain.joint_types, q)
    p_t, code, R_t, angles_t = target.position, target.code, target.rotation, target.angles
    if m == 0:
        out[0], out[1], out[2] = ((t[9] - p_t[0]) / scale, (t[10] - p_t[1]) / scale,
                                  (t[11] - p_t[2]) / scale)
        return
    rot = (t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8])
    if code == EOSMA_EULER:
        a0, a1, a2 = eosma_euler_angles(rot)
        out[0], out[1], out[2] = a0 - angles_t[0], a1 - angles_t[1], a2 - angles_t[2]
    elif code in (ZYX_EULER, ZYX_EULER_FREE_GAMMA):
        a0, a1, a2 = zyx_euler_angles(rot)
        out[0], out[1] = a0 - angles_t[0], a1 - angles_t[1]
        out[2] = 0.0 if code == ZYX_EULER_FREE_GAMMA else a2 - angles_t[2]
    else:  # skew part of M = R_t^T R
        r00, r01, r02, r10, r11, r12, r20, r21, r22 = rot
        m01 = R_t[0, 0] * r01 + R_t[1, 0] * r11 + R_t[2, 0] * r21
        m10 = R_t[0, 1] * r00 + R_t[1, 1] * r10 + R_t[2, 1] * r20
        m02 = R_t[0, 0] * r02 + R_t[1, 0] * r12 + R_t[2, 0] * r22
        m20 = R_t[0, 2] * r00 + R_t[1, 2] * r10 + R_t[2, 2] * r20
        m12 = R_t[0, 1] * r02 + R_t[1, 1] * r12 + R_t[2, 1] * r22
        m21 = R_t[0, 2] * r01 + R_t[1, 2] * r11 + R_t[2, 2] * r21
        out[0], out[1], out[2] = 0.5 * (m21 - m12), 0.5 * (m02 - m20), 0.5 * (m10 - m01)


@jit
def pose_equations_and_jacobian(chain, target, q, equation, value, jac):
    """:func:`pose_equations` into ``value (3,)``, their central-difference Jacobian into
    ``jac (3, dof)``; ``equation = (m, scale, h)`` (``h``: the difference step)."""
    m, scale, h = equation
    x = q.copy()
    a, b = np.empty(3), np.empty(3)
    pose_equations(chain, target, x, m, scale, value)
    for j in range(x.size):
        x[j] = q[j] + h
        pose_equations(chain, target, x, m, scale, a)
        x[j] = q[j] - h
        pose_equations(chain, target, x, m, scale, b)
        x[j] = q[j]
        for r in range(3):
            jac[r, j] = (a[r] - b[r]) / (2.0 * h)
