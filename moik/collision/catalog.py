"""The capsule models shipped for the catalog arms (``moik/collision/data``, see its README).

``collision_model("panda")`` (or a catalog :class:`Robot`) returns the shipped model;
a robot that is not the catalog's (another name, or other joints) gets a clear error
rather than a model of another arm.
"""

from __future__ import annotations

import json
from importlib import resources
from typing import Any

from moik.collision.io import load_model
from moik.collision.model import CollisionModel
from moik.exceptions import UnknownNameError
from moik.robots.catalog import as_robot

MESH_ARMS = ("iiwa14", "panda", "ur5")
"""Catalog arms whose collision geometry is their URDF's own meshes (shipped in
``moik/robots/data/packages``): a solve's default geometry for them is
:func:`moik.collision.urdf.robot_model` (compounds: sound and tight against the meshes),
not the capsule model of :func:`collision_model` (measured unsound against the meshes for
panda and ur5: ``docs/results/mesh-collision.md``)."""


def shipped_models() -> list[str]:
    """Names of the robots with a shipped capsule model."""
    folder = resources.files("moik.collision") / "data"
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".json"))


def collision_model(robot: Any) -> CollisionModel:
    """The shipped capsule model of a catalog robot (a name or the catalog's Robot).

    Raises:
        UnknownNameError: no model is shipped for that name.
        GeometryError: the robot given has the name but not the joints of the catalog arm.
    """
    r = as_robot(robot)
    names = shipped_models()
    if r.name not in names:
        raise UnknownNameError("robot with a shipped collision model", r.name, names)
    path = resources.files("moik.collision") / "data" / f"{r.name}.json"
    return load_model(json.loads(path.read_text()), r)
