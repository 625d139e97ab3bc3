"""Point-to-point joint trajectories: the quintic polynomial with zero boundary
velocity and acceleration.

Used for the motion from a start configuration to a solved one (EOSMA
Figs. 19-20, Table 9). With ``s = t / T`` and ``dq = q1 - q0``::

    q(t)   = q0 + dq (10 s^3 - 15 s^4 + 6 s^5)
    qd(t)  = dq (30 s^2 - 60 s^3 + 30 s^4) / T
    qdd(t) = dq (60 s - 180 s^2 + 120 s^3) / T^2

so ``q(0) = q0``, ``q(T) = q1`` and the velocity and acceleration vanish at
both ends (the unique quintic with these six conditions per joint).
"""

from __future__ import annotations

import numpy as np

from moik._validate import integer
from moik.exceptions import NonFiniteError, ParameterError, ShapeError


def quintic_trajectory(
    q0, q1, duration: float, n: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Sample the rest-to-rest quintic from ``q0`` to ``q1``.

    Args:
        q0: Start joint vector ``(dof,)`` (rad / length unit).
        q1: End joint vector ``(dof,)``.
        duration: Motion time ``T`` in seconds (> 0).
        n: Number of samples including both ends (>= 2).

    Returns:
        ``(t, q, qd, qdd)``: times ``(n,)`` from 0 to ``duration``, positions,
        velocities (per second) and accelerations (per second squared), each
        ``(n, dof)``.

    Raises:
        ShapeError: ``q0``/``q1`` not 1-D of the same length.
        NonFiniteError: NaN or inf in ``q0``/``q1``.
        ParameterError: ``duration <= 0`` or ``n < 2``.
    """
    a = np.asarray(q0, dtype=float)
    b = np.asarray(q1, dtype=float)
    if a.ndim != 1 or b.shape != a.shape or a.size == 0:
        raise ShapeError(f"q0 and q1 must be 1-D of the same length, got {a.shape} and {b.shape}")
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
        raise NonFiniteError("q0 and q1 must be finite")
    duration = float(duration)
    if not (np.isfinite(duration) and duration > 0):
        raise ParameterError(f"duration must be a positive number of seconds, got {duration}")
    n = integer("n", n, minimum=2)  # samples, both ends included
    t = np.linspace(0.0, duration, n)
    s = (t / duration)[:, None]
    dq = (b - a)[None, :]
    q = a + dq * (s**3 * (10 - 15 * s + 6 * s**2))
    qd = dq * (30 * s**2 * (1 - s) ** 2) / duration
    qdd = dq * (60 * s * (1 - s) * (1 - 2 * s)) / duration**2
    return t, q, qd, qdd
