"""Serial robot chains described by Denavit-Hartenberg rows, with batched FK.

A :class:`Robot` is a frozen description: DH rows in the standard (Denavit-
Hartenberg) or modified (Craig) convention, joint types, joint offsets, joint
limits, length unit, name and source. ``robot.fk(Q)`` evaluates forward
kinematics for one joint vector ``(dof,)`` or a batch ``(n, dof)`` with no
Python loop over ``n``.

Every robot is evaluated in the general form ``F_0 M_1(q_1) F_1 ... M_n(q_n) F_n``
(:attr:`Robot.kinematic_chain`) by the compiled kernels of :mod:`moik.robots.dh`;
:func:`fk_reference` (plain numpy, textbook DH matrices or 4x4 products) is the
oracle the tests compare them with.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Literal

import numpy as np

from moik._jit import kernel_array
from moik.exceptions import LimitsError, NonFiniteError, ParameterError, ShapeError
from moik.robots import dh
from moik.robots.transforms import (
    PRISMATIC,
    REVOLUTE,
    KinematicChain,
    dh_link_frames,
    dh_to_origins,
    fk_general_reference,
    lock_joints,
)

Convention = Literal["standard", "modified"]
UNITS = ("m", "cm", "mm")
JOINT_TYPES = ("revolute", "prismatic")


def _as_vector(name: str, values, dof: int) -> np.ndarray:
    arr = np.asarray(values, dtype=float)
    if arr.shape != (dof,):
        raise ShapeError(f"{name} must have shape ({dof},), got {arr.shape}")
    return arr


@dataclass(frozen=True, eq=False, kw_only=True)
class Robot:
    """A serial chain of revolute/prismatic joints.

    Given either by DH rows (``a``, ``alpha``, ``d``, ``theta``) or, for URDF
    chains and chains with locked joints, by ``origins``: the constant
    transforms ``F_0 .. F_n`` of ``F_0 M_1(q_1) F_1 ... M_n(q_n) F_n`` where
    ``M_j`` is ``Rz(q_j)`` or ``Tz(q_j)`` (see :mod:`moik.robots.transforms`).

    Args:
        name: Short name (catalog key).
        a: Link lengths, shape ``(dof,)`` (``a_{i-1}`` for the modified convention).
        alpha: Link twists in radians (``alpha_{i-1}`` for modified).
        d: Link offsets; for a prismatic joint the constant part added to q.
        theta: Joint angle offsets in radians (e.g. ``pi/2`` for "theta2 + 90
            deg"); for a prismatic joint the fixed joint angle.
        origins: ``(dof + 1, 4, 4)`` fixed transforms, instead of DH rows.
        lower: Lower joint limits (rad for revolute, ``unit`` for prismatic).
        upper: Upper joint limits.
        joint_types: ``"revolute"`` or ``"prismatic"`` per joint; default all revolute.
        convention: ``"standard"`` or ``"modified"`` (Craig) DH.
        unit: Length unit of lengths and of FK positions: "m", "cm" or "mm".
        source: Where the parameters come from (paper + table, or file).
    """

    name: str
    lower: np.ndarray
    upper: np.ndarray
    a: np.ndarray | None = None
    alpha: np.ndarray | None = None
    d: np.ndarray | None = None
    theta: np.ndarray | None = None
    origins: np.ndarray | None = None
    joint_types: tuple[str, ...] = ()
    convention: Convention = "standard"
    unit: str = "m"
    source: str = ""

    def __post_init__(self) -> None:
        lower = np.asarray(self.lower, dtype=float)
        if lower.ndim != 1 or lower.size == 0:
            raise ShapeError(f"lower limits must be a non-empty 1-D array, got {lower.shape}")
        dof = lower.size
        dh_given = [k for k in ("a", "alpha", "d", "theta") if getattr(self, k) is not None]
        if self.origins is None and len(dh_given) != 4:
            raise ParameterError("a robot needs DH rows (a, alpha, d, theta) or origins")
        if self.origins is not None and dh_given:
            raise ParameterError(f"give DH rows or origins, not both (got origins and {dh_given})")
        cols = {"lower": lower, "upper": _as_vector("upper", self.upper, dof)}
        for key in dh_given:
            cols[key] = _as_vector(key, getattr(self, key), dof)
        if self.origins is not None:
            origins = np.asarray(self.origins, dtype=float)
            if origins.shape != (dof + 1, 4, 4):
                raise ShapeError(f"origins must have shape ({dof + 1}, 4, 4), got {origins.shape}")
            cols["origins"] = origins
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

    # ------------------------------------------------------------------ properties
    @property
    def dof(self) -> int:
        """Number of joints."""
        return self.lower.size

    @property
    def is_dh(self) -> bool:
        """Whether the robot is given by DH rows (else by origins)."""
        return self.origins is None

    @cached_property
    def is_prismatic(self) -> np.ndarray:
        """Boolean mask of prismatic joints, shape ``(dof,)`` (read-only, computed once)."""
        mask = np.array([t == "prismatic" for t in self.joint_types])
        mask.flags.writeable = False
        return mask

    @property
    def limits(self) -> np.ndarray:
        """Joint limits as a ``(2, dof)`` array ``[lower, upper]``."""
        return np.stack([self.lower, self.upper])

    @cached_property
    def reach(self) -> float:
        """Upper bound on the distance from the base to the end effector (computed once)."""
        stroke = np.where(self.is_prismatic, np.maximum(abs(self.lower), abs(self.upper)), 0.0)
        links = np.linalg.norm(self.chain_origins()[:, :3, 3], axis=1)
        return float(np.sum(links) + np.sum(stroke))

    def chain_origins(self) -> np.ndarray:
        """The fixed transforms ``F_0 .. F_n`` (converted from DH if needed)."""
        if self.origins is not None:
            return np.array(self.origins)
        return dh_to_origins(self.a, self.alpha, self.d, self.theta, self.is_prismatic,
                             self.convention)

    @cached_property
    def kinematic_chain(self) -> KinematicChain:
        """The general-form constants the compiled FK kernels take (built once).

        Pass its arrays to the kernels of :mod:`moik.robots.dh` (and
        :mod:`moik.kinematics.jacobian`) from compiled code, e.g.
        ``fk_pose_into(chain.origins, chain.joint_types, q, out)``.
        """
        if self.origins is None:
            links = dh_link_frames(self.a, self.alpha, self.d, self.theta, self.is_prismatic,
                                   self.convention)
        else:
            links = self.origins[1:]
        types = np.where(self.is_prismatic, PRISMATIC, REVOLUTE)
        return KinematicChain(origins=self.chain_origins(), joint_types=types,
                              link_frames=links)

    def with_locked_joints(self, locked: dict[int, float]) -> Robot:
        """The robot with joints ``{index: value}`` fixed (0-based indices).

        Example: the I-BES Table 9 Puma 560 position problem is
        ``get_robot("puma560").with_locked_joints({3: 0.0, 4: 0.0, 5: 0.0})``.
        """
        bad = [j for j in locked if not (isinstance(j, int | np.integer) and 0 <= j < self.dof)]
        if bad:
            raise ParameterError(f"locked joint indices must be in 0..{self.dof - 1}, got {bad}")
        if len(locked) >= self.dof:
            raise ParameterError("at least one joint must stay free")
        origins, free = lock_joints(self.chain_origins(), self.is_prismatic,
                                    {int(j): float(v) for j, v in locked.items()})
        desc = ", ".join(f"q{j + 1}={v:g}" for j, v in sorted(locked.items()))
        return Robot(name=f"{self.name}[{desc}]", origins=origins, lower=self.lower[free],
                     upper=self.upper[free],
                     joint_types=tuple(self.joint_types[j] for j in free), unit=self.unit,
                     source=f"{self.source}; joints locked: {desc}")

    # ------------------------------------------------------------------ FK
    def check_q(self, q, name: str = "q") -> np.ndarray:
        """Validate a joint vector/batch; returns it as a C-contiguous, writeable float array.

        Raises:
            ShapeError: if the last axis is not ``dof`` or ndim is not 1 or 2.
            NonFiniteError: if it holds NaN or inf.
        """
        Q = kernel_array(q)
        if Q.ndim not in (1, 2) or Q.shape[-1] != self.dof:
            raise ShapeError(
                f"{name} for robot {self.name!r} must have shape ({self.dof},) or "
                f"(n, {self.dof}), got {Q.shape}"
            )
        if not dh.all_finite(Q.reshape(-1)):
            raise NonFiniteError(f"{name} must be finite, got NaN or inf in {name}")
        return Q

    def kernel_batch(self, q) -> np.ndarray:
        """``q`` as the batched kernels take it: a C-contiguous, writeable float ``(n, dof)``.

        Checks the shape only (a kernel given fewer columns would read past the
        array; numba does not check bounds), not finiteness (hot path: NaN in, NaN out).

        Raises:
            ShapeError: if ``q`` is not 2-D with ``dof`` columns.
        """
        Q = kernel_array(q)
        if Q.ndim != 2 or Q.shape[1] != self.dof:
            raise ShapeError(f"a batch for robot {self.name!r} must have shape (n, {self.dof}), "
                             f"got {Q.shape}")
        return Q

    def fk_parts(self, q) -> tuple[np.ndarray, np.ndarray]:
        """Rotation ``(n, 3, 3)`` and position ``(n, 3)`` of the end effector.

        Cheaper than :meth:`fk` when the homogeneous matrix is not needed.
        ``q`` must be 2-D ``(n, dof)``; no finiteness check (hot path).
        """
        chain = self.kinematic_chain
        Q = self.kernel_batch(q)
        R, p = np.empty((Q.shape[0], 3, 3)), np.empty((Q.shape[0], 3))
        dh.fk_rotations_positions(chain.origins, chain.joint_types, Q, R, p)
        return R, p

    def fk_position(self, q) -> np.ndarray:
        """End-effector positions ``(n, 3)`` of a 2-D batch (hot path, no finiteness check)."""
        chain = self.kinematic_chain
        Q = self.kernel_batch(q)
        p = np.empty((Q.shape[0], 3))
        dh.fk_positions(chain.origins, chain.joint_types, Q, p)
        return p

    def fk(self, q) -> np.ndarray:
        """End-effector pose(s).

        Args:
            q: Joint vector ``(dof,)`` or batch ``(n, dof)`` (rad / robot unit).

        Returns:
            ``(4, 4)`` homogeneous transform for 1-D ``q``, ``(n, 4, 4)`` for 2-D.
        """
        Q = self.check_q(q)
        Q2 = Q[None] if Q.ndim == 1 else Q
        chain = self.kinematic_chain
        T = np.empty((Q2.shape[0], 4, 4))
        dh.fk_poses(chain.origins, chain.joint_types, Q2, T)
        return T[0] if Q.ndim == 1 else T

    def frames(self, q) -> np.ndarray:
        """Base frame and every joint frame, for plotting.

        Returns:
            ``(dof + 1, 4, 4)`` for 1-D ``q`` or ``(n, dof + 1, 4, 4)``; frame 0 is
            the base (identity), frame ``dof`` the end effector.
        """
        Q = self.check_q(q)
        Q2 = Q[None] if Q.ndim == 1 else Q
        chain = self.kinematic_chain
        out = np.empty((Q2.shape[0], self.dof + 1, 4, 4))
        dh.fk_frames(chain.origins, chain.link_frames, chain.joint_types, Q2, out)
        return out[0] if Q.ndim == 1 else out

    def random_q(self, n: int, *, rng: np.random.Generator) -> np.ndarray:
        """Uniform joint vectors within the limits, shape ``(n, dof)``."""
        # lower + (upper - lower) * U[0, 1): Generator.uniform's own formula, bit for bit,
        # without its broadcasting overhead (this is on solve_ik's hot path)
        return self.lower + (self.upper - self.lower) * rng.random((n, self.dof))

    def within_limits(self, q, tol: float = 0.0) -> np.ndarray:
        """Boolean per row: all joints within ``[lower - tol, upper + tol]``."""
        Q = np.atleast_2d(np.asarray(q, dtype=float))
        return np.all((self.lower - tol <= Q) & (self.upper + tol >= Q), axis=1)

    def __repr__(self) -> str:
        kind = f"{self.convention} DH" if self.is_dh else "general chain"
        return f"Robot({self.name!r}, dof={self.dof}, {kind}, unit={self.unit!r})"


def fk_reference(robot: Robot, q) -> np.ndarray:
    """FK of ``robot`` by the straightforward per-joint 4x4 product in numpy.

    The oracle the compiled kernels are tested against, and the baseline of
    ``benchmarks/fk.py``; not used at run time.
    """
    Q = robot.check_q(q)
    Q2 = np.atleast_2d(Q)
    if robot.is_dh:
        T = dh.fk_reference(robot.a, robot.alpha, robot.d, robot.theta, robot.is_prismatic,
                            robot.convention, Q2)
    else:
        T = fk_general_reference(robot.origins, robot.is_prismatic, Q2)
    return T if Q.ndim == 2 else T[0]
