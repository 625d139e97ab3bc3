"""Validation of a robot description (the checks :class:`~moik.robots.chain.Robot` runs).

Arrays must hold real numbers (:func:`moik._validate.real_array`: no strings,
complex numbers or ragged lists) and be finite; joint types and names come one
per joint; base and tool are rigid transforms; lower limits do not exceed upper
ones. Angles are radians: joint limits beyond two turns, or DH twists and
offsets beyond one turn, look like degrees and raise a
:class:`~moik.exceptions.DegreesWarning` (a warning, not an error: the values
are legal, only suspicious); so do joint values (:func:`warn_if_joint_degrees`)
beyond a joint's limits by more than a turn, or all whole numbers some beyond a
turn (``fk([45, 0, 45, 0, 45, 0, 0])``). :func:`outside_limits` names the joints
outside their limits, for every message about limits.
"""

from __future__ import annotations

import warnings

import numpy as np

from moik._validate import finite_array, real_array
from moik.exceptions import (
    DegreesWarning,
    LimitsError,
    NonFiniteError,
    ParameterError,
    ShapeError,
)

JOINT_TYPES = ("revolute", "prismatic")
UNITS = ("m", "cm", "mm")
DH_KEYS = ("a", "alpha", "d", "theta")
FULL_TURN = 2 * np.pi + 1e-6  # beyond this a DH twist or offset looks like degrees
LIMIT_TURNS = 2  # joint limits beyond two turns look like degrees (multi-turn joints
# legitimately exceed one turn: the IRB-2600's axes 4 and 6 reach +-400 deg = 6.98 rad)
RIGID_ATOL = 1e-6  # orthonormality tolerance of a rigid transform (as for target rotations)
MAX_REACH = 1e100  # in the robot's unit: squares and sums of squares of lengths stay finite


def _vector(name: str, values, dof: int) -> np.ndarray:
    arr = real_array(name, values)
    if arr.shape != (dof,):
        raise ShapeError(f"{name} must have shape ({dof},), got {arr.shape}")
    return arr


def columns(robot: str, lower, upper, dh_rows: dict, origins) -> dict[str, np.ndarray]:
    """The validated, read-only arrays of a robot: limits, DH rows or origins.

    Args:
        robot: The robot's name, for messages.
        lower, upper: Joint limits.
        dh_rows: ``{key: values}`` for the DH keys given (``a``, ``alpha``, ``d``, ``theta``).
        origins: The ``(dof + 1, 4, 4)`` constants, or ``None`` for a DH robot.
    """
    lower = real_array("lower limits", lower)
    if lower.ndim != 1 or lower.size == 0:
        raise ShapeError(f"lower limits must be a non-empty 1-D array, got {lower.shape}")
    dof = lower.size
    if origins is None and len(dh_rows) != 4:
        raise ParameterError("a robot needs DH rows (a, alpha, d, theta) or origins")
    if origins is not None and dh_rows:
        raise ParameterError(f"give DH rows or origins, not both (got origins and "
                             f"{list(dh_rows)})")
    cols = {"lower": lower, "upper": _vector("upper", upper, dof)}
    for key, values in dh_rows.items():
        cols[key] = _vector(key, values, dof)
    if origins is not None:
        arr = real_array("origins", origins)
        if arr.shape != (dof + 1, 4, 4):
            raise ShapeError(f"origins must have shape ({dof + 1}, 4, 4), got {arr.shape}")
        cols["origins"] = arr
    for key, arr in cols.items():
        if not np.all(np.isfinite(arr)):
            raise NonFiniteError(f"robot {robot!r}: {key} must be finite, got {arr}")
        arr.setflags(write=False)
    bad = np.flatnonzero(cols["lower"] > cols["upper"])
    if bad.size:
        raise LimitsError(
            f"robot {robot!r}: lower limit > upper limit for joint(s) "
            f"{(bad + 1).tolist()} (lower={cols['lower'][bad]}, upper={cols['upper'][bad]})"
        )
    return cols


def joint_types(types, dof: int) -> tuple[str, ...]:
    """``types`` as ``dof`` entries of :data:`JOINT_TYPES` (default all revolute)."""
    if isinstance(types, str):
        raise ParameterError(f"joint_types must be a sequence of {dof} entries from "
                             f"{JOINT_TYPES}, got the string {types!r}")
    types = tuple(types) or ("revolute",) * dof
    if len(types) != dof or any(t not in JOINT_TYPES for t in types):
        raise ParameterError(f"joint_types must be {dof} entries from {JOINT_TYPES}, got {types}")
    return types


def joint_names(names, dof: int) -> tuple[str, ...]:
    """``names`` as ``dof`` distinct non-empty strings (default ``q1 .. qn``)."""
    if isinstance(names, str):
        raise ParameterError(f"joint_names must be a sequence of {dof} names, got the string "
                             f"{names!r}")
    names = tuple(names) or tuple(f"q{j + 1}" for j in range(dof))
    if (len(names) != dof or not all(isinstance(n, str) and n for n in names)
            or len(set(names)) != dof):
        raise ParameterError(f"joint_names must be {dof} distinct non-empty strings, got {names}")
    return names


