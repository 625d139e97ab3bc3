"""The exact stage: pairs the bounding shapes cannot separate, measured on convex hulls.

A model built from a URDF's meshes (:func:`moik.collision.urdf.model_from_urdf`) bounds
each link's meshes by capsules; :data:`HULLS` keeps, for each such capsule, the vertices
of the convex hull of the triangles it encloses (in the frame of its body). For a pair
whose capsule distance is below a threshold (the clearance asked for), the
:class:`ExactStage` measures a lower bound on the distance of the two convex hulls with
the compiled GJK of :mod:`moik.collision.gjk` (a primitive shape is its own hull: a
sphere its centre and radius, a capsule its end points and radius, a box its corners; a
half-space obstacle is measured exactly), and keeps the larger of the two lower bounds.

Sound: the hull contains the meshes, the capsule contains the hull, and both numbers
are lower bounds of the meshes' distance, so a configuration called free keeps the
clearance for the meshes. Tight: the hull is far closer to a link's shape than one
capsule (UR5's, iiwa's and panda's links: the capsules reject 29 to 100 % of the
mesh-free configurations, ``studies/mesh_collision_check.py``).

This module calls the checker's public methods from Python (per configuration and pair);
the solver's compiled start loop does not use it yet.
"""

from __future__ import annotations

from typing import Any
from weakref import WeakKeyDictionary

import numpy as np

from moik.collision.fit import hull_vertices
from moik.collision.gjk import halfspace_distance, hull_distance_bound
from moik.collision.model import CollisionChecker
from moik.collision.shapes import Box, Capsule, HalfSpace, Shape, Sphere

HULLS: WeakKeyDictionary[Shape, list[np.ndarray]] = WeakKeyDictionary()
"""Fitted capsule -> the vertices of the convex hulls of the pieces of its link's meshes
(:func:`hull_pieces`), in its body's frame."""


def hull_pieces(vertices: np.ndarray, faces: np.ndarray, pieces: int) -> list[np.ndarray]:
    """The vertices of the convex hulls of ``pieces`` slabs of a mesh's triangles: the
    triangles sorted by their centroids along the mesh's principal axis and cut into
    groups of equal count (a triangle belongs to one group, so the hulls enclose the mesh;
    a concave link, e.g. an upper arm with its joint housings, is followed far closer by
    several hulls than by one)."""
    centroids = vertices[faces].mean(axis=1)
    centred = centroids - centroids.mean(axis=0)
    _, vectors = np.linalg.eigh(centred.T @ centred)
    order = np.argsort(centroids @ vectors[:, 2], kind="stable")
    out = []
    for group in np.array_split(order, min(pieces, len(faces))):
        out.append(np.ascontiguousarray(hull_vertices(vertices[np.unique(faces[group])])))
    return out


def _points(shape: Shape) -> tuple[np.ndarray, float]:
    """A primitive as (points in the frame it is attached to, sweeping radius)."""
    if isinstance(shape, Sphere):
        return shape.pose[None, :3, 3].copy(), shape.radius
    if isinstance(shape, Capsule):
        return np.array(shape.ends), shape.radius
    if isinstance(shape, Box):
        corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
        local = corners * np.asarray(shape.size) / 2
        return local @ shape.pose[:3, :3].T + shape.pose[:3, 3], 0.0
    raise TypeError(type(shape).__name__)


class ExactStage:
    """A checker's pairs, refined on convex hulls where the bounds come within ``below``.

    Args:
        checker: The :class:`CollisionChecker` (its model's fitted capsules are looked up
            in :data:`HULLS`; other shapes are their own hulls).
    """

    def __init__(self, checker: CollisionChecker) -> None:
        self.checker = checker
        model = checker.model
        self._robot: list[tuple[int, list[np.ndarray], float]] = []
        for body, shape in model.items:
            hulls = HULLS.get(shape)
            if hulls is not None:
                self._robot.append((body, hulls, 0.0))
            else:
                points, radius = _points(shape)
                self._robot.append((body, [np.ascontiguousarray(points, dtype=float)], radius))
        self._centres = [np.array([P.mean(axis=0) for P in hulls]) for _, hulls, _ in self._robot]
        self._reach = [np.array([np.linalg.norm(P - P.mean(axis=0), axis=1).max() for P in hulls])
                       for _, hulls, _ in self._robot]
        self._obstacles: list[Any] = []
        for shape in ([] if checker.scene is None else checker.scene.obstacles.values()):
            if isinstance(shape, HalfSpace):
                self._obstacles.append(("plane", shape.pose[:3, 2].copy(),
                                        float(shape.pose[:3, 2] @ shape.pose[:3, 3])))
            else:
                points, radius = _points(shape)
                self._obstacles.append(("hull", np.ascontiguousarray(points), radius))
        names = checker.shape_names
        index = {name: k for k, name in enumerate(names)}
        self._pairs = [(index[a], index[b]) for a, b in checker.pair_names]

    def _placed(self, k: int, frames: np.ndarray) -> tuple[list[np.ndarray], np.ndarray,
                                                            np.ndarray, float]:
        """Shape ``k``'s hull pieces placed at ``frames``, their bounding spheres' centres
        and radii, and the sweeping radius."""
        body, hulls, r = self._robot[k]
        F = frames[body]
        placed = [np.ascontiguousarray(P @ F[:3, :3].T + F[:3, 3]) for P in hulls]
        return placed, self._centres[k] @ F[:3, :3].T + F[:3, 3], self._reach[k], r

    def _pair_bound(self, a: tuple, b: tuple) -> float:
        """The smallest GJK bound over the piece pairs; piece pairs whose bounding
        spheres are farther apart than the smallest bound found are skipped (their
        distance cannot be smaller)."""
        As, ca, qa, ra = a
        Bs, cb, qb, rb = b
        spheres = (np.linalg.norm(ca[:, None] - cb[None], axis=2) - qa[:, None] - qb[None]
                   - ra - rb)
        best = np.inf
        for flat in np.argsort(spheres, axis=None):
            i, j = divmod(int(flat), len(Bs))
            if spheres[i, j] >= best:
                break
            best = min(best, hull_distance_bound(As[i], ra, Bs[j], rb))
            if best == -np.inf:
                break
        return best

    def distances(self, Q: Any, below: float = 0.0) -> np.ndarray:
        """Per pair, the larger of the bounding-shape distance and the hull bound (the
        hull bound computed only where the former is below ``below``): ``(n, n_pairs)``."""
        Q2 = np.atleast_2d(self.checker.robot.check_q(Q))
        D = np.atleast_2d(self.checker.distances(Q2)).copy()
        frames = self.checker.robot.frames(Q2)
        frames = frames[None] if frames.ndim == 3 else frames
        n_robot = len(self._robot)
        for i, j in zip(*np.nonzero(np.less(D, below)), strict=True):
            a, b = self._pairs[j]
            A = self._placed(a, frames[i])
            if b < n_robot:
                bound = self._pair_bound(A, self._placed(b, frames[i]))
            else:
                kind, x, y = self._obstacles[b - n_robot]
                bound = min(halfspace_distance(P, A[3], x, y) if kind == "plane"
                            else hull_distance_bound(P, A[3], x, y) for P in A[0])
            D[i, j] = max(D[i, j], bound)
        return D

    def min_distance(self, Q: Any, below: float = 0.0) -> np.ndarray:
        """The smallest of :meth:`distances` per configuration, ``(n,)`` (``inf``: no pair)."""
        D = self.distances(Q, below)
        return D.min(axis=1) if D.shape[1] else np.full(len(D), np.inf)
