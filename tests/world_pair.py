"""moik's compiled distance of two shapes placed in the world (compounds measured on their
parts), shared by the tests of the GJK and of the cylinder's prism."""

from __future__ import annotations

import numpy as np

from moik.collision.compiled import collision_set
from moik.collision.kernels import pair_distances
from moik.collision.shapes import expand_compounds, hull_arrays, refinements, shape_arrays
from moik.robots import get_robot

ROBOT = get_robot("planar2")  # any arm: both shapes are in the world (body -1)


def world_pair(A, B) -> tuple:
    """``(distance, collision set)`` of shapes ``A`` and ``B``, both placed in the world."""
    shapes, bodies, parts = expand_compounds([A, B], [-1, -1])
    kinds, local, sizes = shape_arrays(shapes)
    points, ranges = hull_arrays(shapes, sizes)
    cs = collision_set(chain=ROBOT.chain_model, body=np.array(bodies), local=local,
                       kinds=kinds, sizes=sizes, pairs=np.array([[0, 1]]), hull_points=points,
                       hull_ranges=ranges, refine=refinements([(0, 1)], parts))
    out = np.empty((1, 1))
    pair_distances(cs, np.zeros((1, ROBOT.dof)), out)
    return out[0, 0], cs
