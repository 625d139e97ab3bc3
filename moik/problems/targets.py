"""IK targets: a position with an optional orientation, random reachable sets, paths.

Positions are in the robot's length unit; angles are radians unless a function
takes ``degrees=True`` explicitly. Every array must hold real numbers: strings,
complex numbers, mappings and ragged lists are refused with a message that says
what a target may be.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from moik._validate import finite_array, flag, integer, positive, real_array
from moik._validate import seed as seed_value
from moik.exceptions import (
    NonFiniteError,
    ParameterError,
    ShapeError,
    TargetError,
    UnknownNameError,
)
from moik.kinematics.orientation import (
    ROTATION_ATOL,
    _all_rotations,
    check_rotation,
    pose_matrix_status,
    rotation_from_eosma_euler,
    rotation_from_zyx,
)
from moik.robots.chain import Robot

EULER_CONVENTIONS = {"zyx-euler": rotation_from_zyx, "eosma-euler": rotation_from_eosma_euler}

# A target beyond this multiple of the robot's reach is taken as a unit mix-up.
UNIT_RANGE_FACTOR = 10.0


_LAST_ROW = (0.0, 0.0, 0.0, 1.0)
TARGET_FORMS = ("a 3-vector position, a (4, 4) pose, a (position, rotation) pair with a (3, 3) "
                "rotation, or a Target")


def _vector3(name: str, values) -> np.ndarray:
    """``values`` as a finite ``(3,)`` float array (real numbers only)."""
    v = real_array(name, values)
    if v.shape != (3,):
        raise ShapeError(f"{name} must have shape (3,), got {v.shape}")
    if not np.all(np.isfinite(v)):
        raise NonFiniteError(f"{name} must be finite, got {v}")
    return v


@dataclass(frozen=True, eq=False)
class Target:
    """A desired end-effector position and, optionally, orientation.

    Attributes:
        position: ``(3,)`` in the robot's length unit.
        rotation: ``(3, 3)`` rotation matrix, or ``None`` for position only.
        q_source: The joint vector that produced this target by FK, if known.
    """

    position: np.ndarray
    rotation: np.ndarray | None = None
    q_source: np.ndarray | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", _vector3("target position", self.position))
        if self.rotation is not None:
            R = real_array("target rotation", self.rotation)
            object.__setattr__(self, "rotation", check_rotation(R, "target rotation"))
        if self.q_source is not None:
            q = real_array("target q_source", self.q_source)
            if q.ndim != 1 or not np.all(np.isfinite(q)):
                raise ShapeError(f"target q_source must be a finite joint vector, got {q}")
            object.__setattr__(self, "q_source", q)

    @property
    def has_orientation(self) -> bool:
        """Whether an orientation is specified."""
        return self.rotation is not None

    @property
    def pose(self) -> np.ndarray:
        """``(4, 4)`` homogeneous pose (requires an orientation)."""
        if self.rotation is None:
            raise TargetError("target has no orientation; a pose needs one")
        T = np.eye(4)
        T[:3, :3] = self.rotation
        T[:3, 3] = self.position
        return T

    @classmethod
    def from_pose(cls, T) -> Target:
        """From a ``(4, 4)`` homogeneous transform."""
        T = real_array("pose", T)
        if T.shape != (4, 4):
            raise ShapeError(f"pose must have shape (4, 4), got {T.shape}")
        if pose_matrix_status(T, ROTATION_ATOL) == 0:  # valid: every check passed in one
            # compiled pass (the hot path); otherwise the checks below name the fault
            target = object.__new__(cls)
            object.__setattr__(target, "position", T[:3, 3].copy())
            object.__setattr__(target, "rotation", np.ascontiguousarray(T[:3, :3]))
            object.__setattr__(target, "q_source", None)
            return target
        last = T[3].tolist()  # numpy.allclose's rule on plain floats (a hot path)
        if not all(abs(a - b) <= 1e-8 + 1e-5 * abs(b) for a, b in zip(last, _LAST_ROW,
                                                                        strict=True)):
            raise TargetError(f"pose last row must be [0, 0, 0, 1], got {T[3]}")
        return cls(T[:3, 3], T[:3, :3])

    @classmethod
    def from_euler(cls, position, angles, *, convention: str = "zyx-euler",
                   degrees: bool = False) -> Target:
        """From a position and Euler angles ``(alpha, beta, gamma)``.

        Args:
            position: ``(3,)``.
            angles: ``(alpha, beta, gamma)`` in radians, or degrees with ``degrees=True``.
            convention: ``"zyx-euler"`` (MO-m-PSO, ``Rz Ry Rx``) or
                ``"eosma-euler"`` (EOSMA Eq. 26, intrinsic ``Rx Ry Rz``).
        """
        if convention not in EULER_CONVENTIONS:
            raise UnknownNameError("Euler convention", convention, EULER_CONVENTIONS)
        ang = _vector3("Euler angles", angles)
        if flag("degrees", degrees, error=TargetError):
            ang = np.radians(ang)
        elif np.any(np.abs(ang) > 2 * np.pi + 1e-9):
            raise TargetError(
                f"Euler angles {ang} exceed 2*pi in magnitude; angles are radians "
                "(pass degrees=True for degrees)"
            )
        return cls(position, EULER_CONVENTIONS[convention](*ang))


def as_target(spec) -> Target:
    """Coerce ``spec`` to a :class:`Target`.

    Accepts a ``Target``, a 3-vector (position only), a ``(4, 4)`` pose, or a
    ``(position, rotation)`` pair with a ``(3, 3)`` rotation.

    Raises:
        TargetError: ``spec`` is none of these (a mapping, a string, ``None``, an
            array of something other than real numbers...); the message lists the
            accepted forms.
        ShapeError: An array of real numbers of another shape.
    """
    if isinstance(spec, Target):
        return spec
    if isinstance(spec, tuple) and len(spec) == 2:
        return Target(spec[0], spec[1])
    if spec is None or isinstance(spec, (str, bytes, Mapping)):
        raise TargetError(f"target must be {TARGET_FORMS}; got a {type(spec).__name__}: "
                          f"{spec!r:.80}")
    try:
        arr = real_array("target", spec, error=TargetError)
    except TargetError as exc:
        raise TargetError(f"target must be {TARGET_FORMS}; {exc}") from None
    if arr.shape == (3,):
        return Target(arr)
    if arr.shape == (4, 4):
        return Target.from_pose(arr)
    raise ShapeError(f"target must be {TARGET_FORMS}, got an array of shape {arr.shape}")


def check_robot(robot) -> Robot:
    """``robot`` if it is a :class:`~moik.robots.chain.Robot`.

    Raises:
        ParameterError: Anything else; a catalog name is pointed to ``get_robot``.
    """
    if isinstance(robot, Robot):
        return robot
    hint = (f" (for the catalog robot call moik.get_robot({robot!r}))"
            if isinstance(robot, str) else "")
    raise ParameterError(f"robot must be a moik Robot{hint}, got {type(robot).__name__} "
                         f"{robot!r:.60}")


def check_has_reach(robot: Robot) -> None:
    """Reject a robot of zero reach (every joint and its tool at the base's origin): its
    tool cannot move, and the solvers scale positions by ``1 / reach``."""
    if robot.reach == 0.0:
        raise TargetError(
            f"robot {robot.name!r} has zero reach (every joint and its tool sit at the base's "
            "origin, no prismatic stroke): its tool cannot move, so there is no position to "
            "solve for; expected a chain with at least one non-zero offset")


def check_unit_range(target: Target, robot: Robot) -> None:
    """Reject targets far beyond the robot's reach: a length-unit mix-up.

    Targets moderately out of reach are legitimate (the solver reports them
    unreachable); one beyond ``UNIT_RANGE_FACTOR`` times the reach is almost
    surely in the wrong unit (m vs cm vs mm). A robot of zero reach is refused
    (:func:`check_has_reach`).
    """
    robot = check_robot(robot)
    check_has_reach(robot)
    dist = math.hypot(*target.position.tolist())  # norm of 3 floats (a hot path)
    if dist > UNIT_RANGE_FACTOR * robot.reach:
        raise TargetError(
            f"target position {target.position} is {dist:.4g} {robot.unit} from the base of "
            f"{robot.name!r}, more than {UNIT_RANGE_FACTOR:g}x its reach "
            f"({robot.reach:.4g} {robot.unit}); expected a position in {robot.unit}"
        )


def batch_targets(targets) -> tuple[np.ndarray, np.ndarray | None]:
    """Positions ``(n, 3)`` and rotations ``(n, 3, 3)`` (or ``None``) of a batch of poses
    ``(n, 4, 4)`` or positions ``(n, 3)``, checked; the first bad target is named."""
    arr = finite_array("targets", targets, error=ShapeError)
    if arr.ndim == 3 and arr.shape[1:] == (4, 4):
        if not np.all(np.abs(arr[:, 3] - (0.0, 0.0, 0.0, 1.0)) <= 1e-8):
            bad = int(np.flatnonzero(np.any(np.abs(arr[:, 3] - (0, 0, 0, 1)) > 1e-8, 1))[0])
            raise TargetError(f"targets[{bad}]: pose last row must be [0, 0, 0, 1], got "
                              f"{arr[bad, 3]}")
        positions, rotations = arr[:, :3, 3].copy(), _batch_rotations(arr[:, :3, :3])
    elif arr.ndim == 2 and arr.shape[1] == 3:
        positions, rotations = arr, None
    else:
        raise ShapeError(f"targets must have shape (n, 4, 4) (poses) or (n, 3) (positions), "
                         f"got {arr.shape}")
    if len(positions) == 0:
        raise ShapeError("targets is an empty batch: give at least one target")
    return positions, rotations


def _batch_rotations(R: np.ndarray) -> np.ndarray:
    """The batch's rotations (finite ``(n, 3, 3)`` blocks of the poses), copied and checked
    (:func:`~moik.kinematics.orientation.check_rotation`'s test, without its second copy and
    finiteness pass); the first that is not one is named."""
    R = np.ascontiguousarray(R)
    if _all_rotations(R, ROTATION_ATOL):
        return R
    bad = next(i for i in range(len(R)) if not _all_rotations(R[i:i + 1], ROTATION_ATOL))
    raise TargetError(f"targets[{bad}]: rotation must be a rotation matrix (orthonormal, "
                      f"det +1), got {R[bad].tolist()}")


def check_batch_reach(robot: Robot, positions: np.ndarray) -> None:
    """Each target within :data:`UNIT_RANGE_FACTOR` times the reach
    (as ``solve_ik`` checks one, here before any is solved), the first beyond it named."""
    check_has_reach(robot)
    with np.errstate(over="ignore"):  # 1e300 is simply beyond the reach (inf)
        dist = np.linalg.norm(positions, axis=1)
    far = np.flatnonzero(dist > UNIT_RANGE_FACTOR * robot.reach)
    if len(far):
        i = int(far[0])
        raise TargetError(f"targets[{i}]: position {positions[i]} is {dist[i]:.4g} "
                          f"{robot.unit} from the base of {robot.name!r}, more than "
                          f"{UNIT_RANGE_FACTOR:g}x its reach ({robot.reach:.4g} {robot.unit}); "
                          f"expected positions in {robot.unit}")


def random_reachable_targets(robot: Robot, n: int, *, seed, with_orientation: bool = True
                             ) -> list[Target]:
    """The papers' random targets: FK of uniform joint vectors within the limits.

    Args:
        robot: The arm.
        n: Number of targets.
        seed: Seed (int or ``numpy.random.SeedSequence``) of the joint sampling.
        with_orientation: Keep the FK orientation (pose targets) or not.
    """
    robot = check_robot(robot)
    n = integer("n", n, minimum=1, error=TargetError)
    with_orientation = flag("with_orientation", with_orientation, error=TargetError)
    rng = np.random.default_rng(seed_value("seed", seed))
    Q = robot.random_q(n, rng=rng)
    T = robot.fk(Q)
    return [Target(T[i, :3, 3], T[i, :3, :3] if with_orientation else None, Q[i])
            for i in range(n)]


def circle_path(center, radius: float, n_points: int, *, rotation=None) -> list[Target]:
    """MO-m-PSO Eqs. 17-18: a circle in the plane ``x = x0``.

    ``y = y0 + r cos(theta_s p)``, ``z = z0 + r sin(theta_s p)``,
    ``theta_s = 2 pi / n_points``, ``p = 0 .. n_points - 1``.
    """
    c = _vector3("circle center", center)
    radius = positive("circle radius", radius, error=TargetError)
    n_points = integer("n_points", n_points, minimum=2, error=TargetError)
    step = 2 * np.pi / n_points  # Eq. 18
    p = np.arange(n_points)
    pts = np.column_stack([np.full(p.size, c[0]), c[1] + radius * np.cos(step * p),
                           c[2] + radius * np.sin(step * p)])  # Eq. 17
    return [Target(x, rotation) for x in pts]
