"""Convex polygons (a mesh's triangles and their parts) split by a plane: Sutherland-Hodgman.

:class:`Polygons` holds many convex polygons as one padded array; :func:`split` cuts each by
the plane ``n . x = d`` into its part on each side, vectorised over the polygons. The two
parts of a polygon are exactly the polygon (up to the rounding of the crossing points,
``a + t (b - a)``, a few units in the last place; :func:`split`), so the pieces of a mesh cut by any
sequence of planes tile its surface: the convex hulls of the pieces hold the mesh
(:mod:`moik.collision.decompose`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

SNAP = 1e-9  # relative: a corner this close to the plane is on it (no sliver beside it)


class Polygons(NamedTuple):
    """Convex polygons: ``corners`` ``(k, m, 3)`` (the first ``counts[i]`` of row ``i`` in
    order around the polygon, the rest padding) and ``counts`` ``(k,)``."""

    corners: np.ndarray
    counts: np.ndarray

    @staticmethod
    def of_triangles(triangles: np.ndarray) -> Polygons:
        """Triangles ``(k, 3, 3)`` as polygons."""
        return Polygons(np.array(triangles, dtype=float), np.full(len(triangles), 3))

    def points(self) -> np.ndarray:
        """Every polygon's corners ``(n, 3)``."""
        m = self.corners.shape[1]
        return self.corners[np.arange(m)[None, :] < self.counts[:, None]]

    def centroids(self) -> np.ndarray:
        """The mean of each polygon's corners ``(k, 3)``."""
        m = self.corners.shape[1]
        valid = np.arange(m)[None, :] < self.counts[:, None]
        return (self.corners * valid[:, :, None]).sum(axis=1) / self.counts[:, None]


def _side(P: np.ndarray, X: np.ndarray, keep: np.ndarray, cross: np.ndarray) -> Polygons:
    """The polygons made of, edge by edge, the corner where ``keep`` and the crossing point
    where ``cross``; rows with no corner left are dropped."""
    k, m = keep.shape
    if k == 0:
        return Polygons(np.zeros((0, max(m, 1), 3)), np.zeros(0, dtype=np.int64))
    V = np.stack([P, X], axis=2).reshape(k, 2 * m, 3)
    mask = np.stack([keep, cross], axis=2).reshape(k, 2 * m)
    counts = mask.sum(axis=1)
    rows = np.flatnonzero(counts > 0)
    order = np.argsort(~mask[rows], axis=1, kind="stable")[:, :max(int(counts.max()), 1)]
    return Polygons(np.ascontiguousarray(V[rows[:, None], order]), counts[rows])


def split(polygons: Polygons, normal: np.ndarray, offset: float) -> tuple[Polygons, Polygons]:
    """The parts of the polygons with ``normal . x <= offset`` and with ``>= offset``
    (a corner on the plane belongs to both; a polygon with no part on a side is not in it).

    A corner within :data:`SNAP` (relative) of the plane counts as on it: it is a corner of
    both parts and no crossing point is made beside it (which would leave a sliver facet in
    the pieces' hulls). The two parts still tile the polygon exactly (they share the chain
    of crossing points and such corners); the part below then reaches that far above the
    plane, which costs nothing in soundness."""
    P, c = polygons
    k, m = P.shape[:2]
    j = np.arange(m)
    valid = j[None, :] < c[:, None]
    s = P @ np.asarray(normal, dtype=float) - offset
    scale = float(np.abs(P[valid]).max()) if k else 0.0
    s[np.abs(s) <= SNAP * (scale + abs(offset))] = 0.0  # on the plane: a corner of both parts
    nxt = np.where(j[None, :] + 1 < c[:, None], j[None, :] + 1, 0)
    rows = np.arange(k)[:, None]
    Q, sq = P[rows, nxt], s[rows, nxt]
    cross = valid & (((s < 0) & (sq > 0)) | ((s > 0) & (sq < 0)))
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(cross, s / (s - sq), 0.0)
    X = P + t[:, :, None] * (Q - P)
    return (_side(P, X, valid & (s <= 0), cross), _side(P, X, valid & (s >= 0), cross))
