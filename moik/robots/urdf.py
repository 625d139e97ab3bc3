"""Load a serial chain from a URDF file into a :class:`~moik.robots.chain.Robot`.

Parsed with the standard library (``xml.etree``): URDF parsers on PyPI pull in
mesh libraries (trimesh, lxml) that kinematics does not need, and meshes are
never read here.

Rules:

* The chain runs from ``base_link`` (default: the root link) to ``tip_link``.
  Without a tip, the chain follows the only child; where it branches, branches
  without movable joints are ignored (e.g. UR5's ``ee_link``/``tool0``: the
  chain ends at the branching link), and two branches with movable joints are
  an error that lists the candidate tips.
* ``revolute`` and ``prismatic`` joints read their ``<limit>``; ``continuous``
  joints get ``[-pi, pi]`` (one full turn covers every orientation);
  ``fixed`` joints are folded into the constant transforms. ``floating`` and
  ``planar`` joints are rejected with a hint; a chain through a ``<mimic>`` joint is
  refused (coupled joints are not modelled, never silently made independent).
* The file must describe a tree: duplicate joint names, undeclared, nameless or
  duplicate links, a link with two parents and cycles are reported; ``.xacro``
  files must be expanded first.
* ``<origin xyz rpy>`` (fixed-axis roll-pitch-yaw, ``R = Rz(y) Ry(p) Rx(r)``)
  and ``<axis xyz>`` (any unit vector; default x as the URDF spec says) are
  honoured. Lengths are metres.
* The robot keeps the names of its movable joints (``robot.joint_names``), in
  chain order, so a solution maps back to the URDF's ``joint_states``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from moik._validate.reading import read_bytes, robot_xml
from moik._validate.reading import text as decoded_text
from moik.exceptions import MoikError, ParameterError, UnknownNameError, URDFError
from moik.robots.chain import Robot
from moik.robots.description import URDFDescription
from moik.robots.transforms import rot_x, translation

__all__ = ["URDFError", "load_urdf"]


def _rotation():
    """scipy's Rotation, imported on first use: ``import moik`` and a solve need not pay
    scipy.spatial's import (start-up time, not an import cycle)."""
    from scipy.spatial.transform import Rotation

    return Rotation


def _floats(text: str | None, default, what: str) -> np.ndarray:
    if text is None:
        return np.array(default, dtype=float)
    try:
        vals = np.array([float(v) for v in text.split()])
    except ValueError:
        raise URDFError(f"{what} must be numbers, got {text!r}") from None
    if vals.shape != (3,) or not np.all(np.isfinite(vals)):
        raise URDFError(f"{what} must be 3 finite numbers, got {text!r}")
    return vals


def _origin(joint: ET.Element, name: str, *, owner: str = "") -> np.ndarray:
    """The ``<origin>`` of an element as a transform; ``name`` a joint's name, or ``owner``
    what else holds it (e.g. "<collision> of link 'a'") for the messages."""
    what = owner or f"joint {name!r}"
    el = joint.find("origin")
    xyz = _floats(None if el is None else el.get("xyz"), (0, 0, 0), f"{what} origin xyz")
    rpy = _floats(None if el is None else el.get("rpy"), (0, 0, 0), f"{what} origin rpy")
    T = translation(*xyz)
    if np.any(rpy != 0):  # fixed-axis roll-pitch-yaw: R = Rz(yaw) Ry(pitch) Rx(roll)
        (cr, cp, cy), (sr, sp, sy) = np.cos(rpy), np.sin(rpy)
        T[:3, :3] = [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]]
    return T


def _axis_frame(axis: np.ndarray) -> np.ndarray:
    """A rotation ``C`` (4x4) with ``C @ z = axis``, exact for +-x, +-y, +-z."""
    exact = {(0, 0, 1): np.eye(4), (0, 0, -1): rot_x(np.pi), (0, 1, 0): rot_x(-np.pi / 2),
             (0, -1, 0): rot_x(np.pi / 2)}
    key = tuple(int(v) for v in axis) if np.all(axis == np.round(axis)) else None
    if key in exact:
        return exact[key]
    C = np.eye(4)
    with np.errstate(all="ignore"):
        rot, _ = _rotation().align_vectors([axis], [[0.0, 0.0, 1.0]])
    C[:3, :3] = rot.as_matrix()
    return C


