"""Serial robot chains described by Denavit-Hartenberg rows, with batched FK.

A :class:`Robot` is a frozen description: DH rows in the standard (Denavit-
Hartenberg) or modified (Craig) convention, joint types, joint offsets, joint
limits, length unit, name and source. ``robot.fk(Q)`` evaluates forward
kinematics for one joint vector ``(dof,)`` or a batch ``(n, dof)`` with no
Python loop over ``n``.

The batched FK kernel and the straightforward reference live in
:mod:`moik.robots.dh`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from moik.exceptions import LimitsError, NonFiniteError, ParameterError, ShapeError
from moik.robots import dh
from moik.robots.dh import assemble, compile_steps, run_steps

Convention = Literal["standard", "modified"]
UNITS = ("m", "cm", "mm")
JOINT_TYPES = ("revolute", "prismatic")


def _as_vector(name: str, values, dof: int) -> np.ndarray:
    arr = np.asarray(values, dtype=float)
    if arr.shape != (dof,):
        raise ShapeError(f"{name} must have shape ({dof},), got {arr.shape}")
    return arr


@dataclass(frozen=True, eq=False)
class Robot:
    """A serial chain of revolute/prismatic joints given by DH rows.

    Args:
        name: Short name (catalog key).
        a: Link lengths, shape ``(dof,)`` (``a_{i-1}`` for the modified convention).
        alpha: Link twists in radians (``alpha_{i-1}`` for modified).
        d: Link offsets; for a prismatic joint the constant part added to q.
        theta: Joint angle offsets in radians (e.g. ``pi/2`` for "theta2 + 90
            deg"); for a prismatic joint the fixed joint angle.
        lower: Lower joint limits (rad for revolute, ``unit`` for prismatic).
        upper: Upper joint limits.
        joint_types: ``"revolute"`` or ``"prismatic"`` per joint; default all revolute.
        convention: ``"standard"`` or ``"modified"`` (Craig) DH.
        unit: Length unit of a, d and of FK positions: "m", "cm" or "mm".
        source: Where the parameters come from (paper + table).
    """

    name: str
    a: np.ndarray
    alpha: np.ndarray
    d: np.ndarray
    theta: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    joint_types: tuple[str, ...] = ()
    convention: Convention = "standard"
    unit: str = "m"
    source: str = ""
    _steps: tuple = field(init=False, repr=False)
    _joint_ends: tuple = field(init=False, repr=False)

    def __post_init__(self) -> None:
        a = np.asarray(self.a, dtype=float)
        if a.ndim != 1 or a.size == 0:
            raise ShapeError(f"DH column a must be a non-empty 1-D array, got shape {a.shape}")
        dof = a.size
        cols = {"a": a}
        for key in ("alpha", "d", "theta", "lower", "upper"):
            cols[key] = _as_vector(key, getattr(self, key), dof)
        for key, arr in cols.items():
            if not np.all(np.isfinite(arr)):
                raise NonFiniteError(f"robot {self.name!r}: {key} must be finite, got {arr}")
            arr.setflags(write=False)
            object.__setattr__(self, key, arr)
        types = tuple(self.joint_types) or ("revolute",) * dof
        if len(types) != dof or any(t not in JOINT_TYPES for t in types):
            raise ParameterError(
                f"joint_types must be {dof} entries from {JOINT_TYPES}, got {types}"
            )
        object.__setattr__(self, "joint_types", types)
        if self.convention not in ("standard", "modified"):
            raise ParameterError(
                f"convention must be 'standard' or 'modified', got {self.convention!r}"
            )
        if self.unit not in UNITS:
            raise ParameterError(f"unit must be one of {UNITS}, got {self.unit!r}")
        bad = np.flatnonzero(cols["lower"] > cols["upper"])
        if bad.size:
            raise LimitsError(
                f"robot {self.name!r}: lower limit > upper limit for joint(s) "
                f"{(bad + 1).tolist()} (lower={cols['lower'][bad]}, upper={cols['upper'][bad]})"
            )
        steps, ends = compile_steps(
            cols["a"],
            cols["alpha"],
            cols["d"],
            cols["theta"],
            [t == "prismatic" for t in types],
            self.convention,
        )
        object.__setattr__(self, "_steps", steps)
        object.__setattr__(self, "_joint_ends", ends)

    # ------------------------------------------------------------------ properties
    @property
    def dof(self) -> int:
        """Number of joints."""
        return self.a.size

    @property
    def is_prismatic(self) -> np.ndarray:
        """Boolean mask of prismatic joints, shape ``(dof,)``."""
        return np.array([t == "prismatic" for t in self.joint_types])

    @property
    def limits(self) -> np.ndarray:
        """Joint limits as a ``(2, dof)`` array ``[lower, upper]``."""
        return np.stack([self.lower, self.upper])

    @property
    def reach(self) -> float:
        """Upper bound on the distance from the base to the end effector."""
        d_max = np.where(
            self.is_prismatic,
            np.maximum(abs(self.d + self.lower), abs(self.d + self.upper)),
            abs(self.d),
        )
        return float(np.sum(np.abs(self.a)) + np.sum(d_max))

    # ------------------------------------------------------------------ FK
    def check_q(self, q, name: str = "q") -> np.ndarray:
        """Validate a joint vector/batch; returns it as a float array.

        Raises:
            ShapeError: if the last axis is not ``dof`` or ndim is not 1 or 2.
            NonFiniteError: if it holds NaN or inf.
        """
        Q = np.asarray(q, dtype=float)
        if Q.ndim not in (1, 2) or Q.shape[-1] != self.dof:
            raise ShapeError(
                f"{name} for robot {self.name!r} must have shape ({self.dof},) or "
                f"(n, {self.dof}), got {Q.shape}"
            )
        if not np.all(np.isfinite(Q)):
            raise NonFiniteError(f"{name} must be finite, got NaN or inf in {name}")
        return Q

    def fk_parts(self, q) -> tuple[np.ndarray, np.ndarray]:
        """Rotation ``(n, 3, 3)`` and position ``(n, 3)`` of the end effector.

        Cheaper than :meth:`fk` when the homogeneous matrix is not needed.
        ``q`` must be 2-D ``(n, dof)``; no validation (hot path).
        """
        xy, z, p, _ = run_steps(self._steps, q, self.theta)
        R = np.empty((q.shape[0], 3, 3))
        R[:, :, 0] = xy.real.T
        R[:, :, 1] = xy.imag.T
        R[:, :, 2] = z.T
        return R, p.T

    def fk_position(self, q) -> np.ndarray:
        """End-effector positions ``(n, 3)`` of a 2-D batch (hot path, no validation)."""
        return run_steps(self._steps, q, self.theta)[2].T

    def fk(self, q) -> np.ndarray:
        """End-effector pose(s).

        Args:
            q: Joint vector ``(dof,)`` or batch ``(n, dof)`` (rad / robot unit).

        Returns:
            ``(4, 4)`` homogeneous transform for 1-D ``q``, ``(n, 4, 4)`` for 2-D.
        """
        Q = self.check_q(q)
        single = Q.ndim == 1
        Q2 = Q[None] if single else Q
        T = assemble(*run_steps(self._steps, Q2, self.theta)[:3])
        return T[0] if single else T

    def frames(self, q) -> np.ndarray:
        """Base frame and every joint frame, for plotting.

        Returns:
            ``(dof + 1, 4, 4)`` for 1-D ``q`` or ``(n, dof + 1, 4, 4)``; frame 0 is
            the base (identity), frame ``dof`` the end effector.
        """
        Q = self.check_q(q)
        single = Q.ndim == 1
        Q2 = Q[None] if single else Q
        out = np.empty((Q2.shape[0], self.dof + 1, 4, 4))
        out[:, 0] = np.eye(4)
        states = run_steps(self._steps, Q2, self.theta, self._joint_ends)[3]
        for j, state in enumerate(states):
            out[:, j + 1] = assemble(*state)
        return out[0] if single else out

    def random_q(self, n: int, *, rng: np.random.Generator) -> np.ndarray:
        """Uniform joint vectors within the limits, shape ``(n, dof)``."""
        return rng.uniform(self.lower, self.upper, size=(n, self.dof))

    def within_limits(self, q, tol: float = 0.0) -> np.ndarray:
        """Boolean per row: all joints within ``[lower - tol, upper + tol]``."""
        Q = np.atleast_2d(np.asarray(q, dtype=float))
        return np.all((self.lower - tol <= Q) & (self.upper + tol >= Q), axis=1)

    def __repr__(self) -> str:
        return f"Robot({self.name!r}, dof={self.dof}, {self.convention} DH, unit={self.unit!r})"


def fk_reference(robot: Robot, q) -> np.ndarray:
    """FK of ``robot`` by the straightforward per-joint 4x4 product (tests, benchmarks)."""
    Q = robot.check_q(q)
    T = dh.fk_reference(
        robot.a,
        robot.alpha,
        robot.d,
        robot.theta,
        robot.is_prismatic,
        robot.convention,
        np.atleast_2d(Q),
    )
    return T if Q.ndim == 2 else T[0]
