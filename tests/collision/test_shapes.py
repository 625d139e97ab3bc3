"""Primitives validate their sizes and poses; cylinders are their enclosing capsules."""

import numpy as np
import pytest

from moik.collision.shapes import Box, Capsule, HalfSpace, Sphere, cylinder, shape_arrays
from moik.exceptions import NonFiniteError, ParameterError, ShapeError


def test_bad_sizes_raise():
    with pytest.raises(ParameterError, match="radius must be >= 0"):
        Sphere(radius=-0.1)
    with pytest.raises(NonFiniteError):
        Capsule(radius=float("nan"), length=0.2)
    with pytest.raises(ParameterError, match="box size must be 3 lengths > 0"):
        Box(size=(0.1, 0.0, 0.1))
    with pytest.raises(ShapeError):
        Box(size=(0.1, 0.2))
    with pytest.raises(ParameterError, match="rigid transform"):
        Sphere(radius=0.1, pose=np.diag([2.0, 1, 1, 1]))
    with pytest.raises(ParameterError, match="normal must be non-zero"):
        HalfSpace.plane([0, 0, 0])


def test_capsule_between_and_halfspace_plane():
    c = Capsule.between([0, 0, 0], [0, 0.3, 0.4], 0.05)
    a, b = c.ends
    assert c.length == pytest.approx(0.5)
    assert np.allclose(a, [0, 0, 0]) and np.allclose(b, [0, 0.3, 0.4])
    h = HalfSpace.plane([0, 0, 2.0], 1.0)  # 2 z <= 1: the plane z = 0.5
    assert np.allclose(h.pose[:3, 3], [0, 0, 0.5]) and np.allclose(h.pose[:3, 2], [0, 0, 1])
    cyl = cylinder(radius=0.1, length=0.4)
    assert isinstance(cyl, Capsule) and cyl.sizes == (0.1, 0.2, 0.0)


def test_shape_arrays_and_moved():
    s = Sphere(radius=0.2).moved(np.diag([1.0, 1, 1, 1]) + np.eye(4, k=3) * 0)
    kinds, P, sizes = shape_arrays([s, Box(size=(0.2, 0.4, 0.6))])
    assert kinds.tolist() == [0, 2] and P.shape == (2, 4, 4)
    assert sizes[1].tolist() == [0.1, 0.2, 0.3]
