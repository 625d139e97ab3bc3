"""Collision primitives: sphere, capsule, box, half-space (cylinders become capsules).

Each shape is a frozen, validated value with a ``pose`` (``(4, 4)`` rigid transform
of the shape's own frame in the frame it is attached to: a link frame of a robot, or
the world for a scene's obstacle) and sizes in the robot's length unit:

* :class:`Sphere` ``(radius)`` centred at the pose's origin;
* :class:`Capsule` ``(radius, length)``: the points within ``radius`` of the segment of
  ``length`` along the pose's z axis, centred at its origin
  (:meth:`Capsule.between` builds one from two end points);
* :class:`Box` ``(size)``: full side lengths along the pose's x, y, z axes;
* :class:`HalfSpace`: the solid ``z <= 0`` of its pose, a table top or floor whose
  outward normal is the pose's z axis (:meth:`HalfSpace.plane` from normal and offset).

A URDF ``<cylinder>`` is modelled by :func:`cylinder`: the capsule of the same radius
whose segment is the cylinder's axis (it contains the cylinder and extends ``radius``
beyond each flat end): conservative, never an underestimate of contact.

The compiled kernels take a shape as a kind code, a pose and three sizes
(:func:`shape_arrays`; :mod:`moik.collision.distance` documents them).
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from moik._validate import finite_array, number
from moik.collision.distance import BOX, CAPSULE, HALFSPACE, SPHERE
from moik.exceptions import NonFiniteError, ParameterError
from moik.robots.checks import rigid_transform

__all__ = ["Box", "Capsule", "HalfSpace", "Shape", "Sphere", "cylinder", "shape_arrays"]


def _pose(owner: str, pose: Any) -> np.ndarray:
    if pose is None:
        return np.eye(4)
    return rigid_transform(f"{owner} pose", finite_array(f"{owner} pose", pose, shape=(4, 4)))


def _length(owner: str, what: str, value: Any, *, allow_zero: bool) -> float:
    if isinstance(value, (float, np.floating)) and not np.isfinite(value):
        raise NonFiniteError(f"{owner} {what} must be a finite length, got {value!r}")
    v = number(f"{owner} {what}", value)
    if v < 0 or (v == 0 and not allow_zero):
        raise ParameterError(f"{owner} {what} must be {'>= 0' if allow_zero else '> 0'}, "
                             f"got {v!r}")
    return v


@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class Shape(ABC):
    """Base of the primitives: a pose and the kernel's kind code and sizes."""

    pose: np.ndarray = field(default_factory=lambda: np.eye(4))
    kind = -1

    def __post_init__(self) -> None:
        object.__setattr__(self, "pose", _pose(type(self).__name__, self.pose))

    @property
    @abstractmethod
    def sizes(self) -> tuple[float, float, float]:
        """The three numbers the kernels take (see :mod:`moik.collision.distance`)."""

    def moved(self, transform: Any) -> Shape:
        """The same shape with pose ``transform @ pose``."""
        T = rigid_transform("transform", finite_array("transform", transform, shape=(4, 4)))
        return _replace_pose(self, T @ self.pose)

    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready description (read back by :func:`moik.collision.io.shape_from_dict`)."""
        out: dict[str, Any] = {"type": type(self).__name__.lower()}
        out.update(self._sizes_dict())
        out["pose"] = self.pose.tolist()
        return out

    @abstractmethod
    def _sizes_dict(self) -> dict[str, Any]:
        """The shape's own sizes, by name (its part of :meth:`to_dict`)."""

    def __repr__(self) -> str:
        """One line: the sizes, the pose's origin, and ``rotated`` when the pose turns."""
        parts = [f"{k}={_short(v)}" for k, v in self._sizes_dict().items()]
        parts.append(f"at={_short(self.pose[:3, 3].tolist())}")
        if not np.allclose(self.pose[:3, :3], np.eye(3)):
            parts.append("rotated")
        return f"{type(self).__name__}({', '.join(parts)})"


def _short(value: Any) -> str:
    """A number or a list of numbers with 4 significant digits."""
    if isinstance(value, (list, tuple)):
        return "(" + ", ".join(_short(v) for v in value) + ")"
    return f"{float(value) + 0.0:.4g}"


def _replace_pose(shape: Shape, pose: np.ndarray) -> Shape:
    return replace(shape, pose=pose)


@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class Sphere(Shape):
    """A ball of ``radius`` around the pose's origin."""

    radius: float
    kind = SPHERE

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "radius", _length("sphere", "radius", self.radius,
                                                   allow_zero=True))

    @property
    def sizes(self) -> tuple[float, float, float]:
        return self.radius, 0.0, 0.0

    def _sizes_dict(self) -> dict[str, Any]:
        return {"radius": self.radius}