def _read(source) -> tuple[ET.Element, str]:
    """The ``<robot>`` element of a URDF file path or XML string, and a label for messages."""
    if isinstance(source, str) and source.lstrip().startswith("<"):
        label, text = "<URDF string>", source
    else:
        if not isinstance(source, (str, Path)):
            raise URDFError(f"a URDF must be a file path or an XML string, got "
                            f"{type(source).__name__}")
        if not str(source).strip():
            raise URDFError("a URDF must be a file path or an XML string, got an empty string")
        path = Path(source)
        label = str(path)
        if path.suffix == ".xacro":
            raise URDFError(f"{label!r} is a xacro file: run xacro first "
                            f"(`xacro {path.name} > {path.stem}.urdf`) and load the URDF")
        text = decoded_text(read_bytes(path, "URDF", URDFError, limit=MAX_URDF_BYTES),
                            f"URDF {label!r}", URDFError)
    root = robot_xml(text, label, "a URDF", URDFError)
    if any(el.tag.startswith("{") and "xacro" in el.tag for el in root.iter()):
        raise URDFError(f"{label!r} contains xacro elements: run xacro first")
    return root, label


def _parse(root: ET.Element, label: str) -> tuple[set, dict]:
    """Links and joints of a URDF, checked to form a tree (one parent per link, no cycle)."""
    names = [el.get("name") or "" for el in root.findall("link")]
    if not all(names):
        raise URDFError(f"{label!r}: every <link> needs a name=, one has none")
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise URDFError(f"{label!r}: links declared more than once: {twice}")
    links = set(names)
    joints: dict[str, ET.Element] = {}
    parent_of: dict[str, str] = {}
    for el in root.findall("joint"):
        name = el.get("name")
        if not name:
            raise URDFError(f"{label!r}: every <joint> needs a name=, one has none")
        parent, child = el.find("parent"), el.find("child")
        if parent is None or child is None or parent.get("link") is None \
                or child.get("link") is None:
            raise URDFError(f"joint {name!r} needs <parent link=> and <child link=>")
        if name in joints:
            raise URDFError(f"{label!r}: two joints are named {name!r} (joint names must be "
                            "unique)")
        for end in (parent.get("link"), child.get("link")):
            if end not in links:
                raise URDFError(f"joint {name!r} refers to link {end!r}, which is not declared "
                                f"as a <link> in {label!r}")
        kid = _link(el, "child")
        if kid in parent_of:
            raise URDFError(f"link {kid!r} has two parent joints ({parent_of[kid]!r} and "
                            f"{name!r}): a URDF must be a tree")
        parent_of[kid] = name
        joints[name] = el
    for start in parent_of:  # walk up from every link: a cycle never reaches a root
        link, seen = start, set()
        while link in parent_of:
            if link in seen:
                raise URDFError(f"{label!r}: the joints form a cycle through link {link!r}; "
                                "a URDF must be a tree")
            seen.add(link)
            link = _link(joints[parent_of[link]], "parent")
    return links, joints


def _children(joints: dict) -> dict[str, list[ET.Element]]:
    out: dict[str, list[ET.Element]] = {}
    for el in joints.values():
        out.setdefault(_link(el, "parent"), []).append(el)
    return out


def _has_movable(link: str, children: dict) -> bool:
    stack = [link]
    while stack:
        for el in children.get(stack.pop(), []):
            if el.get("type") != "fixed":
                return True
            stack.append(_child(el))
    return False


def _link(joint: ET.Element, end: str) -> str:
    """The ``link`` of a joint's ``<parent>`` or ``<child>`` (``_parse`` checked both)."""
    tag = joint.find(end)
    link = None if tag is None else tag.get("link")
    assert link is not None  # every joint of a parsed tree has both
    return link


def _child(el: ET.Element) -> str:
    return _link(el, "child")


def _leaves(link: str, children: dict) -> list[str]:
    kids = children.get(link, [])
    if not kids:
        return [link]
    return [leaf for el in kids for leaf in _leaves(_child(el), children)]


def _chain_joints(links, joints, base: str, tip: str | None) -> list[ET.Element]:
    children = _children(joints)
    if tip is not None:  # walk up from the tip
        parent_of = {_child(el): el for el in joints.values()}
        chain, link = [], tip
        while link != base:
            if link not in parent_of:
                raise URDFError(f"link {tip!r} is not below base link {base!r}")
            chain.append(parent_of[link])
            link = _link(parent_of[link], "parent")
        return chain[::-1]
    chain, link = [], base
    while children.get(link):
        movable = [el for el in children[link]
                   if el.get("type") != "fixed" or _has_movable(_child(el), children)]
        if len(children[link]) == 1:
            nxt = children[link][0]
        elif len(movable) == 1:
            nxt = movable[0]
        elif not movable:
            break
        else:
            leaves = sorted(leaf for el in children[link]  # a fixed leaf (a TCP) is a tip too
                            for leaf in _leaves(_child(el), children))
            raise URDFError(f"the chain branches at link {link!r}; pass tip_link= one of {leaves}")
        chain.append(nxt)
        link = _child(nxt)
    return chain


