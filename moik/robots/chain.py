"""Serial robot chains described by Denavit-Hartenberg rows, with batched FK.

A :class:`Robot` is a frozen description: DH rows in the standard (Denavit-
Hartenberg) or modified (Craig) convention, joint types, names, offsets and
limits, base and tool transforms, length unit, name and source. ``robot.fk(Q)``
evaluates forward kinematics for one joint vector ``(dof,)`` or a batch
``(n, dof)`` with no Python loop over ``n``.

Every robot is evaluated in the general form ``F_0 M_1(q_1) F_1 ... M_n(q_n) F_n``
(:attr:`Robot.kinematic_chain`, the base folded into ``F_0`` and the tool into
``F_n``) by the compiled kernels of :mod:`moik.robots.fk_kernels`; :func:`fk_reference`
(plain numpy, textbook DH matrices or 4x4 products, then base and tool) is the
oracle the tests compare them with.

Angles are radians: joint limits beyond two turns, or DH twists and offsets
beyond one turn, look like degrees and raise a :class:`~moik.exceptions.DegreesWarning`.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Literal

import numpy as np
from numpy.typing import ArrayLike

from moik._lazy import lazy_module
from moik._validate import integer, is_integer, number, real_array
from moik.exceptions import NonFiniteError, ParameterError, ShapeError
from moik.robots import checks
from moik.robots.description import URDFDescription
from moik.robots.transforms import (
    PRISMATIC,
    REVOLUTE,
    KinematicChain,
    dh_link_frames,
    dh_to_origins,
    fk_general_reference,
    lock_joints,
    with_base_tool,
)

Convention = Literal["standard", "modified"]
UNITS = checks.UNITS
JOINT_TYPES = checks.JOINT_TYPES
if TYPE_CHECKING:
    import moik._jit as _jit
    from moik.robots import chain_model as chain_models
    from moik.robots import fk_kernels
else:  # loaded at the first FK: describing a robot needs no numba (moik._lazy)
    _jit = lazy_module("moik._jit")
    chain_models = lazy_module("moik.robots.chain_model")
    fk_kernels = lazy_module("moik.robots.fk_kernels")
_IDENTITY = np.eye(4)
_IDENTITY.setflags(write=False)


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
        joint_names: One name per joint (default ``"q1" .. "qn"``; URDF robots
            get their joint names), to map a solution to e.g. ROS ``joint_states``.
        base: ``(4, 4)`` rigid transform from the world frame to the chain's base
            frame (default identity): FK returns ``base @ T_chain(q) @ tool``.
        tool: ``(4, 4)`` rigid transform from the last joint frame to the tool
            frame (default identity).
        convention: ``"standard"`` or ``"modified"`` (Craig) DH.
        unit: Length unit of lengths and of FK positions: "m", "cm" or "mm".
        source: Where the parameters come from (paper + table, or file).
        description: The URDF the robot was loaded from (set by ``load_urdf``; its
            collision geometry is what collision-aware solves check by default).

    Raises:
        ShapeError, NonFiniteError: Arrays of the wrong shape, not real numbers
            (strings, complex numbers, ragged lists) or not finite.
        LimitsError: A lower limit above its upper limit.
        ParameterError: Bad joint types, names, convention, unit, or a base/tool
            that is not a rigid transform.

    Warns:
        DegreesWarning: Joint limits beyond two turns, or DH twists/offsets
            beyond one turn (they look like degrees).
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
    joint_names: tuple[str, ...] = ()
    if TYPE_CHECKING:  # __post_init__ always sets them (the identity when None is given)
        base: np.ndarray
        tool: np.ndarray
    else:
        base: np.ndarray | None = None
        tool: np.ndarray | None = None
    convention: Convention = "standard"
    unit: str = "m"
    source: str = ""
    description: URDFDescription | None = None

    if TYPE_CHECKING:  # what the constructor accepts (the fields hold the checked arrays)
        def __init__(self, *, name: str, lower: ArrayLike, upper: ArrayLike,
                     a: ArrayLike | None = None, alpha: ArrayLike | None = None,
                     d: ArrayLike | None = None, theta: ArrayLike | None = None,
                     origins: ArrayLike | None = None, joint_types: Sequence[str] = (),
                     joint_names: Sequence[str] = (), base: ArrayLike | None = None,
                     tool: ArrayLike | None = None, convention: Convention = "standard",
                     unit: str = "m", source: str = "",
                     description: URDFDescription | None = None) -> None: ...

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name:
            raise ParameterError(f"robot name must be a non-empty string, got {self.name!r}")
        dh_rows = {k: getattr(self, k) for k in checks.DH_KEYS if getattr(self, k) is not None}
        cols = checks.columns(self.name, self.lower, self.upper, dh_rows, self.origins)
        for key, arr in cols.items():
            object.__setattr__(self, key, arr)
        dof = cols["lower"].size
        types = checks.joint_types(self.joint_types, dof)
        object.__setattr__(self, "joint_types", types)
        object.__setattr__(self, "joint_names", checks.joint_names(self.joint_names, dof))
        for key in ("base", "tool"):
            value = getattr(self, key)
            object.__setattr__(self, key, _IDENTITY if value is None
                               else checks.rigid_transform(f"robot {self.name!r} {key}", value))
        if self.convention not in ("standard", "modified"):
            raise ParameterError(
                f"convention must be 'standard' or 'modified', got {self.convention!r}"
            )
        if self.unit not in UNITS:
            raise ParameterError(f"unit must be one of {UNITS}, got {self.unit!r}")
        if self.description is not None and not isinstance(self.description, URDFDescription):
            raise ParameterError("description must be a moik.robots.description.URDFDescription "
                                 f"or None, got {type(self.description).__name__}")
        with np.errstate(over="ignore", invalid="ignore"):  # inf is what is checked for
            checks.finite_reach(self.name, self.reach, self.unit)
        checks.warn_if_degrees(self.name, cols, np.array([t == "prismatic" for t in types]),
                               stacklevel=3)

    def __getstate__(self) -> dict:
        """The fields and cached values but :attr:`chain_model` (a numba StructRef does not
        pickle; it is built again where the robot is unpickled)."""
        return {k: v for k, v in self.__dict__.items() if k != "chain_model"}

    def __setstate__(self, state: dict) -> None:
        """Unpickled, the arrays are read-only again, as the constructor leaves them (and
        so of the numba types kernels were compiled for in the pickling process)."""
        for value in state.values():
            if isinstance(value, np.ndarray):
                value.flags.writeable = False
        self.__dict__.update(state)

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

    @cached_property
    def _revolute(self) -> np.ndarray:
        """Boolean mask of revolute joints (read-only; the joint screen of :meth:`check_q`)."""
        mask = ~self.is_prismatic
        mask.flags.writeable = False
        return mask

    @property
    def limits(self) -> np.ndarray:
        """Joint limits as a ``(2, dof)`` array ``[lower, upper]``."""
        return np.stack([self.lower, self.upper])

    @cached_property
    def reach(self) -> float:
        """Upper bound on ``|p(q)|``, the distance of the tool from the world origin.

        The sum of the translations of every constant (base and tool included)
        and of the prismatic strokes (computed once).
        """
        stroke = np.where(self.is_prismatic, np.maximum(abs(self.lower), abs(self.upper)), 0.0)
        links = np.linalg.norm(self.chain_origins()[:, :3, 3], axis=1)
        return float(np.sum(links) + np.sum(stroke))

    def chain_origins(self) -> np.ndarray:
        """The fixed transforms ``F_0 .. F_n`` the kernels evaluate, base and tool included."""
        return with_base_tool(self._own_origins(), self.base, self.tool)

    def _own_origins(self) -> np.ndarray:
        """``F_0 .. F_n`` of the chain itself (from DH if needed), without base and tool."""
        if self.origins is not None:
            return np.array(self.origins)
        return dh_to_origins(self.a, self.alpha, self.d, self.theta, self.is_prismatic,
                             self.convention)

    @cached_property
    def kinematic_chain(self) -> KinematicChain:
        """The general-form constants the compiled FK kernels take (built once).

        Pass its arrays to the kernels of :mod:`moik.robots.fk_kernels` (and
        :mod:`moik.kinematics.jacobian`) from compiled code, e.g.
        ``fk_pose_into(chain.origins, chain.joint_types, q, out)``.
        """
        if self.origins is None:
            links = dh_link_frames(self.a, self.alpha, self.d, self.theta, self.is_prismatic,
                                   self.convention)
        else:
            links = np.array(self.origins[1:])
        if not np.array_equal(self.tool, _IDENTITY):  # the last frame is the tool frame
            links[-1] = links[-1] @ self.tool
        types = np.where(self.is_prismatic, PRISMATIC, REVOLUTE)
        return KinematicChain(origins=self.chain_origins(), joint_types=types,
                              link_frames=links)

    @cached_property
    def chain_model(self) -> chain_models.ChainModel:
        """The arm as the one compiled record every kernel outside :mod:`moik.algorithms`
        takes (:class:`~moik.robots.chain_model.ChainModel`: the chain, base, limits and
        ``1 / reach``; built once)."""
        return self.new_chain_model()

    def new_chain_model(self) -> chain_models.ChainModel:
        """A :attr:`chain_model` of its own (the same arrays): for a thread, whose compiled
        code would otherwise share one record's reference count with the others' (an atomic
        operation on one cache line at each use)."""
        return chain_models.chain_model(self.kinematic_chain, self.base, self.lower,
                                        self.upper, self.reach)

    def with_locked_joints(self, locked: dict[int, float]) -> Robot:
        """The robot with joints ``{index: value}`` fixed (0-based indices).

        Example: the I-BES Table 9 Puma 560 position problem is
        ``get_robot("puma560").with_locked_joints({3: 0.0, 4: 0.0, 5: 0.0})``.
        The free joints keep their names, the robot its base and tool.

        Raises:
            ParameterError: ``locked`` is not a mapping of joint indices to finite
                numbers, or it leaves no joint free.
        """
        if not isinstance(locked, Mapping):
            raise ParameterError(f"locked must be a dict {{joint index: value}}, got "
                                 f"{type(locked).__name__}")
        bad = [j for j in locked if not (is_integer(j) and 0 <= j < self.dof)]
        if bad:
            raise ParameterError(f"locked joint indices must be in 0..{self.dof - 1}, got {bad}")
        if len(locked) >= self.dof:
            raise ParameterError("at least one joint must stay free")
        values = {int(j): number(f"locked value of joint {j}", v) for j, v in locked.items()}
        origins, free = lock_joints(self._own_origins(), self.is_prismatic, values)
        desc = ", ".join(f"q{j + 1}={v:g}" for j, v in sorted(values.items()))
        return Robot(name=f"{self.name}[{desc}]", origins=origins, lower=self.lower[free],
                     upper=self.upper[free],
                     joint_types=tuple(self.joint_types[j] for j in free),
                     joint_names=tuple(self.joint_names[j] for j in free),
                     base=self.base, tool=self.tool, unit=self.unit,
                     source=f"{self.source}; joints locked: {desc}")

    # ------------------------------------------------------------------ FK
    def check_q(self, q, name: str = "q") -> np.ndarray:
        """Validate a joint vector/batch; returns it as a C-contiguous, writeable float array.

        Raises:
            ShapeError: if it is not an array of real numbers (strings, complex
                numbers, ragged lists), the last axis is not ``dof`` or ndim is not 1 or 2.
            NonFiniteError: if it holds NaN or inf.

        Warns:
            DegreesWarning: revolute values that look like degrees (one more than a turn
                beyond its limits, or all whole numbers some beyond a turn).
        """
        Q = self._joint_array(q, name)
        if Q.ndim not in (1, 2) or Q.shape[-1] != self.dof:
            raise ShapeError(
                f"{name} for robot {self.name!r} must have shape ({self.dof},) or "
                f"(n, {self.dof}), got {Q.shape}"
            )
        screen = fk_kernels.joint_screen(Q.reshape(-1, self.dof), self.lower, self.upper,
                                         self._revolute, checks.FULL_TURN)
        if screen == 1:
            raise NonFiniteError(f"{name} must be finite, got NaN or inf in {name}")
        if screen == 2:  # the kernel's screen is the warning's condition; this words it
            checks.warn_if_joint_degrees(self.name, self.joint_names, self.lower, self.upper,
                                         self.is_prismatic, Q, name, stacklevel=3)
        return Q

    def kernel_batch(self, q) -> np.ndarray:
        """``q`` as the batched kernels take it: a C-contiguous, writeable float ``(n, dof)``.

        Checks the type and shape only (a kernel given fewer columns would read past
        the array; numba does not check bounds), not finiteness (hot path: NaN in,
        NaN out). A single joint vector ``(dof,)`` is refused: pass ``q[None]``
        (or use :meth:`fk`, which takes both).

        Raises:
            ShapeError: if ``q`` is not 2-D with ``dof`` columns of real numbers.
        """
        Q = self._joint_array(q, "a batch")
        if Q.ndim != 2 or Q.shape[1] != self.dof:
            hint = ("; for one joint vector pass q[None] or use robot.fk(q)"
                    if Q.shape == (self.dof,) else "")
            raise ShapeError(f"a batch for robot {self.name!r} must have shape (n, {self.dof}), "
                             f"got {Q.shape}{hint}")
        return Q

    def _joint_array(self, q, name: str) -> np.ndarray:
        """``q`` as the kernels' float64 array; anything but real numbers is refused."""
        if type(q) is np.ndarray and q.dtype == np.float64:
            return _jit.kernel_array(q)
        return real_array(f"{name} for robot {self.name!r}", q)

    def fk_parts(self, q) -> tuple[np.ndarray, np.ndarray]:
        """Rotation ``(n, 3, 3)`` and position ``(n, 3)`` of the end effector.

        Cheaper than :meth:`fk` when the homogeneous matrix is not needed.
        ``q`` must be 2-D ``(n, dof)`` (a single vector is refused with a hint:
        pass ``q[None]``); no finiteness check (hot path).
        """
        chain = self.kinematic_chain
        Q = self.kernel_batch(q)
        R, p = np.empty((Q.shape[0], 3, 3)), np.empty((Q.shape[0], 3))
        fk_kernels.fk_rotations_positions(chain.origins, chain.joint_types, Q, R, p)
        return R, p

    def fk_position(self, q) -> np.ndarray:
        """End-effector positions ``(n, 3)`` of a 2-D batch ``(n, dof)`` (hot path, no
        finiteness check; a single vector is refused with a hint: pass ``q[None]``)."""
        chain = self.kinematic_chain
        Q = self.kernel_batch(q)
        p = np.empty((Q.shape[0], 3))
        fk_kernels.fk_positions(chain.origins, chain.joint_types, Q, p)
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
        fk_kernels.fk_poses(chain.origins, chain.joint_types, Q2, T)
        return T[0] if Q.ndim == 1 else T

    def frames(self, q) -> np.ndarray:
        """Base frame and every joint frame, for plotting.

        Returns:
            ``(dof + 1, 4, 4)`` for 1-D ``q`` or ``(n, dof + 1, 4, 4)``; frame 0 is
            the base (:attr:`base`), frame ``dof`` the tool (the pose :meth:`fk` returns).
        """
        Q = self.check_q(q)
        Q2 = Q[None] if Q.ndim == 1 else Q
        chain = self.kinematic_chain
        out = np.empty((Q2.shape[0], self.dof + 1, 4, 4))
        fk_kernels.fk_frames(chain.origins, chain.link_frames, chain.joint_types, Q2, out)
        out[:, 0] = self.base
        return out[0] if Q.ndim == 1 else out

    def random_q(self, n: int, *, rng: np.random.Generator) -> np.ndarray:
        """Uniform joint vectors within the limits, shape ``(n, dof)``."""
        n = integer("n", n, minimum=0)
        if not isinstance(rng, np.random.Generator):
            raise ParameterError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
        # lower + (upper - lower) * U[0, 1): Generator.uniform's own formula, bit for bit,
        # without its broadcasting overhead (this is on solve_ik's hot path)
        return self.lower + (self.upper - self.lower) * rng.random((n, self.dof))

    def outside_limits(self, q) -> str:
        """The joints of one joint vector ``q`` outside the limits, in words ("" if none)."""
        return checks.outside_limits(self.joint_names, self.lower, self.upper,
                                     self._joint_array(q, "q"))

    def within_limits(self, q, tol: float = 0.0) -> np.ndarray:
        """Boolean per row: all joints within ``[lower - tol, upper + tol]``."""
        Q = np.atleast_2d(self._joint_array(q, "q"))
        return np.all((self.lower - tol <= Q) & (self.upper + tol >= Q), axis=1)

    def __repr__(self) -> str:
        kind = f"{self.convention} DH" if self.is_dh else "general chain"
        return f"Robot({self.name!r}, dof={self.dof}, {kind}, unit={self.unit!r})"


def fk_reference(robot: Robot, q) -> np.ndarray:
    """FK of ``robot`` by the straightforward per-joint 4x4 product in numpy.

    The oracle the compiled kernels are tested against, and the baseline of
    ``benchmarks/fk.py``. Base and tool are applied here as separate products
    (``base @ T @ tool``), not folded into the constants as the kernels have them.
    """
    Q = robot.check_q(q)
    Q2 = np.atleast_2d(Q)
    if robot.is_dh:
        T = fk_kernels.fk_reference(robot.a, robot.alpha, robot.d, robot.theta,
                                    robot.is_prismatic, robot.convention, Q2)
    else:
        assert robot.origins is not None  # a chain not given by DH rows has origins
        T = fk_general_reference(robot.origins, robot.is_prismatic, Q2)
    if not np.array_equal(robot.base, _IDENTITY):
        T = robot.base @ T
    if not np.array_equal(robot.tool, _IDENTITY):
        T = T @ robot.tool
    return T if Q.ndim == 2 else T[0]
