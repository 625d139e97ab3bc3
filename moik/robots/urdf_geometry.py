"""The ``<collision>`` primitives of a URDF, placed on the bodies of its loaded chain.

Beside :func:`moik.robots.urdf.load_urdf` (reusing its parser, not changing it): for a
robot loaded from a URDF, every link below ``base_link`` belongs to body ``b`` = the
number of the robot's joints on its path (body ``b`` is frame ``b`` of
:meth:`Robot.frames`); a movable joint outside the chain on that path (a gripper's
fingers) is placed at a stated value (:mod:`moik.robots.urdf_joints`), so the links
behind it ride on the body of the chain link they hang from. Each such link's
``<collision>`` elements with a primitive geometry (``box``, ``cylinder``, ``sphere``,
``capsule``) are returned with their pose in that body's frame; meshes are marked
``skipped`` there. :func:`mesh_geometry` lists the mesh references themselves (file
name, scale, pose on the body), which :mod:`moik.collision.urdf` reads and fits;
nothing here reads a mesh. Plain data (dicts): the shapes are built by
:mod:`moik.collision.urdf`.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from moik.exceptions import URDFError
from moik.robots.chain import Robot
from moik.robots.fk_kernels import world_frames
from moik.robots.urdf import _child, _floats, _link, _origin, _parse, _read
from moik.robots.urdf_joints import JointPlacement, place_joints

PRIMITIVES = ("box", "cylinder", "sphere", "capsule")


def _axis_rotation(axis: np.ndarray, q: float, prismatic: bool) -> np.ndarray:
    T = np.eye(4)
    a = axis / np.linalg.norm(axis)
    if prismatic:
        T[:3, 3] = q * a
        return T
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    T[:3, :3] = np.eye(3) + np.sin(q) * K + (1 - np.cos(q)) * K @ K
    return T


def link_placements(source: Any, robot: Robot, q: Any = None, joint_values: Any = None
                    ) -> tuple[list[str], dict[str, tuple[int, np.ndarray]]]:
    """Each URDF link on ``robot``'s bodies: ``{link: (body, pose in the body's frame)}``.

    Also returns the URDF name of each body (``dof + 1``: the base link, then each
    joint's child link). ``q`` is where the link poses are compared with the robot's
    frames (default: the middle of the limits; the result does not depend on it).
    Links behind movable joints outside the chain are on the body of the chain link they
    hang from, placed at ``joint_values`` (:mod:`moik.robots.urdf_joints`).

    Raises:
        URDFError: the URDF does not contain the robot's joints; an off-chain joint that
            cannot be placed. ParameterError: bad ``joint_values``.
    """
    body_names, placed, _ = _walk(source, robot, q, joint_values)
    return body_names, placed


def offchain_placement(source: Any, robot: Robot, joint_values: Any = None
                       ) -> dict[str, JointPlacement]:
    """The off-chain joints with links behind them on ``robot``'s bodies, and where each is
    placed (:func:`moik.robots.urdf_joints.place_joints`), in the URDF's order."""
    return _walk(source, robot, None, joint_values)[2]


def urdf_links(source: Any) -> set[str]:
    """The names of every ``<link>`` of a URDF (path or XML text)."""
    root, label = _read(source)
    return _parse(root, label)[0]


def joint_frames(robot: Robot, q: Any) -> np.ndarray:
    """:meth:`Robot.frames` of one joint vector ``q`` (``(dof + 1, 4, 4)``, the same
    values), by :func:`~moik.robots.fk_kernels.world_frames`: the kernel a collision check
    compiles anyway, so that reading an arm's geometry compiles no FK kernel of its own."""
    qv = robot.kernel_batch(robot.check_q(q)[None])[0]
    frames, axes = np.empty((robot.dof + 1, 4, 4)), np.empty((robot.dof, 6))
    world_frames(robot.chain_model, qv, frames, axes)
    return frames


def _walk(source: Any, robot: Robot, q: Any, joint_values: Any
          ) -> tuple[list[str], dict[str, tuple[int, np.ndarray]], dict[str, JointPlacement]]:
    root, label = _read(source)
    links, joints = _parse(root, label)
    names = list(robot.joint_names)
    missing = [n for n in names if n not in joints]
    if missing:
        raise URDFError(f"{label!r} has no joints {missing}: it is not the URDF of robot "
                        f"{robot.name!r}")
    match = re.search(r": (\S+) -> ", robot.source)
    base = match.group(1) if match and match.group(1) in links else None
    if base is None:
        childs = {_child(el) for el in joints.values()}
        base = sorted(links - childs)[0]
    off = place_joints(joints, tuple(names), joint_values)
    qv = (robot.lower + robot.upper) / 2 if q is None else np.asarray(q, dtype=float)
    values = dict(zip(names, qv, strict=True))
    values.update({n: p.value for n, p in off.items()})
    children: dict[str, list] = {}
    for el in joints.values():
        children.setdefault(_link(el, "parent"), []).append(el)
    frames = joint_frames(robot, qv)
    placed: dict[str, tuple[int, np.ndarray]] = {}
    reached: dict[str, JointPlacement] = {}
    body_names = [base] + [""] * len(names)
    stack = [(base, np.eye(4), 0, 0)]
    while stack:
        link, T, body, nxt = stack.pop()
        placed[link] = (body, np.linalg.inv(frames[body]) @ T)
        for el in children.get(link, []):
            jname, jtype = str(el.get("name")), el.get("type")
            Tj = T @ _origin(el, jname)
            if jtype == "fixed":
                stack.append((_child(el), Tj, body, nxt))
                continue
            chained = nxt < len(names) and jname == names[nxt]
            if not chained and jname not in off:
                raise URDFError(f"joint {jname!r} is {jtype!r}: the links behind it "
                                f"({_child(el)!r}) cannot be placed on the arm at one value; "
                                "expected revolute, continuous or prismatic")
            axis_el = el.find("axis")
            axis = _floats(None if axis_el is None else axis_el.get("xyz"), (1, 0, 0),
                           f"joint {jname!r} axis")
            if not np.any(axis):
                raise URDFError(f"joint {jname!r} axis must be non-zero, got {axis.tolist()}")
            Tj = Tj @ _axis_rotation(axis, values[jname], jtype == "prismatic")
            if chained:
                body_names[body + 1] = _child(el)
                stack.append((_child(el), Tj, body + 1, nxt + 1))
            else:
                reached[jname] = off[jname]
                stack.append((_child(el), Tj, body, nxt))
    order = list(joints)
    reached = {n: reached[n] for n in sorted(reached, key=order.index)}
    return body_names, placed, reached


def collision_geometry(source: Any, robot: Robot, q: Any = None, joint_values: Any = None
                       ) -> tuple[list[str], list[dict[str, Any]]]:
    """The primitive collision geometry of a URDF on ``robot``'s bodies.

    Args:
        source: The URDF file path or text ``robot`` was loaded from.
        robot: The robot :func:`load_urdf` returned for it.
        q, joint_values: As in :func:`link_placements`.

    Returns:
        The body names of :func:`link_placements`, and one dict per primitive:
        ``link``, ``body``, ``type``, sizes (``radius``, ``length``, ``size``) and
        ``pose`` (4x4 list, in body ``body``'s frame); and one dict
        ``{"link", "body", "type": "mesh", "skipped": True}`` per mesh.
    """
    body_names, placed = link_placements(source, robot, q, joint_values)
    root, _ = _read(source)
    link_el = {el.get("name"): el for el in root.findall("link")}
    out: list[dict[str, Any]] = []
    for link, (body, offset) in placed.items():
        for col in link_el[link].findall("collision"):
            out.extend(_primitives(col, link, body, offset))
    return body_names, out


def _primitives(col: Any, link: str, body: int, offset: np.ndarray) -> list[dict[str, Any]]:
    geom = col.find("geometry")
    if geom is None or len(geom) == 0:
        raise URDFError(f"link {link!r}: a <collision> needs a <geometry>")
    pose = offset @ _origin(col, "", owner=f"<collision> of link {link!r}")
    out = []
    for g in geom:
        if g.tag == "mesh":
            out.append({"link": link, "body": body, "type": "mesh", "skipped": True})
            continue
        if g.tag not in PRIMITIVES:
            raise URDFError(f"link {link!r}: unknown collision geometry <{g.tag}>; expected one "
                            f"of {', '.join(PRIMITIVES + ('mesh',))}")
        item: dict[str, Any] = {"link": link, "body": body, "type": g.tag, "pose": pose.tolist()}
        try:
            if g.tag == "box":
                item["size"] = [float(v) for v in str(g.get("size", "")).split()]
            else:
                item["radius"] = float(g.get("radius", "nan"))
                if g.tag != "sphere":
                    item["length"] = float(g.get("length", "nan"))
        except ValueError:
            raise URDFError(f"link {link!r}: <{g.tag}> sizes must be numbers, got "
                            f"{dict(g.attrib)}") from None
        out.append(item)
    return out


def mesh_geometry(source: Any, robot: Robot, element: str = "collision", q: Any = None,
                  joint_values: Any = None) -> tuple[list[str], list[dict[str, Any]]]:
    """The ``<mesh>`` references of a URDF's ``<collision>`` (or ``<visual>``) elements on
    ``robot``'s bodies; no mesh is read.

    Args:
        source, robot, q, joint_values: As in :func:`collision_geometry`.
        element: ``"collision"`` or ``"visual"``.

    Returns:
        The body names of :func:`link_placements`, and one dict per mesh: ``link``,
        ``body``, ``filename`` (as written, e.g. ``package://...``), ``scale`` (3 floats,
        default 1) and ``pose`` (4x4 array: the element's ``<origin>`` in body ``body``'s
        frame; a mesh vertex ``v`` lies at ``pose @ (scale * v, 1)``).
    """
    if element not in ("collision", "visual"):
        raise URDFError(f"element must be 'collision' or 'visual', got {element!r}")
    body_names, placed = link_placements(source, robot, q, joint_values)
    root, _ = _read(source)
    link_el = {el.get("name"): el for el in root.findall("link")}
    out: list[dict[str, Any]] = []
    for link, (body, offset) in placed.items():
        for el in link_el[link].findall(element):
            pose = offset @ _origin(el, "", owner=f"<{element}> of link {link!r}")
            for m in el.iter("mesh"):
                filename = m.get("filename")
                if not filename:
                    raise URDFError(f"link {link!r}: a <mesh> needs a filename=")
                scale = _floats(m.get("scale"), (1, 1, 1), f"link {link!r} mesh scale")
                out.append({"link": link, "body": body, "filename": filename,
                            "scale": scale, "pose": pose})
    return body_names, out