def rigid_transform(name: str, T) -> np.ndarray:
    """``T`` as a read-only ``(4, 4)`` homogeneous rigid transform.

    Raises:
        ShapeError: not ``(4, 4)`` or not real numbers.
        NonFiniteError: NaN or infinite entries.
        ParameterError: last row not ``[0, 0, 0, 1]``, or rotation part not
            orthonormal with determinant +1 (within :data:`RIGID_ATOL`).
    """
    M = finite_array(name, T, shape=(4, 4))
    R = M[:3, :3]
    if not np.allclose(M[3], (0.0, 0.0, 0.0, 1.0), rtol=0, atol=RIGID_ATOL):
        raise ParameterError(f"{name} must be a 4x4 homogeneous transform with last row "
                             f"[0, 0, 0, 1], got {M[3].tolist()}")
    if not np.allclose(R.T @ R, np.eye(3), rtol=0, atol=RIGID_ATOL) or np.linalg.det(R) <= 0:
        raise ParameterError(f"{name} must be a rigid transform: its rotation part (upper-left "
                             f"3x3) must be orthonormal with determinant +1, got {R.tolist()}")
    M.setflags(write=False)
    return M


def finite_reach(robot: str, reach: float, unit: str) -> None:
    """Refuses a chain whose reach (the bound on the tool's distance) is not a usable number.

    Finite lengths can still add up to ``inf`` (``1e200`` m origins), and lengths
    whose squares overflow break every error and tolerance computed from them
    (a tolerance of ``1e-9 x inf`` accepts any answer).

    Raises:
        ParameterError: ``reach`` is NaN, infinite or above :data:`MAX_REACH`.
    """
    if not reach <= MAX_REACH:  # NaN fails the comparison too
        raise ParameterError(
            f"robot {robot!r}: its reach (the sum of its link offsets and prismatic strokes) is "
            f"{reach:.3g} {unit}; expected a finite length below {MAX_REACH:.0e} {unit} "
            "(larger lengths overflow double precision in FK errors and tolerances)")


def warn_if_degrees(robot: str, cols: dict[str, np.ndarray], prismatic: np.ndarray,
                    stacklevel: int) -> None:
    """A :class:`DegreesWarning` for angles that look like degrees (moik takes radians)."""
    suspects = []
    for key in ("alpha", "theta"):
        if key in cols and np.any(np.abs(cols[key]) > FULL_TURN):
            suspects.append(f"{key} reaches {np.max(np.abs(cols[key])):.6g} (beyond 2 pi)")
    for key in ("lower", "upper"):
        values = np.abs(cols[key][~prismatic])
        if values.size and np.max(values) > LIMIT_TURNS * FULL_TURN:
            suspects.append(f"revolute {key} limits reach {np.max(values):.6g} "
                            f"(beyond {LIMIT_TURNS} turns)")
    if suspects:
        warnings.warn(f"robot {robot!r}: {'; '.join(suspects)}: these look like degrees; moik "
                      "takes angles in radians (convert with numpy.radians)", DegreesWarning,
                      stacklevel=stacklevel + 1)


def _joint(names: tuple[str, ...], j: int) -> str:
    return f"joint {j + 1} ({names[j]})" if names else f"joint {j + 1}"


def outside_limits(names: tuple[str, ...], lower: np.ndarray, upper: np.ndarray,
                   q: np.ndarray) -> str:
    """The joints of one joint vector ``q`` outside ``[lower, upper]``, in words ("" if none).

    E.g. ``"joint 2 (j2) = 1.9 above its upper limit 1.5708"``.
    """
    parts = []
    for j in map(int, np.flatnonzero((q < lower) | (q > upper))):
        side, bound = ("below its lower", lower[j]) if q[j] < lower[j] else ("above its upper",
                                                                              upper[j])
        parts.append(f"{_joint(names, j)} = {q[j]:.6g} {side} limit {bound:.6g}")
    return "; ".join(parts)


def warn_if_joint_degrees(robot: str, names: tuple[str, ...], lower: np.ndarray,
                          upper: np.ndarray, prismatic: np.ndarray, Q: np.ndarray, what: str,
                          stacklevel: int, hint: str = "convert with numpy.radians") -> None:
    """A :class:`DegreesWarning` when revolute joint values ``Q`` (``(dof,)`` or ``(n, dof)``)
    look like degrees: one beyond its joint's limits by more than a turn, or every one a
    whole number with some beyond a turn."""
    Q2 = np.atleast_2d(Q)
    rev = ~prismatic
    if not rev.any() or Q2.size == 0 or not np.all(np.isfinite(Q2)):
        return  # NaN and inf are refused by the caller
    V = Q2[:, rev]
    far = (upper[rev] + FULL_TURN < V) | (lower[rev] - FULL_TURN > V)
    if far.any():
        row, col = np.argwhere(far)[0]
        j = int(np.flatnonzero(rev)[col])
        why = (f"{_joint(names, j)} = {V[row, col]:.6g} is more than a turn beyond its limits "
               f"[{lower[j]:.6g}, {upper[j]:.6g}]")
    elif np.all(np.round(V) == V) and np.max(np.abs(V)) > FULL_TURN:
        why = "every revolute value is a whole number and some exceed a turn (2 pi)"
    else:
        return
    warnings.warn(f"{what} for robot {robot!r}: {why}: these look like degrees; moik takes "
                  f"joint angles in radians ({hint})", DegreesWarning,
                  stacklevel=stacklevel + 1)
