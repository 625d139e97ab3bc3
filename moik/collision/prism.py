"""A cylinder as a compound: its enclosing capsule, and a prism that holds it.

Every cylinder moik reads is this compound: a URDF's ``<cylinder>``
(:mod:`moik.collision.urdf`), a scene or capsule-model file's ``"cylinder"``
(:mod:`moik.collision.io`) and ``moik.collision.cylinder``. The enclosing capsule
(:func:`moik.collision.shapes.cylinder`) reaches ``radius`` beyond each flat end of the
cylinder. For a link whose collision geometry is cylinders (a Unitree Z1 in
example-robot-data: its wrist's two cylinders face each other end to end, 1.5 cm apart,
with the next link between them), those caps overlap in every configuration, so a capsule
model rejects every configuration, free or not. Here the capsule is only the bound
(:class:`~moik.collision.shapes.Compound`): where two bounds come close, the pair is
measured on the compound's one part, the right prism on the regular :data:`SIDES`-gon
circumscribed about the cylinder's cross-section (its sides touch the circle, so the prism
holds the cylinder: sound), at most ``radius * (1 / cos(pi / SIDES) - 1)`` outside it
(0.5 % of the radius) and nowhere beyond its flat ends.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from moik.collision.shapes import Compound, ConvexHull, cylinder

SIDES = 32  # sides of the prism's cross-section


def prism_points(radius: float, length: float) -> np.ndarray:
    """The ``2 * SIDES`` corners of the prism holding the cylinder of ``radius`` and
    ``length`` (axis z, centred), in the cylinder's frame."""
    angle = 2.0 * np.pi * np.arange(SIDES) / SIDES
    corner = radius / np.cos(np.pi / SIDES)  # the circumscribed polygon's vertex radius
    ring = np.column_stack([corner * np.cos(angle), corner * np.sin(angle)])
    half = length / 2.0
    return np.vstack([np.column_stack([ring, np.full(SIDES, -half)]),
                      np.column_stack([ring, np.full(SIDES, half)])])


def cylinder_compound(*, radius: float, length: float, pose: Any = None) -> Compound:
    """The cylinder of ``radius`` and ``length`` (axis z, centred at ``pose``) as a
    :class:`~moik.collision.shapes.Compound`: its enclosing capsule as the bound, the prism
    of :func:`prism_points` as the one part (module docstring). Sizes and pose are
    validated as the capsule's."""
    bound = cylinder(radius=radius, length=length, pose=pose)
    part = ConvexHull(points=prism_points(bound.radius, bound.length), pose=bound.pose)
    return Compound(bound=bound, parts=(part,))
