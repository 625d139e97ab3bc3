"""The enclosing polytope of a high-poly hull (moik/collision/outer_hull.py): it holds
every point (soundness of the exact stage), has fewer vertices, and lies within about
OUTER_TOL of the hull (the nearest hull point found by non-negative least squares)."""

from __future__ import annotations

import numpy as np
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import nnls
from scipy.spatial import ConvexHull

from moik.collision.outer_hull import MAX_EXACT_VERTICES, OUTER_TOL, enclosing_polytope


def _holds(W: np.ndarray, P: np.ndarray) -> bool:
    """Every point of ``P`` inside the hull of ``W`` (to qhull's rounding of its planes)."""
    eq = ConvexHull(W).equations
    return bool((P @ eq[:, :3].T + eq[:, 3]).max() <= 1e-12 * np.abs(P).max())


def _distance_to_hull(w: np.ndarray, V: np.ndarray) -> float:
    """The distance of ``w`` to the hull of ``V`` (a convex combination, the weights'
    sum held at 1 by a heavy row)."""
    lam, _ = nnls(np.vstack([V.T, 1e3 * np.ones(len(V))]), np.r_[w, 1e3])
    return float(np.linalg.norm(V.T @ lam - w))


def test_a_small_hull_is_kept_exactly():
    P = trimesh.creation.icosphere(subdivisions=1).vertices * 0.05  # 42 vertices
    W = enclosing_polytope(P)
    assert len(W) == 42 and {tuple(v) for v in W} == {tuple(v) for v in P}


def test_a_high_poly_hull_is_replaced_by_a_tight_enclosing_polytope():
    """A 2,562-vertex ellipsoid (5 x 8 x 20 cm) and a slab of it (sharp rims where it is cut)."""
    P = trimesh.creation.icosphere(subdivisions=4).vertices * [0.05, 0.08, 0.2]
    for pts in (P, P[np.abs(P[:, 2]) < 0.03]):
        W = enclosing_polytope(pts)
        V = pts[ConvexHull(pts).vertices]
        assert len(V) > MAX_EXACT_VERTICES and len(W) < len(V)
        assert _holds(W, pts)
        assert max(_distance_to_hull(w, V) for w in W) <= 2 * OUTER_TOL


def test_flat_points_are_returned_as_given():
    P = np.c_[np.random.default_rng(0).uniform(size=(300, 2)), np.zeros(300)]
    assert np.array_equal(enclosing_polytope(P), P)


@settings(max_examples=25, deadline=None)
@given(st.integers(0, 10_000), st.floats(0.01, 2.0), st.integers(150, 600))
def test_every_point_is_inside(seed, size, n):
    """Noisy points on an ellipsoid (most on the hull), any scale: all inside."""
    rng = np.random.default_rng(seed)
    u = rng.normal(size=(n, 3))
    P = u / np.linalg.norm(u, axis=1, keepdims=True) * rng.uniform(0.3, 1.0, 3) * size
    P *= 1 + rng.uniform(-0.01, 0.0, (n, 1))
    W = enclosing_polytope(P)
    assert _holds(W, P)
