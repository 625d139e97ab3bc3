"""Collision geometry: primitives, robot models, scenes and compiled signed distances.

``CollisionModel`` (shapes on a robot's link frames plus an allowed-collision matrix),
``Scene`` (obstacles in the world), ``CollisionChecker`` (both compiled: batched
distances, their minimum and its gradient). ``collision_model(name)``: the shipped
capsule model of a catalog arm; ``load_scene``/``load_model``: JSON files;
``model_from_urdf``: a URDF's ``<collision>`` geometry (primitives, and each link's meshes
a ``Compound``: a fitted enclosing capsule holding the convex hulls of pieces of the meshes,
measured by :mod:`moik.collision.gjk` where the capsules come close). ``cylinder``: a
cylinder as a ``Compound`` too (its enclosing capsule holding a prism that holds it,
:mod:`moik.collision.prism`), in URDFs, scene files and capsule-model files alike.
"""

from typing import TYPE_CHECKING

from moik._lazy import lazy_names

if TYPE_CHECKING:
    from moik.collision.catalog import collision_model, shipped_models
    from moik.collision.io import load_model, load_scene
    from moik.collision.model import CollisionChecker, CollisionModel, Scene, default_links
    from moik.collision.prism import cylinder_compound as cylinder
    from moik.collision.shapes import Box, Capsule, ConvexHull, HalfSpace, Shape, Sphere
    from moik.collision.urdf import model_from_urdf

_LAZY: dict[str, tuple[str, str | None]] = {
    "collision_model": ("moik.collision.catalog", "collision_model"),
    "shipped_models": ("moik.collision.catalog", "shipped_models"),
    "load_model": ("moik.collision.io", "load_model"),
    "load_scene": ("moik.collision.io", "load_scene"),
    "CollisionChecker": ("moik.collision.model", "CollisionChecker"),
    "CollisionModel": ("moik.collision.model", "CollisionModel"),
    "Scene": ("moik.collision.model", "Scene"),
    "default_links": ("moik.collision.model", "default_links"),
    "Box": ("moik.collision.shapes", "Box"),
    "Capsule": ("moik.collision.shapes", "Capsule"),
    "ConvexHull": ("moik.collision.shapes", "ConvexHull"),
    "HalfSpace": ("moik.collision.shapes", "HalfSpace"),
    "Shape": ("moik.collision.shapes", "Shape"),
    "Sphere": ("moik.collision.shapes", "Sphere"),
    "cylinder": ("moik.collision.prism", "cylinder_compound"),
    "model_from_urdf": ("moik.collision.urdf", "model_from_urdf"),
}
"""Public name -> (module, attribute), loaded at first use: the solver's start loop
imports :mod:`moik.collision.compiled` for every solve, which need not load the models,
files and URDF readers (start-up time)."""

__all__ = ["Box", "Capsule", "CollisionChecker", "CollisionModel", "ConvexHull", "HalfSpace",
           "Scene", "Shape", "Sphere", "collision_model", "cylinder", "default_links",
           "load_model", "load_scene", "model_from_urdf", "shipped_models"]

__getattr__, __dir__ = lazy_names("moik.collision", _LAZY, globals(), __all__)
