"""Compiled kernels of the secondary criteria (:mod:`moik.kinematics.criteria`).

Each works on a batch of joint vectors ``Q (n, dof)`` and writes into ``out``:
the joint motion to the nearest 2 pi copy of each revolute joint, Yoshikawa's
manipulability from the geometric Jacobian, and the normalised margin to the
joint limits; :func:`nearest_copies_into` moves a configuration to its 2 pi copy next
to a reference (:func:`~moik.kinematics.criteria.nearest_copies`), :func:`wrapped_distance`
(the one 2 pi joint distance) is shared with the solver's start loop and the
experiments' branches.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit
from moik.kinematics.jacobian import pose_jacobian_into
from moik.robots.transforms import PRISMATIC


@jit
def nearest_copy(q, q_ref, lo, hi):
    """The value ``q + 2 pi k`` within ``[lo, hi]`` nearest to ``q_ref`` (``q`` when no copy
    is within them).

    ``|q + 2 pi k - q_ref|`` is convex in ``k``, so the best ``k`` within the limits is
    the unconstrained one (rounded) clipped to the turns that keep the copy within them,
    for any reference (one within the limits, as ``q_current`` is, or not). A copy that
    rounding puts a hair outside a limit is moved a turn back inside.
    """
    two_pi = 2.0 * np.pi
    k_lo, k_hi = np.ceil((lo - q) / two_pi), np.floor((hi - q) / two_pi)
    k = min(max(np.round((q_ref - q) / two_pi), k_lo), k_hi)
    for _ in range(2):
        c = q if k == 0.0 else q + k * two_pi
        if lo <= c <= hi:
            return c
        k += 1.0 if c < lo else -1.0
    return q


@jit
def wrapped_distance(a, b, types):
    """Joint-space distance over the joints of ``types``, revolute differences wrapped to
    ``[-pi, pi)`` (prismatic ones as they are): the one 2 pi distance."""
    s = 0.0
    for j in range(types.shape[0]):
        d = b[j] - a[j]
        if types[j] != PRISMATIC:
            d = (d + np.pi) % (2.0 * np.pi) - np.pi
        s += d * d
    return np.sqrt(s)


@jit
def distances_into(Q, q, types, out):
    """``out[i]``: :func:`wrapped_distance` from ``q`` to row ``i`` of ``Q``."""
    for i in range(Q.shape[0]):
        out[i] = wrapped_distance(q, Q[i], types)


@jit
def nearest_copies_into(Q, q_refs, lo, hi, types, out):
    """``out[i, j]``: :func:`nearest_copy` of every revolute ``Q[i, j]`` towards
    ``q_refs[i, j]`` (prismatic joints copied)."""
    for i in range(Q.shape[0]):
        for j in range(Q.shape[1]):
            v = Q[i, j]
            out[i, j] = v if types[j] == PRISMATIC else nearest_copy(v, q_refs[i, j], lo[j],
                                                                      hi[j])


@jit
def joint_motions(Q, q_ref, lo, hi, types, out):
    """``out[i] = ||Q_i' - q_ref||`` with ``Q_i'`` the 2 pi copies of :func:`nearest_copy`."""
    for i in range(Q.shape[0]):
        acc = 0.0
        for j in range(Q.shape[1]):
            v = Q[i, j]
            if types[j] != PRISMATIC:
                v = nearest_copy(v, q_ref[j], lo[j], hi[j])
            d = v - q_ref[j]
            acc += d * d
        out[i] = np.sqrt(acc)


@jit(inline=True)
def determinant(A):
    """Determinant of a small square matrix by Gaussian elimination with partial pivoting
    (``A`` is overwritten)."""
    n = A.shape[0]
    det = 1.0
    for c in range(n):
        p = c
        for r in range(c + 1, n):
            if abs(A[r, c]) > abs(A[p, c]):
                p = r
        if A[p, c] == 0.0:
            return 0.0
        if p != c:
            for k in range(n):
                A[c, k], A[p, k] = A[p, k], A[c, k]
            det = -det
        det *= A[c, c]
        for r in range(c + 1, n):
            f = A[r, c] / A[c, c]
            for k in range(c, n):
                A[r, k] -= f * A[c, k]
    return det


@jit
def manipulabilities(F, types, Q, rows, out):
    """Yoshikawa's ``sqrt(det(J J^T))`` of the first ``rows`` rows (3 or 6) of the Jacobian."""
    dof = types.size
    T, J = np.empty((4, 4)), np.empty((6, dof))
    k = min(rows, dof)
    A = np.empty((k, k))
    for i in range(Q.shape[0]):
        pose_jacobian_into(F, types, Q[i], T, J)
        for a in range(k):
            for b in range(k):
                s = 0.0
                if rows <= dof:  # J J^T (rows x rows)
                    for c in range(dof):
                        s += J[a, c] * J[b, c]
                else:  # J^T J (dof x dof)
                    for c in range(rows):
                        s += J[c, a] * J[c, b]
                A[a, b] = s
        out[i] = np.sqrt(max(determinant(A), 0.0))


@jit
def limit_margins(Q, lo, hi, out):
    """Smallest normalised distance of each row to a joint limit (0.5 when no joint has a range)."""
    for i in range(Q.shape[0]):
        m = 0.5
        for j in range(Q.shape[1]):
            span = hi[j] - lo[j]
            if span > 0.0:
                m = min(m, (Q[i, j] - lo[j]) / span, (hi[j] - Q[i, j]) / span)
        out[i] = m
