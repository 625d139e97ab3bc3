"""A :class:`CollisionModel` from a URDF's ``<collision>`` primitives.

Boxes, spheres and capsules are taken as they are; cylinders become their enclosing
capsules (:func:`moik.collision.shapes.cylinder`); meshes are skipped (no mesh is read
here: use a shipped capsule model, :mod:`moik.collision.catalog`, your own capsules in
JSON, :func:`moik.collision.io.load_model`, or capsules fitted to the meshes at build
time, :mod:`moik.collision.fit`). Bodies are named by their URDF links.
"""

from __future__ import annotations

from typing import Any

from moik.collision.model import CollisionModel
from moik.collision.shapes import Box, Capsule, Shape, Sphere, cylinder
from moik.robots.chain import Robot
from moik.robots.urdf_geometry import collision_geometry


def _shape(item: dict[str, Any]) -> Shape:
    kind, pose = item["type"], item["pose"]
    if kind == "box":
        return Box(size=item["size"], pose=pose)
    if kind == "sphere":
        return Sphere(radius=item["radius"], pose=pose)
    build = Capsule if kind == "capsule" else cylinder
    return build(radius=item["radius"], length=item["length"], pose=pose)


def model_from_urdf(source: Any, robot: Robot) -> tuple[CollisionModel, list[str]]:
    """The URDF's primitive collision geometry on ``robot``, and the links whose meshes
    were skipped.

    Raises:
        URDFError: the URDF is not ``robot``'s. GeometryError, NonFiniteError: a bad size.
    """
    names, items = collision_geometry(source, robot)
    shapes: dict[str, list[Shape]] = {}
    skipped = []
    for item in items:
        if item.get("skipped"):
            skipped.append(item["link"])
            continue
        shapes.setdefault(names[item["body"]], []).append(_shape(item))
    model = CollisionModel(robot=robot, shapes=shapes, links=tuple(names),
                           source=f"<collision> primitives of {robot.source}")
    return model, skipped
