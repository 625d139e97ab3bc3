"""The smallest circle (moik/collision/circle.py) against a brute force over the circles
on every pair and triple of points (the smallest circle is one of them)."""

from __future__ import annotations

import itertools

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision.circle import smallest_circle_centre


def _brute_radius(X: np.ndarray) -> float:
    """The radius of the smallest circle around ``X``: the smallest of the circles on two
    or three of the points that hold them all."""
    best = np.inf
    cands = [(X[i] + X[j]) / 2 for i, j in itertools.combinations(range(len(X)), 2)]
    for i, j, k in itertools.combinations(range(len(X)), 3):
        a, b = X[j] - X[i], X[k] - X[i]
        den = 2.0 * (a[0] * b[1] - a[1] * b[0])
        if abs(den) > 1e-12:
            a2, b2 = a @ a, b @ b
            cands.append(X[i] + np.array([b[1] * a2 - a[1] * b2, a[0] * b2 - b[0] * a2]) / den)
    for c in cands or [X[0]]:
        best = min(best, float(np.linalg.norm(X - c, axis=1).max()))
    return best


points = st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=1, max_size=9)


@settings(max_examples=150, deadline=None)
@given(points)
def test_the_circle_is_the_smallest_around_the_points(raw):
    X = np.array(raw, dtype=float) / 10.0  # many ties, duplicates and collinear triples
    c = np.array(smallest_circle_centre(X))
    radius = float(np.linalg.norm(X - c, axis=1).max())
    assert radius <= _brute_radius(X) * (1 + 1e-9) + 1e-12


def test_a_large_cloud_and_its_order():
    """Thousands of points near one circle (a hull's vertices seen along an axis): the
    centre is the circle's, and the same on every call."""
    rng = np.random.default_rng(3)
    angle = rng.uniform(0, 2 * np.pi, 20_000)
    X = np.c_[np.cos(angle), np.sin(angle)] * (1 - rng.uniform(0, 1e-3, 20_000)[:, None]) + [2, -1]
    c = smallest_circle_centre(X)
    assert np.allclose(c, [2, -1], atol=1e-3)
    assert smallest_circle_centre(X) == c
