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

The kernels (:mod:`moik.collision.exact_kernels`) take the arrays of
:attr:`ExactStage.arrays` and the body frames; the solver's compiled start loop does not
call them yet.
"""

from __future__ import annotations

from typing import Any
from weakref import WeakKeyDictionary

import numpy as np

from moik.collision.exact_kernels import refine_distances
from moik.collision.fit import hull_vertices
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
        pieces: list[list[np.ndarray]] = []
        body, radius, plane, normal, offset = [], [], [], [], []
        for b, shape in checker.model.items:
            hulls = HULLS.get(shape)
            if hulls is None:
                points, r = _points(shape)
                hulls = [points]
            else:
                r = 0.0
            pieces.append(hulls)
            body.append(b)
            radius.append(r)
        obstacles = {} if checker.scene is None else checker.scene.obstacles
        for shape in obstacles.values():
            body.append(-1)
            if isinstance(shape, HalfSpace):
                pieces.append([])
                radius.append(0.0)
            else:
                points, r = _points(shape)
                pieces.append([points])
                radius.append(r)
        for shape in [s for _, s in checker.model.items] + list(obstacles.values()):
            flat = isinstance(shape, HalfSpace)
            n = shape.pose[:3, 2] if flat else np.zeros(3)
            plane.append(1 if flat else 0)
            normal.append(n)
            offset.append(float(n @ shape.pose[:3, 3]) if flat else 0.0)
        flat_pieces = [P for group in pieces for P in group]
        piece_start = np.cumsum([0] + [len(group) for group in pieces])
        point_start = np.cumsum([0] + [len(P) for P in flat_pieces])
        centres = np.array([P.mean(axis=0) for P in flat_pieces]).reshape(-1, 3)
        reach = np.array([np.linalg.norm(P - c, axis=1).max()
                          for P, c in zip(flat_pieces, centres, strict=True)])
        points = np.vstack(flat_pieces) if flat_pieces else np.zeros((0, 3))
        self.arrays = (np.array(body, dtype=np.int64), np.array(radius, dtype=float),
                       np.array(plane, dtype=np.int64),
                       np.array(normal, dtype=float).reshape(-1, 3),
                       np.array(offset, dtype=float), piece_start.astype(np.int64),
                       point_start.astype(np.int64), np.ascontiguousarray(points, dtype=float),
                       np.ascontiguousarray(centres, dtype=float), reach.astype(float))
        """The kernels' arrays (:mod:`moik.collision.exact_kernels` documents them)."""
        self.pairs = np.ascontiguousarray(checker.arrays["pairs"], dtype=np.int64)

    def distances(self, Q: Any, below: float = 0.0) -> np.ndarray:
        """Per pair, the larger of the bounding-shape distance and the hull bound (the
        hull bound computed only where the former is below ``below``): ``(n, n_pairs)``.
        Every entry is a lower bound of the meshes' distance, and it is ``>= below``
        exactly when the pair's hulls keep ``below``; the hull bounds are not converged
        further than that decision needs."""
        Q2 = np.atleast_2d(self.checker.robot.check_q(Q))
        D = np.ascontiguousarray(np.atleast_2d(self.checker.distances(Q2)), dtype=float)
        frames = np.ascontiguousarray(self.checker.robot.frames(Q2).reshape(
            len(Q2), -1, 4, 4))
        refine_distances(self.arrays, frames, D, self.pairs, float(below))
        return D

    def min_distance(self, Q: Any, below: float = 0.0) -> np.ndarray:
        """The smallest of :meth:`distances` per configuration, ``(n,)`` (``inf``: no pair)."""
        D = self.distances(Q, below)
        return D.min(axis=1) if D.shape[1] else np.full(len(D), np.inf)