def _srdf_source(srdf: Any) -> Path | str | None:
    """``srdf`` kept for the collision model: None, XML text, or an existing file's
    absolute path (read at first use, as the meshes are)."""
    if srdf is None or (isinstance(srdf, str) and srdf.lstrip().startswith("<")):
        return srdf
    if not isinstance(srdf, (str, Path)) or not str(srdf).strip():
        raise ParameterError(f"srdf must be an SRDF file path or XML text, got {srdf!r:.80}")
    if not Path(srdf).is_file():
        raise ParameterError(f"srdf {str(srdf)!r} is not a file")
    return Path(srdf).resolve()


def load_urdf(source, base_link: str | None = None, tip_link: str | None = None,
              name: str | None = None, *, package_dirs=None, srdf=None) -> Robot:
    """A :class:`Robot` for the serial chain ``base_link -> tip_link`` of a URDF.

    Args:
        source: URDF file path, or the URDF's XML text.
        base_link: First link (default: the root link of the file).
        tip_link: Last link (default: follow the chain as the module doc says).
        name: Robot name (default ``"ROBOT:TIP"``: the URDF's robot name and the chain's
            last link, e.g. ``"ur5:wrist_3_link"``, so that two chains of one file, or a
            file's chain and the catalog arm made from it, do not share a name).
        package_dirs: Where the URDF's ``package://`` meshes are found: folders holding
            package folders, or ``{package name: folder}``
            (:func:`moik.collision.meshes.resolve_mesh`). Nothing is read here: the
            robot keeps the URDF and these folders (``robot.description``), and a
            collision-aware solve reads its ``<collision>`` geometry at first use.
        srdf: A MoveIt SRDF of the robot (file path or XML text): the link pairs it
            disables are not checked for self-collision (:mod:`moik.collision.srdf`),
            read with the geometry at first use; kept in ``robot.description``.

    Returns:
        The chain with ``joint_names`` the URDF names of its movable joints.

    Raises:
        ParameterError: ``package_dirs`` not one of those, or naming a folder that does
            not exist; ``srdf`` neither XML text nor the path of an existing file.
        URDFError: malformed file (not a tree, undeclared, nameless or duplicate link,
            duplicate joint name, xacro), unsupported or mimic joint, branching chain
            without tip.
        UnknownNameError: a link name not in the file (lists the links).
    """
    package_dirs = absolute_package_dirs(package_dirs)
    srdf = _srdf_source(srdf)
    root, label = _read(source)
    links, joints = _parse(root, label)
    for given in (base_link, tip_link):
        if given is not None and given not in links:
            raise UnknownNameError("link", given, links)
    if base_link is None:
        childs = {_child(el) for el in joints.values()}
        roots = sorted(links - childs)
        if len(roots) != 1:
            raise URDFError(f"expected one root link, found {roots}; pass base_link=")
        base_link = roots[0]
    chain = _chain_joints(links, joints, base_link, tip_link)
    origins, lower, upper, types, names = [np.eye(4)], [], [], [], []
    for el in chain:
        jname, jtype = el.get("name", ""), el.get("type")  # named: _parse checked
        with np.errstate(over="ignore", invalid="ignore"):  # checked just below
            T = origins[-1] @ _origin(el, jname)
        if not np.all(np.isfinite(T)):
            raise URDFError(f"{label!r}: the transform from {base_link!r} to joint {jname!r} "
                            "overflows (origin xyz too large); expected lengths in metres")
        if jtype == "fixed":
            origins[-1] = T
            continue
        if jtype in ("floating", "planar"):
            raise URDFError(f"joint {jname!r} is {jtype!r}: moik loads serial arms with revolute "
                            "and prismatic joints; pass base_link= the link after it (e.g. the "
                            "arm's base) to leave a floating/planar root out")
        if jtype not in ("revolute", "continuous", "prismatic"):
            raise URDFError(f"joint {jname!r} has unsupported type {jtype!r}; expected revolute, "
                            "continuous, prismatic or fixed")
        mimic = el.find("mimic")
        if mimic is not None:
            raise URDFError(f"joint {jname!r} mimics joint {mimic.get('joint')!r}: coupled (mimic) "
                            "joints are not supported; choose a tip_link whose chain has no "
                            "mimic joint")
        axis_el = el.find("axis")
        axis = _floats(None if axis_el is None else axis_el.get("xyz"), (1, 0, 0),
                       f"joint {jname!r} axis")
        scale = np.max(np.abs(axis))  # scaled first: the norm of 1e300-sized axes overflows
        if scale == 0:
            raise URDFError(f"joint {jname!r} axis must be non-zero, got {axis.tolist()}")
        C = _axis_frame(axis / scale / np.linalg.norm(axis / scale))
        origins[-1] = T @ C
        origins.append(C.T.copy())
        lo, hi = _limits(el, jname, jtype)
        lower.append(lo)
        upper.append(hi)
        types.append("prismatic" if jtype == "prismatic" else "revolute")
        names.append(jname)
    if not types:
        end = tip_link if tip_link is not None else (_child(chain[-1]) if chain else base_link)
        raise URDFError(f"no movable joint between {base_link!r} and {end!r}")
    tip = _child(chain[-1])
    stem = Path(label).stem if label != "<URDF string>" else "urdf"
    default_name = f"{root.get('name', stem)}:{tip}"  # the file's name and the chain's tip
    try:
        return Robot(name=name or default_name,
                     origins=np.array(origins), lower=lower, upper=upper,
                     joint_types=tuple(types), joint_names=tuple(names), unit="m",
                     source=f"URDF {Path(label).name}: {base_link} -> {tip}",
                     description=URDFDescription(
                         source=source if label == "<URDF string>" else Path(label).resolve(),
                         package_dirs=package_dirs, srdf=srdf))
    except URDFError:
        raise
    except MoikError as exc:  # limits, reach: say which file
        raise URDFError(f"{label!r} ({base_link} -> {tip}): {exc}") from exc


