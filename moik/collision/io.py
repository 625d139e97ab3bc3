"""Shapes, scenes and capsule models from JSON (files or parsed dictionaries).

A shape is an object with ``"type"`` (``sphere``, ``capsule``, ``cylinder``, ``box``,
``halfspace``), its sizes (``radius``; ``length``; box ``size`` = full side lengths) and
its placement: ``"pose"`` (a 4x4 matrix) or ``"xyz"`` and ``"rpy"`` (URDF's
fixed-axis roll-pitch-yaw, ``R = Rz(y) Ry(p) Rx(r)``). A capsule may instead give its
segment's end points ``"a"`` and ``"b"``; a half-space ``"normal"`` and ``"offset"``
(``normal . x <= offset``). Lengths are in the robot's unit.

Scene file::

    {"obstacles": [{"name": "table", "type": "halfspace", "normal": [0, 0, 1], "offset": 0},
                   {"name": "shelf", "type": "box", "size": [0.4, 0.8, 0.02],
                    "xyz": [0.6, 0, 0.5]}],
     "allowed": [["table", "panda_link0"]]}

(``allowed``: obstacle-link pairs never checked, e.g. the table the arm stands on.)

Capsule-model file (``"robot"`` and ``"dof"`` must match the robot it is used with)::

    {"robot": "panda", "dof": 7, "links": ["panda_link0", ...],
     "shapes": [{"link": "panda_link1", "type": "capsule", "a": [0, 0, -0.333],
                 "b": [0, 0, -0.05], "radius": 0.06}, ...],
     "allowed": [["panda_link0", "panda_link2"], ...], "source": "..."}
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from moik._validate import finite_array
from moik.collision.model import CollisionModel, Scene
from moik.collision.shapes import Box, Capsule, HalfSpace, Shape, Sphere, cylinder
from moik.exceptions import GeometryError, UnknownNameError
from moik.robots.chain import Robot

SHAPE_TYPES = ("box", "capsule", "cylinder", "halfspace", "sphere")


def rpy_pose(xyz: Any = (0.0, 0.0, 0.0), rpy: Any = (0.0, 0.0, 0.0)) -> np.ndarray:
    """The 4x4 pose of URDF's ``<origin xyz rpy>`` (``R = Rz(yaw) Ry(pitch) Rx(roll)``)."""
    p = finite_array("xyz", xyz, shape=(3,))
    angles = finite_array("rpy", rpy, shape=(3,))
    (cr, cp, cy), (sr, sp, sy) = np.cos(angles), np.sin(angles)
    T = np.eye(4)
    T[:3, :3] = [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                 [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                 [-sp, cp * sr, cp * cr]]
    T[:3, 3] = p
    return T


def _get(d: Mapping, key: str, what: str) -> Any:
    if key not in d:
        raise GeometryError(f"{what} needs the key {key!r}; it has {sorted(d)}")
    return d[key]


def shape_from_dict(d: Any, what: str = "shape") -> Shape:
    """A shape from its JSON description (see the module doc).

    Raises:
        UnknownNameError: an unknown ``type``.
        GeometryError: a missing key or a malformed size; NonFiniteError: NaN or inf.
    """
    if not isinstance(d, Mapping):
        raise GeometryError(f"{what} must be an object with a 'type', got {type(d).__name__}")
    kind = _get(d, "type", what)
    if kind not in SHAPE_TYPES:
        raise UnknownNameError("shape type", kind, SHAPE_TYPES)
    if "pose" in d:
        pose = finite_array(f"{what} pose", d["pose"], shape=(4, 4))
    else:
        pose = rpy_pose(d.get("xyz", (0.0, 0.0, 0.0)), d.get("rpy", (0.0, 0.0, 0.0)))
    if kind == "sphere":
        return Sphere(radius=_get(d, "radius", what), pose=pose)
    if kind == "capsule" and "a" in d:
        capsule = Capsule.between(d["a"], _get(d, "b", what), _get(d, "radius", what))
        return capsule.moved(pose) if "pose" in d or "xyz" in d or "rpy" in d else capsule
    if kind in ("capsule", "cylinder"):
        build = Capsule if kind == "capsule" else cylinder
        return build(radius=_get(d, "radius", what), length=_get(d, "length", what), pose=pose)
    if kind == "box":
        return Box(size=_get(d, "size", what), pose=pose)
    if "normal" in d:
        return HalfSpace.plane(d["normal"], d.get("offset", 0.0))
    return HalfSpace(pose=pose)


def _read_json(source: Any, what: str) -> Any:
    if isinstance(source, Mapping):
        return source
    if not isinstance(source, (str, Path)):
        raise GeometryError(f"a {what} must be a JSON file path or a dict, got "
                            f"{type(source).__name__}")
    path = Path(source)
    try:
        return json.loads(path.read_text())
    except OSError as exc:
        raise GeometryError(f"cannot read {what} {str(path)!r}: {exc}") from None
    except json.JSONDecodeError as exc:
        raise GeometryError(f"{what} {str(path)!r} is not valid JSON: {exc}") from None


def load_scene(source: Any) -> Scene:
    """A :class:`Scene` from a JSON file or a parsed dict (see the module doc)."""
    data = _read_json(source, "scene")
    if not isinstance(data, Mapping):
        raise GeometryError(f"a scene must be a JSON object with 'obstacles', got "
                            f"{type(data).__name__}")
    items = _get(data, "obstacles", "a scene")
    if not isinstance(items, list):
        raise GeometryError("scene 'obstacles' must be a list of shapes")
    obstacles: dict[str, Shape] = {}
    for k, item in enumerate(items):
        name = item.get("name", f"obstacle{k}") if isinstance(item, Mapping) else f"obstacle{k}"
        if name in obstacles:
            raise GeometryError(f"two obstacles are named {name!r}")
        obstacles[name] = shape_from_dict(item, f"obstacle {name!r}")
    allowed = data.get("allowed", [])
    if not isinstance(allowed, list) or any(not isinstance(p, list) or len(p) != 2
                                            for p in allowed):
        raise GeometryError("scene 'allowed' must be a list of [obstacle, link] pairs")
    return Scene(obstacles, allowed=frozenset(tuple(p) for p in allowed))


def load_model(source: Any, robot: Robot) -> CollisionModel:
    """A :class:`CollisionModel` of ``robot`` from a capsule-model JSON file or dict.

    Raises:
        GeometryError: the file is for another robot (name or number of joints).
        UnknownNameError: a shape on a link the model does not name.
    """
    data = _read_json(source, "collision model")
    if not isinstance(data, Mapping):
        raise GeometryError("a collision model must be a JSON object")
    for key, want in (("robot", robot.name), ("dof", robot.dof)):
        if key in data and data[key] != want:
            raise GeometryError(f"this collision model is for {key} {data[key]!r}, but robot "
                                f"{robot.name!r} has {key} {want!r}")
    shapes: dict[str, list[Shape]] = {}
    for k, item in enumerate(_get(data, "shapes", "a collision model")):
        if not isinstance(item, Mapping):
            raise GeometryError(f"collision model shape {k} must be an object")
        link = _get(item, "link", f"collision model shape {k}")
        shapes.setdefault(link, []).append(shape_from_dict(item, f"shape {k} on {link!r}"))
    allowed = [tuple(p) for p in data.get("allowed", [])]
    if any(len(p) != 2 for p in allowed):
        raise GeometryError("collision model 'allowed' must be a list of [link, link] pairs")
    return CollisionModel(robot=robot, shapes=shapes, links=tuple(data.get("links", ())),
                          allowed=frozenset(frozenset(p) for p in allowed),
                          source=str(data.get("source", "")))


def model_to_dict(model: CollisionModel) -> dict[str, Any]:
    """A capsule-model JSON object of ``model`` (read back by :func:`load_model`)."""
    shapes = []
    for link, items in model.shapes.items():
        for s in items:
            d = s.to_dict()
            d["link"] = link
            shapes.append(d)
    return {"robot": model.robot.name, "dof": model.robot.dof, "links": list(model.links),
            "shapes": shapes, "allowed": sorted(sorted(p) for p in model.allowed),
            "source": model.source}
