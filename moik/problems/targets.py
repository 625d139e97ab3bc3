"""IK targets: a position with an optional orientation, random reachable sets, paths.

Positions are in the robot's length unit; angles are radians unless a function
takes ``degrees=True`` explicitly.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from moik._validate import integer, positive
from moik._validate import seed as seed_value
from moik.exceptions import NonFiniteError, ShapeError, TargetError, UnknownNameError
from moik.kinematics.orientation import (
    check_rotation,
    rotation_from_eosma_euler,
    rotation_from_zyx,
)
from moik.robots.chain import Robot

EULER_CONVENTIONS = {"zyx-euler": rotation_from_zyx, "eosma-euler": rotation_from_eosma_euler}

# A target beyond this multiple of the robot's reach is taken as a unit mix-up.
UNIT_RANGE_FACTOR = 10.0


_LAST_ROW = (0.0, 0.0, 0.0, 1.0)


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
        p = np.asarray(self.position, dtype=float)
        if p.shape != (3,):
            raise ShapeError(f"target position must have shape (3,), got {p.shape}")
        if not np.all(np.isfinite(p)):
            raise NonFiniteError(f"target position must be finite, got {p}")
        object.__setattr__(self, "position", p)
        if self.rotation is not None:
            object.__setattr__(self, "rotation", check_rotation(self.rotation, "target rotation"))

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
        T = np.asarray(T, dtype=float)
        if T.shape != (4, 4):
            raise ShapeError(f"pose must have shape (4, 4), got {T.shape}")
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
        ang = np.asarray(angles, dtype=float)
        if ang.shape != (3,):
            raise ShapeError(f"Euler angles must have shape (3,), got {ang.shape}")
        if not np.all(np.isfinite(ang)):
            raise NonFiniteError(f"Euler angles must be finite, got {ang}")
        if degrees:
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
    """
    if isinstance(spec, Target):
        return spec
    if isinstance(spec, tuple) and len(spec) == 2:
        return Target(spec[0], spec[1])
    arr = np.asarray(spec, dtype=float)
    if arr.shape == (3,):
        return Target(arr)
    if arr.shape == (4, 4):
        return Target.from_pose(arr)
    raise ShapeError(
        "target must be a 3-vector position, a (4, 4) pose, a (position, rotation) "
        f"pair or a Target, got an array of shape {arr.shape}"
    )


def check_unit_range(target: Target, robot: Robot) -> None:
    """Reject targets far beyond the robot's reach: a length-unit mix-up.

    Targets moderately out of reach are legitimate (the solver reports them
    unreachable); one beyond ``UNIT_RANGE_FACTOR`` times the reach is almost
    surely in the wrong unit (m vs cm vs mm).
    """
    dist = float(np.linalg.norm(target.position))
    if dist > UNIT_RANGE_FACTOR * robot.reach:
        raise TargetError(
            f"target position {target.position} is {dist:.4g} {robot.unit} from the base of "
            f"{robot.name!r}, more than {UNIT_RANGE_FACTOR:g}x its reach "
            f"({robot.reach:.4g} {robot.unit}); expected a position in {robot.unit}"
        )


def random_reachable_targets(robot: Robot, n: int, *, seed, with_orientation: bool = True
                             ) -> list[Target]:
    """The papers' random targets: FK of uniform joint vectors within the limits.

    Args:
        robot: The arm.
        n: Number of targets.
        seed: Seed (int or ``numpy.random.SeedSequence``) of the joint sampling.
        with_orientation: Keep the FK orientation (pose targets) or not.
    """
    n = integer("n", n, minimum=1, error=TargetError)
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
    c = np.asarray(center, dtype=float)
    if c.shape != (3,):
        raise ShapeError(f"circle center must have shape (3,), got {c.shape}")
    radius = positive("circle radius", radius, error=TargetError)
    n_points = integer("n_points", n_points, minimum=2, error=TargetError)
    step = 2 * np.pi / n_points  # Eq. 18
    p = np.arange(n_points)
    pts = np.column_stack([np.full(p.size, c[0]), c[1] + radius * np.cos(step * p),
                           c[2] + radius * np.sin(step * p)])  # Eq. 17
    return [Target(x, rotation) for x in pts]