@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class Capsule(Shape):
    """The points within ``radius`` of a segment of ``length`` along the pose's z axis."""

    radius: float
    length: float
    kind = CAPSULE

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "radius", _length("capsule", "radius", self.radius,
                                                   allow_zero=True))
        object.__setattr__(self, "length", _length("capsule", "length", self.length,
                                                   allow_zero=True))

    @classmethod
    def between(cls, a: Sequence[float], b: Sequence[float], radius: float) -> Capsule:
        """The capsule of ``radius`` around the segment from point ``a`` to point ``b``."""
        pa = finite_array("capsule end a", a, shape=(3,))
        pb = finite_array("capsule end b", b, shape=(3,))
        axis = pb - pa
        length = float(np.linalg.norm(axis))
        pose = np.eye(4)
        pose[:3, 3] = (pa + pb) / 2
        if length > 0:
            pose[:3, :3] = _frame_with_z(axis / length)
        return cls(radius=radius, length=length, pose=pose)

    @property
    def ends(self) -> tuple[np.ndarray, np.ndarray]:
        """The segment's end points in the frame the capsule is attached to."""
        c, z = self.pose[:3, 3], self.pose[:3, 2]
        return c - self.length / 2 * z, c + self.length / 2 * z

    @property
    def sizes(self) -> tuple[float, float, float]:
        return self.radius, self.length / 2, 0.0

    def _sizes_dict(self) -> dict[str, Any]:
        return {"radius": self.radius, "length": self.length}


@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class Box(Shape):
    """A box of full side lengths ``size = (x, y, z)`` along the pose's axes."""

    size: tuple[float, float, float]
    kind = BOX

    def __post_init__(self) -> None:
        super().__post_init__()
        size = finite_array("box size", self.size, shape=(3,))
        if np.any(size <= 0):
            raise ParameterError(f"box size must be 3 lengths > 0, got {size.tolist()}")
        object.__setattr__(self, "size", tuple(float(v) for v in size))

    @property
    def sizes(self) -> tuple[float, float, float]:
        x, y, z = self.size
        return x / 2, y / 2, z / 2

    def _sizes_dict(self) -> dict[str, Any]:
        return {"size": list(self.size)}


@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class HalfSpace(Shape):
    """The solid ``z <= 0`` of the pose's frame (outward normal: the pose's z axis)."""

    kind = HALFSPACE

    @classmethod
    def plane(cls, normal: Sequence[float], offset: float = 0.0) -> HalfSpace:
        """The half-space ``normal . x <= offset`` (``normal`` need not be unit length)."""
        n = finite_array("half-space normal", normal, shape=(3,))
        norm = float(np.linalg.norm(n))
        if norm == 0:
            raise ParameterError("half-space normal must be non-zero, got [0, 0, 0]")
        pose = np.eye(4)
        pose[:3, :3] = _frame_with_z(n / norm)
        pose[:3, 3] = n / norm * (number("half-space offset", offset) / norm)
        return cls(pose=pose)

    @property
    def sizes(self) -> tuple[float, float, float]:
        return 0.0, 0.0, 0.0

    def __repr__(self) -> str:
        """As :meth:`plane` takes it: the unit outward normal and the offset along it."""
        n = self.pose[:3, 2]
        return f"HalfSpace(normal={_short(n.tolist())}, offset={_short(n @ self.pose[:3, 3])})"

    def _sizes_dict(self) -> dict[str, Any]:
        return {}


def cylinder(*, radius: float, length: float, pose: Any = None) -> Capsule:
    """A URDF cylinder (axis z, centred) as its enclosing capsule (see the module doc)."""
    return Capsule(radius=radius, length=length, pose=pose)


def _frame_with_z(z: np.ndarray) -> np.ndarray:
    """A rotation whose third column is the unit vector ``z``."""
    helper = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    return np.column_stack([x, np.cross(z, x), z])


def shape_arrays(shapes: Sequence[Shape], poses: np.ndarray | None = None
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Kinds ``(m,)`` int64, poses ``(m, 4, 4)`` and sizes ``(m, 3)`` of ``shapes``."""
    kinds = np.array([s.kind for s in shapes], dtype=np.int64)
    P = np.array([s.pose for s in shapes], dtype=float).reshape(len(shapes), 4, 4)
    sizes = np.array([s.sizes for s in shapes], dtype=float).reshape(len(shapes), 3)
    return kinds, np.ascontiguousarray(P if poses is None else poses), sizes
