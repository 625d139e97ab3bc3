"""Shapes, scenes and capsule models from JSON (files or parsed dictionaries).

A shape is an object with ``"type"`` (``sphere``, ``capsule``, ``cylinder``, ``box``,
``halfspace``), its sizes (``radius``; ``length``; box ``size`` = full side lengths) and
its placement (a cylinder is measured on a prism holding it inside its enclosing capsule:
:mod:`moik.collision.prism`): ``"pose"`` (a 4x4 matrix) or ``"xyz"`` and ``"rpy"`` (URDF's
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

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from moik._validate import finite_array, known_keys
from moik._validate.reading import depth_problem, read_json
from moik.collision.model import CollisionModel, Scene
from moik.collision.prism import cylinder_compound
from moik.collision.shapes import Box, Capsule, HalfSpace, Shape, Sphere
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
        raise GeometryError(f"{what} needs the key {key!r}; it has {sorted(map(str, d))}")
    return d[key]


PLACEMENT_KEYS = ("type", "pose", "xyz", "rpy")
SIZE_KEYS = {"sphere": ("radius",), "capsule": ("radius", "length", "a", "b"),
             "cylinder": ("radius", "length"), "box": ("size",),
             "halfspace": ("normal", "offset")}
"""The keys each shape type reads besides :data:`PLACEMENT_KEYS` (any other is refused)."""
MAX_ITEMS = 100_000
"""Obstacles, shapes or allowed pairs in one file."""


def _size(d: Mapping, key: str, what: str) -> Any:
    """A size value: a number or a list of numbers (checked by the shape's constructor);
    anything else (a string, an object, null) is refused here by name."""
    value = _get(d, key, what)
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) or \
        isinstance(value, list) and all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                        for v in value)
    if not ok:
        raise GeometryError(f"{what} {key!r} must be a number or a list of numbers, got "
                            f"{_short(value)}")
    return value


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def shape_from_dict(d: Any, what: str = "shape", *, extra_keys: tuple[str, ...] = ()) -> Shape:
    """A shape from its JSON description (see the module doc).

    Args:
        d: The description.
        what: Names the shape in messages.
        extra_keys: Keys the caller reads itself (a scene's ``name``, a model's ``link``).

    Raises:
        UnknownNameError: an unknown ``type``.
        GeometryError: a missing or unknown key (the nearest valid key is named) or a
            malformed size; NonFiniteError: NaN or inf.
    """
    if not isinstance(d, Mapping):
        raise GeometryError(f"{what} must be an object with a 'type', got {type(d).__name__}")
    kind = _get(d, "type", what)
    if not isinstance(kind, str) or kind not in SHAPE_TYPES:
        raise UnknownNameError("shape type", _short(kind) if not isinstance(kind, str) else kind,
                               SHAPE_TYPES)
    known_keys(what, d, (*PLACEMENT_KEYS, *SIZE_KEYS[kind], *extra_keys), error=GeometryError)
    sizes = {k: _size(d, k, what) for k in SIZE_KEYS[kind] if k in d}
    try:
        return _build(kind, d, sizes, what)
    except (OverflowError, TypeError) as exc:  # a number beyond float, a ragged list
        raise GeometryError(f"{what}: {type(exc).__name__}: {exc}") from None


def _build(kind: str, d: Mapping, sizes: dict[str, Any], what: str) -> Shape:
    if "pose" in d:
        pose = finite_array(f"{what} pose", d["pose"], shape=(4, 4))
    else:
        pose = rpy_pose(d.get("xyz", (0.0, 0.0, 0.0)), d.get("rpy", (0.0, 0.0, 0.0)))
    if kind == "sphere":
        return Sphere(radius=_get(sizes, "radius", what), pose=pose)
    if kind == "capsule" and "a" in d:
        capsule = Capsule.between(d["a"], _get(sizes, "b", what), _get(sizes, "radius", what))
        return capsule.moved(pose) if "pose" in d or "xyz" in d or "rpy" in d else capsule
    if kind in ("capsule", "cylinder"):
        build = Capsule if kind == "capsule" else cylinder_compound
        return build(radius=_get(sizes, "radius", what), length=_get(sizes, "length", what),
                     pose=pose)
    if kind == "box":
        return Box(size=_get(sizes, "size", what), pose=pose)
    if "normal" in d:
        return HalfSpace.plane(d["normal"], sizes.get("offset", 0.0))
    if "offset" in d:
        raise GeometryError(f"{what}: 'offset' needs 'normal' (normal . x <= offset)")
    return HalfSpace(pose=pose)


def _read_json(source: Any, what: str) -> Any:
    if isinstance(source, Mapping):
        value = source
        why = depth_problem(dict(source))
        if why is not None:
            raise GeometryError(f"a {what} holds {why}")
        return value
    if not isinstance(source, (str, Path)) or (isinstance(source, str) and not source):
        raise GeometryError(f"a {what} must be a JSON file path or a dict, got "
                            f"{_short(source)}")
    return read_json(source, what, GeometryError, limit=MAX_FILE_BYTES)


MAX_FILE_BYTES = 64 * 2**20
"""Size of a scene or capsule-model file."""


def _names(value: Any, what: str) -> list[str]:
    """A list of strings (a model's links)."""
    if not isinstance(value, list) or len(value) > MAX_ITEMS or \
            any(not isinstance(v, str) for v in value):
        raise GeometryError(f"{what} must be a list of names (strings), got {_short(value)}")
    return value


def _pairs(value: Any, what: str, pair: str) -> list[tuple[str, str]]:
    if not isinstance(value, list) or len(value) > MAX_ITEMS or any(
            not isinstance(p, list) or len(p) != 2 or not all(isinstance(n, str) for n in p)
            for p in value):
        raise GeometryError(f"{what} must be a list of [{pair}] pairs of names, got "
                            f"{_short(value)}")
    return [(p[0], p[1]) for p in value]


SCENE_KEYS = ("obstacles", "allowed")
MODEL_KEYS = ("robot", "dof", "links", "shapes", "allowed", "source", "acm")
"""The keys of a scene and of a capsule-model file (``acm``: how ``allowed`` was found)."""


def load_scene(source: Any) -> Scene:
    """A :class:`Scene` from a JSON file or a parsed dict (see the module doc).

    Raises:
        GeometryError: A file that cannot be read, an unknown key (the nearest valid key
            is named), a malformed obstacle or name.
    """
    data = _read_json(source, "scene")
    if not isinstance(data, Mapping):
        raise GeometryError(f"a scene must be a JSON object with 'obstacles', got "
                            f"{type(data).__name__}")
    known_keys("a scene", data, SCENE_KEYS, error=GeometryError)
    items = _get(data, "obstacles", "a scene")
    if not isinstance(items, list) or len(items) > MAX_ITEMS:
        raise GeometryError(f"scene 'obstacles' must be a list of at most {MAX_ITEMS} shapes")
    obstacles: dict[str, Shape] = {}
    for k, item in enumerate(items):
        name = item.get("name", f"obstacle{k}") if isinstance(item, Mapping) else f"obstacle{k}"
        if not isinstance(name, str) or not name or len(name) > 200:
            raise GeometryError(f"obstacle {k}: 'name' must be a string of 1 to 200 "
                                f"characters, got {_short(name)}")
        if name in obstacles:
            raise GeometryError(f"two obstacles are named {name!r}")
        obstacles[name] = shape_from_dict(item, f"obstacle {name!r}", extra_keys=("name",))
    allowed = _pairs(data.get("allowed", []), "scene 'allowed'", "obstacle, link")
    return Scene(obstacles, allowed=frozenset(allowed))


def load_model(source: Any, robot: Robot) -> CollisionModel:
    """A :class:`CollisionModel` of ``robot`` from a capsule-model JSON file or dict.

    Raises:
        GeometryError: the file is for another robot (name or number of joints), has an
            unknown key (the nearest valid key is named) or a malformed entry.
        UnknownNameError: a shape on a link the model does not name.
    """
    data = _read_json(source, "collision model")
    if not isinstance(data, Mapping):
        raise GeometryError("a collision model must be a JSON object")
    known_keys("a collision model", data, MODEL_KEYS, error=GeometryError)
    for key, want in (("robot", robot.name), ("dof", robot.dof)):
        if key in data and data[key] != want:
            raise GeometryError(f"this collision model is for {key} {_short(data[key])}, but "
                                f"robot {robot.name!r} has {key} {want!r}")
    items = _get(data, "shapes", "a collision model")
    if not isinstance(items, list) or len(items) > MAX_ITEMS:
        raise GeometryError(f"collision model 'shapes' must be a list of at most {MAX_ITEMS} "
                            "shapes")
    shapes: dict[str, list[Shape]] = {}
    for k, item in enumerate(items):
        if not isinstance(item, Mapping):
            raise GeometryError(f"collision model shape {k} must be an object")
        link = _get(item, "link", f"collision model shape {k}")
        if not isinstance(link, str):
            raise GeometryError(f"collision model shape {k}: 'link' must be a link name "
                                f"(string), got {_short(link)}")
        shapes.setdefault(link, []).append(
            shape_from_dict(item, f"shape {k} on {link!r}", extra_keys=("link",)))
    allowed = _pairs(data.get("allowed", []), "collision model 'allowed'", "link, link")
    links = _names(data.get("links", []), "collision model 'links'")
    source_text = data.get("source", "")
    if not isinstance(source_text, str):
        raise GeometryError(f"collision model 'source' must be a string, got "
                            f"{_short(source_text)}")
    return CollisionModel(robot=robot, shapes=shapes, links=tuple(links),
                          allowed=frozenset(frozenset(p) for p in allowed),
                          source=source_text)


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
