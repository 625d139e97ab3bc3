"""Compiled pose errors and their gradients, for the scalarised subproblems of a front.

The two objectives of the bi-objective IK problem (:class:`moik.problems.BiObjectiveIK`,
MO-m-PSO Eq. 15) are the position error ``f1 = ||p(q) - p_t||`` and an orientation
error ``f2`` of :mod:`moik.kinematics.rotation_metrics`. The subproblems of
:mod:`moik.fronts.scalarised` work with their squares ``s1 = f1^2`` and ``s2 = f2^2``
(smooth where ``f1``, ``f2`` vanish, unlike the norms). :func:`squared_errors_and_gradients`
gives both and their gradients by central differences with step ``h`` in one compiled
call (``2 dof + 1`` forward kinematics, the FK kernel of :mod:`moik.robots.dh` and the
metric kernel of :mod:`moik.kinematics.rotation_metrics`, inlined): a truncation error
``O(h^2)`` and a rounding error ``O(1e-16 / h)`` per entry.
"""

from __future__ import annotations

import math

from moik._jit import jit
from moik.kinematics.rotation_metrics import rotation_error
from moik.robots.dh import chain_pose


@jit(inline=True)
def pose_errors(F, types, q, p_t, code, R_t, angles_t):
    """``(f1, f2)``: position error and orientation error (metric ``code``) of ``q``."""
    t = chain_pose(F, types, q)
    dx, dy, dz = t[9] - p_t[0], t[10] - p_t[1], t[11] - p_t[2]
    rot = (t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8])
    return math.sqrt(dx * dx + dy * dy + dz * dz), rotation_error(code, rot, R_t, angles_t)


@jit
def batch_pose_errors(F, types, Q, p_t, code, R_t, angles_t, out):
    """:func:`pose_errors` of every row of ``Q (n, dof)`` into ``out (n, 2)``."""
    for i in range(Q.shape[0]):
        out[i, 0], out[i, 1] = pose_errors(F, types, Q[i], p_t, code, R_t, angles_t)


@jit
def squared_errors_and_gradients(F, types, q, p_t, code, R_t, angles_t, h, value, grad):
    """``s1 = f1^2``, ``s2 = f2^2`` into ``value (2,)``, their gradients into ``grad (2, dof)``.

    Central differences with step ``h`` (radians or the robot's length unit per joint).
    ``q`` is not modified (a copy is perturbed).
    """
    x = q.copy()
    f1, f2 = pose_errors(F, types, x, p_t, code, R_t, angles_t)
    value[0], value[1] = f1 * f1, f2 * f2
    for j in range(x.size):
        x[j] = q[j] + h
        a1, a2 = pose_errors(F, types, x, p_t, code, R_t, angles_t)
        x[j] = q[j] - h
        b1, b2 = pose_errors(F, types, x, p_t, code, R_t, angles_t)
        x[j] = q[j]
        grad[0, j] = (a1 * a1 - b1 * b1) / (2.0 * h)
        grad[1, j] = (a2 * a2 - b2 * b2) / (2.0 * h)
