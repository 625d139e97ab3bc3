"""Collision primitives: sphere, capsule, box, half-space, convex hull, compound.

Each shape is a frozen, validated value with a ``pose`` (``(4, 4)`` rigid transform
of the shape's own frame in the frame it is attached to: a link frame of a robot, or
the world for a scene's obstacle) and sizes in the robot's length unit:

* :class:`Sphere` ``(radius)`` centred at the pose's origin;
* :class:`Capsule` ``(radius, length)``: the points within ``radius`` of the segment of
  ``length`` along the pose's z axis, centred at its origin
  (:meth:`Capsule.between` builds one from two end points);
* :class:`Box` ``(size)``: full side lengths along the pose's x, y, z axes;
* :class:`HalfSpace`: the solid ``z <= 0`` of its pose, a table top or floor whose
  outward normal is the pose's z axis (:meth:`HalfSpace.plane` from normal and offset);
* :class:`ConvexHull` ``(points)``: the convex hull of points in its frame, a collision
  mesh's hull (:mod:`moik.collision.gjk` computes its distances);
* :class:`Compound` ``(bound, parts)``: convex hulls inside a bounding primitive, measured
  on the parts only where the bounds come close (a collision mesh cut in convex pieces).

:func:`cylinder` is a cylinder's enclosing capsule: the capsule of the same radius whose
segment is the cylinder's axis (it contains the cylinder and extends ``radius`` beyond
each flat end). A cylinder of a URDF, a scene file or ``moik.collision.cylinder`` is a
:class:`Compound` with that capsule as its bound and a prism that holds the cylinder as
its part (:mod:`moik.collision.prism`).

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
from moik.collision.distance import BOX, CAPSULE, HALFSPACE, HULL, SPHERE
from moik.exceptions import GeometryError, NonFiniteError, ParameterError
from moik.robots.checks import rigid_transform

__all__ = ["Box", "Capsule", "Compound", "ConvexHull", "HalfSpace", "Shape", "Sphere",
           "cylinder", "shape_arrays"]


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
        return (f"HalfSpace.plane(normal={_short(n.tolist())}, "
                f"offset={_short(n @ self.pose[:3, 3])})")

    def _sizes_dict(self) -> dict[str, Any]:
        return {}


@dataclass(frozen=True, eq=False, kw_only=True)
class ConvexHull(Shape):
    """The convex hull of ``points`` ``(n, 3)`` in the pose's frame: a collision mesh's hull
    (it holds the mesh: distances to it never exceed the mesh's; :mod:`moik.collision.gjk`).

    Only the hull's vertices are kept, centred on the middle of their bounding box (the
    pose takes the offset), so the bounding sphere the broad phase uses is small.
    """

    points: np.ndarray
    kind = HULL

    def __post_init__(self) -> None:
        super().__post_init__()
        P = finite_array("convex hull points", self.points)
        if P.ndim != 2 or P.shape[1] != 3 or len(P) == 0:
            raise ParameterError(f"convex hull points must have shape (n, 3) with n >= 1, "
                                 f"got {P.shape}")
        P = hull_vertices(P)
        centre = (P.min(axis=0) + P.max(axis=0)) / 2
        shift = np.eye(4)
        shift[:3, 3] = centre
        P = np.ascontiguousarray(P - centre)
        P.setflags(write=False)
        object.__setattr__(self, "points", P)
        object.__setattr__(self, "pose", self.pose @ shift)

    @property
    def sizes(self) -> tuple[float, float, float]:
        """``(hull index, bounding radius, 0)``: the index is set when a checker gathers its
        hulls (:class:`~moik.collision.CollisionChecker`)."""
        return 0.0, float(np.sqrt((self.points ** 2).sum(axis=1).max())), 0.0

    def moved(self, transform: Any) -> Shape:
        """The same hull with pose ``transform @ pose`` (its vertices as they are)."""
        T = rigid_transform("transform", finite_array("transform", transform, shape=(4, 4)))
        out = object.__new__(ConvexHull)
        object.__setattr__(out, "points", self.points)
        object.__setattr__(out, "pose", T @ self.pose)
        return out

    def _sizes_dict(self) -> dict[str, Any]:
        return {"points": self.points.tolist()}


MAX_PARTS = 62  # the kernels keep a compound's parts still in play as the bits of an int64


@dataclass(frozen=True, eq=False, kw_only=True)
class Compound(Shape):
    """A body's geometry as a ``bound`` (a sphere, capsule or box holding it) and convex
    ``parts`` inside the bound (the hulls of a collision mesh's pieces): a pair is measured on
    the bounds first and refined on the parts only when the bounds come close (the parts'
    smallest distance; never below the bounds', and never above the geometry's).

    The pose is the bound's; ``moved`` moves the parts with it.
    """

    bound: Shape
    parts: tuple[ConvexHull, ...]
    kind = -1  # the kernels see the bound and the parts, never a compound

    def __post_init__(self) -> None:
        if not isinstance(self.bound, (Sphere, Capsule, Box)):
            raise GeometryError(f"a compound's bound must be a Sphere, Capsule or Box, got "
                                f"{type(self.bound).__name__}")
        parts = tuple(self.parts)
        if not parts or not all(isinstance(p, ConvexHull) for p in parts):
            raise GeometryError("a compound's parts must be one or more ConvexHull shapes")
        if len(parts) > MAX_PARTS:
            raise GeometryError(f"a compound has at most {MAX_PARTS} parts, got {len(parts)}")
        object.__setattr__(self, "parts", parts)
        object.__setattr__(self, "pose", self.bound.pose)

    @property
    def sizes(self) -> tuple[float, float, float]:
        return self.bound.sizes

    def moved(self, transform: Any) -> Shape:
        """The compound with its bound and parts moved by ``transform``."""
        return Compound(bound=self.bound.moved(transform),
                        parts=tuple(p.moved(transform) for p in self.parts))  # type: ignore[misc]

    def to_dict(self) -> dict[str, Any]:
        return {"type": "compound", "bound": self.bound.to_dict(),
                "parts": [p.to_dict() for p in self.parts]}

    def _sizes_dict(self) -> dict[str, Any]:
        return {}


def hull_vertices(points: np.ndarray) -> np.ndarray:
    """The vertices of the convex hull of ``points`` ``(n, 3)`` (qhull through scipy); the
    distinct points themselves when they span no volume (flat or fewer than four)."""
    from scipy.spatial import ConvexHull as Qhull  # qhull loads at the first hull (start-up)
    from scipy.spatial import QhullError

    unique = np.unique(points, axis=0)
    if len(unique) < 4:
        return unique
    try:
        return unique[np.sort(Qhull(unique).vertices)]
    except QhullError:  # flat or degenerate: every distinct point (GJK takes any point set)
        return unique


def cylinder(*, radius: float, length: float, pose: Any = None) -> Capsule:
    """The enclosing capsule of a cylinder (axis z, centred; see the module doc): the bound
    of :func:`moik.collision.prism.cylinder_compound`."""
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


def hull_arrays(shapes: Sequence[Shape], sizes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The vertices of the hulls among ``shapes``, gathered for the kernels: ``hull_points
    (v, 3)`` and ``hull_ranges (h, 2)`` (rows ``start:end`` of each hull); each hull's
    index is written into ``sizes[k, 0]`` (``sizes`` of :func:`shape_arrays`)."""
    hulls = [(k, s) for k, s in enumerate(shapes) if isinstance(s, ConvexHull)]
    for h, (k, _) in enumerate(hulls):
        sizes[k, 0] = h
    counts = np.array([len(s.points) for _, s in hulls], dtype=np.int64)
    ends = np.cumsum(counts)
    ranges = np.ascontiguousarray(np.column_stack([ends - counts, ends]).reshape(-1, 2),
                                  dtype=np.int64)
    points = np.concatenate([s.points for _, s in hulls]) if hulls else np.zeros((0, 3))
    return np.ascontiguousarray(points, dtype=np.float64), ranges


def hull_capsules(shapes: Sequence[Shape]) -> np.ndarray:
    """A capsule holding each hull among ``shapes`` (in its frame), ``(h, 8)``: centre,
    unit axis, half length, radius. The axis is the points' principal axis, the radius
    their largest distance from it, the segment as short as the radius allows (every point
    within the radius of it): the kernels' cheap lower bound of a pair of hulls."""
    out = [hull_capsule(s.points) for s in shapes if isinstance(s, ConvexHull)]
    return np.ascontiguousarray(np.array(out, dtype=np.float64).reshape(-1, 8))


def hull_capsule(points: np.ndarray) -> np.ndarray:
    """``(centre (3), axis (3), half length, radius)`` of a capsule holding ``points``."""
    mean = points.mean(axis=0)
    centred = points - mean
    axis = np.linalg.eigh(centred.T @ centred)[1][:, 2]
    t = centred @ axis
    perp = np.sqrt(np.maximum((centred ** 2).sum(axis=1) - t ** 2, 0.0))
    radius = float(perp.max()) * (1 + 1e-12) + 1e-12  # rounding: never a point outside
    slack = np.sqrt(np.maximum(radius ** 2 - perp ** 2, 0.0))
    # a point is within the radius of the segment [t0, t1] iff t_i - slack_i <= t1 and
    # t0 <= t_i + slack_i: the shortest one runs from lo to hi (a point when hi <= lo)
    lo, hi = float((t + slack).min()), float((t - slack).max())
    t0, t1 = ((hi + lo) / 2, (hi + lo) / 2) if hi <= lo else (lo, hi)
    centre, half = mean + axis * (t0 + t1) / 2, (t1 - t0) / 2
    w = np.clip((points - centre) @ axis, -half, half)  # the points' distances, measured
    reach = float(np.linalg.norm(points - (centre + w[:, None] * axis), axis=1).max())
    return np.array([*centre, *axis, half, max(radius, reach * (1 + 1e-12) + 1e-12)])


def expand_compounds(tops: Sequence[Shape], bodies: Sequence[int]
                     ) -> tuple[list[Shape], list[int], list[list[int]]]:
    """The shapes the kernels see: ``tops`` (each :class:`Compound` by its bound) followed by
    the compounds' parts; their bodies; and for each top, the kernel indices of its parts
    (``[t]`` itself when it is not a compound)."""
    shapes = [s.bound if isinstance(s, Compound) else s for s in tops]
    out_bodies = list(bodies)
    parts: list[list[int]] = []
    for t, s in enumerate(tops):
        if isinstance(s, Compound):
            parts.append(list(range(len(shapes), len(shapes) + len(s.parts))))
            shapes += list(s.parts)
            out_bodies += [bodies[t]] * len(s.parts)
        else:
            parts.append([t])
    return shapes, out_bodies, parts


def refinements(pairs: Sequence[tuple[int, int]], parts: Sequence[Sequence[int]]
                ) -> np.ndarray:
    """For each pair of tops, the parts that refine it, ``(p, 4)``: the first kernel index
    and the number of each side's parts (a compound's are consecutive; a plain shape is its
    own one part), or zeros when neither top is a compound (the pair is measured as it is)."""
    refine = np.zeros((len(pairs), 4), dtype=np.int64)
    for k, (a, b) in enumerate(pairs):
        if parts[a] != [a] or parts[b] != [b]:
            refine[k] = parts[a][0], len(parts[a]), parts[b][0], len(parts[b])
    return refine
