"""Collision geometry: primitives, robot models, scenes and compiled signed distances.

``CollisionModel`` (shapes on a robot's link frames plus an allowed-collision matrix),
``Scene`` (obstacles in the world), ``CollisionChecker`` (both compiled: batched
distances, their minimum and its gradient). ``collision_model(name)``: the shipped
capsule model of a catalog arm; ``load_scene``/``load_model``: JSON files;
``model_from_urdf``: a URDF's ``<collision>`` primitives.
"""

from moik.collision.catalog import collision_model, shipped_models
from moik.collision.io import load_model, load_scene
from moik.collision.model import CollisionChecker, CollisionModel, Scene, default_links
from moik.collision.shapes import Box, Capsule, HalfSpace, Shape, Sphere, cylinder
from moik.collision.urdf import model_from_urdf

__all__ = ["Box", "Capsule", "CollisionChecker", "CollisionModel", "HalfSpace", "Scene", "Shape",
           "Sphere", "collision_model", "cylinder", "default_links", "load_model", "load_scene",
           "model_from_urdf", "shipped_models"]
