"""Convex polygons split by a plane (moik.collision.clip): the two parts tile the polygon."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision.clip import SNAP, Polygons, split


def _areas(polygons: Polygons) -> np.ndarray:
    """Each polygon's area (a fan of triangles from its first corner)."""
    P, c = polygons
    out = np.zeros(len(c))
    for i, n in enumerate(c):
        for k in range(1, n - 1):
            out[i] += 0.5 * np.linalg.norm(np.cross(P[i, k] - P[i, 0], P[i, k + 1] - P[i, 0]))
    return out


coordinates = st.floats(-1.0, 1.0, allow_nan=False)


@settings(max_examples=30, deadline=None)
@given(corners=st.lists(st.tuples(*[coordinates] * 9), min_size=1, max_size=6),
       normal=st.tuples(*[coordinates] * 3).filter(lambda n: np.linalg.norm(n) > 1e-3),
       offset=st.floats(-1.0, 1.0), again=st.tuples(*[coordinates] * 3))
def test_the_two_parts_tile_each_polygon(corners, normal, offset, again):
    """Split twice (so the parts are polygons of more than three corners): on each side the
    corners keep to the side (or within SNAP of the plane), and the areas of the parts add
    up to the polygon's."""
    T = np.array(corners, dtype=float).reshape(-1, 3, 3)
    whole = _areas(Polygons.of_triangles(T)).sum()
    n = np.array(normal) / np.linalg.norm(normal)
    below, above = split(Polygons.of_triangles(T), n, offset)
    snap = SNAP * (np.abs(T).max() + abs(offset))  # a corner that close counts as on it
    for part, sign in ((below, 1.0), (above, -1.0)):
        assert (sign * (part.points() @ n - offset) <= snap + 1e-15).all()
    assert np.isclose(_areas(below).sum() + _areas(above).sum(), whole, rtol=1e-9, atol=1e-12)
    m = np.array(again)
    if np.linalg.norm(m) > 1e-3:
        parts = [*split(below, m, 0.1), *split(above, m, 0.1)]
        assert np.isclose(sum(_areas(p).sum() for p in parts), whole, rtol=1e-9, atol=1e-12)


def test_a_triangle_cut_through_two_edges():
    T = np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0]]], dtype=float)
    below, above = split(Polygons.of_triangles(T), np.array([1.0, 0, 0]), 0.5)
    assert below.counts.tolist() == [4] and above.counts.tolist() == [3]
    assert np.allclose(above.points(), [[0.5, 0, 0], [1, 0, 0], [0.5, 0.5, 0]])


def test_a_polygon_wholly_on_one_side_is_not_on_the_other():
    T = np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[3, 0, 0], [4, 0, 0], [3, 1, 0]]], float)
    below, above = split(Polygons.of_triangles(T), np.array([1.0, 0, 0]), 2.0)
    assert len(below.counts) == 1 and len(above.counts) == 1
