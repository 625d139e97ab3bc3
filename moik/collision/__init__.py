"""Collision geometry: primitives, robot models, scenes and compiled signed distances.

``CollisionModel`` (shapes on a robot's link frames plus an allowed-collision matrix),
``Scene`` (obstacles in the world), ``CollisionChecker`` (both compiled: batched
distances, their minimum and its gradient). Shipped capsule models of the catalog arms:
:func:`moik.collision.catalog.collision_model`.
"""

from moik.collision.model import CollisionChecker, CollisionModel, Scene, default_links
from moik.collision.shapes import Box, Capsule, HalfSpace, Shape, Sphere, cylinder

__all__ = ["Box", "Capsule", "CollisionChecker", "CollisionModel", "HalfSpace", "Scene", "Shape",
           "Sphere", "cylinder", "default_links"]