MAX_URDF_BYTES = 64 * 2**20
"""Size of a URDF file moik reads."""
MAX_LIMIT = 1e6
"""Magnitude of a joint limit (rad or m): a larger one is no physical limit (-1e308 would
overflow the solver's arithmetic)."""


def _limits(el: ET.Element, name: str, jtype: str) -> tuple[float, float]:
    if jtype == "continuous":
        return -np.pi, np.pi
    lim = el.find("limit")
    lo, hi = (None, None) if lim is None else (lim.get("lower"), lim.get("upper"))
    if lo is None or hi is None:
        raise URDFError(f"joint {name!r} ({jtype}) needs <limit lower= upper=>")
    try:
        values = float(lo), float(hi)
    except ValueError:
        raise URDFError(f"joint {name!r} limits must be numbers") from None
    if not all(abs(v) <= MAX_LIMIT for v in values):
        raise URDFError(f"joint {name!r} limits must lie within +-{MAX_LIMIT:g} (rad or m), got "
                        f"lower={lo}, upper={hi}; an unlimited revolute joint is "
                        "type=\"continuous\"")
    return values


def absolute_package_dirs(package_dirs: Any) -> Any:
    """``package_dirs`` checked (:func:`check_package_dirs`), each folder made absolute (``~``
    expanded; links kept as named): the robot keeps them, and a later ``os.chdir`` must not
    change where its meshes are found."""
    check_package_dirs(package_dirs)
    if package_dirs is None:
        return None
    if isinstance(package_dirs, Mapping):
        return {name: Path(folder).expanduser().absolute() for name, folder in package_dirs.items()}
    if isinstance(package_dirs, str | Path):
        return [Path(package_dirs).expanduser().absolute()]
    return [Path(folder).expanduser().absolute() for folder in package_dirs]


def check_package_dirs(package_dirs: Any) -> None:
    """``package_dirs`` as :func:`load_urdf` takes it: ``None``, a folder, a sequence of
    folders or ``{package name: folder}``, each folder (str or Path) existing.

    Raises:
        ParameterError: Anything else, named.
    """
    if package_dirs is None:
        return
    if isinstance(package_dirs, Mapping):
        entries = list(package_dirs.items())
    elif isinstance(package_dirs, str | Path):
        entries = [(None, package_dirs)]
    elif isinstance(package_dirs, Sequence) and not isinstance(package_dirs, bytes | bytearray):
        entries = [(None, folder) for folder in package_dirs]
    else:
        raise ParameterError("package_dirs must be a folder, a list of folders or "
                             f"{{package name: folder}}, got {type(package_dirs).__name__}")
    for name, folder in entries:
        if (name is not None and not isinstance(name, str)) or not isinstance(folder, str | Path):
            given = f"{name!r}: {folder!r:.80}" if name is not None else f"{folder!r:.80}"
            raise ParameterError("package_dirs entries must be folders (str or Path), keyed "
                                 f"by package name (str) in a mapping; got {given}")
        if not Path(folder).expanduser().is_dir():
            raise ParameterError(f"package_dirs: {str(folder)!r} is not a folder"
                                 f"{f' (package {name!r})' if name is not None else ''}")
