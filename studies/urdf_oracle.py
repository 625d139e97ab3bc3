"""An independent oracle of a URDF arm's self-collision: coal on every link's own geometry.

Nothing of moik's geometry code is used: the URDF is parsed here (``xml.etree``), every
link below the base is placed by its own forward kinematics (``<origin xyz rpy>``,
``<axis>``, revolute/continuous/prismatic/fixed), the chain's joints at ``q`` and every
other movable joint at a stated value (given; else its zero clipped into its limits;
a ``<mimic>`` joint at ``multiplier * leader + offset``), and each link's ``<collision>``
elements become coal objects (meshes read with trimesh and scaled, boxes, spheres,
cylinders, capsules). A link's *body* is the number of the chain's joints on its path
from the base (a gripper's fingers are on the body of the link they hang from).

:meth:`URDFOracle.touching` says per configuration whether two links on bodies that are
not chain neighbours collide (``coal.collide``), the rule of
``studies/mesh_collision_check.py`` (a pair the allowed-collision matrix never checks
included); :meth:`URDFOracle.distances_to` each link's distance to an obstacle;
:meth:`URDFOracle.offchain_touch_neighbour` whether a link behind an off-chain
joint touches a link of the neighbouring body (a pair no body-level model checks).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import coal
import numpy as np
import trimesh
from scipy.spatial.transform import Rotation

MOVABLE = ("revolute", "continuous", "prismatic")


def _vec(el, attr: str, default) -> np.ndarray:
    text = None if el is None else el.get(attr)
    return np.array(default if text is None else [float(v) for v in text.split()], dtype=float)


def _pose(el) -> np.ndarray:
    origin = None if el is None else el.find("origin")
    T = np.eye(4)
    T[:3, :3] = Rotation.from_euler("xyz", _vec(origin, "rpy", (0, 0, 0))).as_matrix()
    T[:3, 3] = _vec(origin, "xyz", (0, 0, 0))
    return T


def _resolve(filename: str, urdf: Path, package_dirs) -> Path:
    if filename.startswith("package://"):
        package, _, rest = filename[len("package://"):].partition("/")
        for folder in package_dirs:
            if (Path(folder) / package / rest).is_file():
                return Path(folder) / package / rest
        raise FileNotFoundError(filename)
    if filename.startswith("file://"):
        return Path(filename[len("file://"):])
    return urdf.parent / filename


def _geometry(g, urdf: Path, package_dirs):
    if g.tag == "mesh":
        mesh = trimesh.load(_resolve(g.get("filename"), urdf, package_dirs), force="mesh")
        V = np.asarray(mesh.vertices, dtype=float) * _vec(g, "scale", (1, 1, 1))
        bvh = coal.BVHModelOBBRSS()
        bvh.beginModel(len(mesh.faces), len(V))
        bvh.addVertices(np.ascontiguousarray(V))
        bvh.addTriangles(np.ascontiguousarray(mesh.faces, dtype=np.int64))
        bvh.endModel()
        return bvh
    if g.tag == "box":
        return coal.Box(*_vec(g, "size", None))
    if g.tag == "sphere":
        return coal.Sphere(float(g.get("radius")))
    build = coal.Cylinder if g.tag == "cylinder" else coal.Capsule
    return build(float(g.get("radius")), float(g.get("length")))


class URDFOracle:
    """Every link's collision geometry of ``urdf`` as coal objects, placed independently.

    Args:
        urdf: The URDF file.
        chain: The chain's joint names, in order (``robot.joint_names``).
        package_dirs: Folders holding the ``package://`` packages.
        joint_values: Values of movable joints outside the chain (others at their zero
            clipped into their limits; mimic joints follow their leader).
    """

    def __init__(self, urdf: Path, chain, package_dirs, joint_values=None) -> None:
        root = ET.parse(urdf).getroot()
        self.joints = {el.get("name"): el for el in root.findall("joint")}
        self.chain = list(chain)
        children = {el.find("child").get("link") for el in self.joints.values()}
        self.base = next(el.get("name") for el in root.findall("link")
                         if el.get("name") not in children)
        self.values = self._offchain(dict(joint_values or {}))
        self.geometry = {}  # link: [(coal geometry, pose in the link's frame)]
        for link in root.findall("link"):
            items = []
            for col in link.findall("collision"):
                for g in col.find("geometry"):
                    items.append((_geometry(g, urdf, package_dirs), _pose(col)))
            self.geometry[link.get("name")] = items
        self.body = {link: body for link, (body, _, _) in self._walk(
            np.zeros(len(self.chain))).items()}

    def _offchain(self, given: dict) -> dict:
        out = {}
        for name, el in self.joints.items():
            if el.get("type") not in MOVABLE or name in self.chain or el.find("mimic") is not None:
                continue
            lim = el.find("limit")
            lo = -np.inf if el.get("type") == "continuous" else float(lim.get("lower"))
            hi = np.inf if el.get("type") == "continuous" else float(lim.get("upper"))
            out[name] = given.get(name, min(max(0.0, lo), hi))
        for name, el in self.joints.items():
            m = el.find("mimic")
            if m is not None and name not in self.chain:
                out[name] = (float(m.get("multiplier", 1)) * out[m.get("joint")]
                             + float(m.get("offset", 0)))
        return out

    def _walk(self, q) -> dict:
        """``{link: (body, world pose, behind an off-chain joint)}`` at chain values ``q``."""
        values = dict(self.values, **dict(zip(self.chain, q, strict=True)))
        kids: dict = {}
        for el in self.joints.values():
            kids.setdefault(el.find("parent").get("link"), []).append(el)
        out, stack = {}, [(self.base, np.eye(4), 0, False)]
        while stack:
            link, T, body, off = stack.pop()
            out[link] = (body, T, off)
            for el in kids.get(link, []):
                Tj = T @ _pose(el)
                kind, name = el.get("type"), el.get("name")
                if kind in MOVABLE:
                    axis = _vec(el.find("axis"), "xyz", (1, 0, 0))
                    axis = axis / np.linalg.norm(axis)
                    M = np.eye(4)
                    if kind == "prismatic":
                        M[:3, 3] = values[name] * axis
                    else:
                        M[:3, :3] = Rotation.from_rotvec(values[name] * axis).as_matrix()
                    Tj = Tj @ M
                chained = name in self.chain
                stack.append((el.find("child").get("link"), Tj, body + chained,
                              off or (kind in MOVABLE and not chained)))
        return out

    def pose(self, q, link: str) -> np.ndarray:
        """The world pose of ``link`` at chain values ``q``."""
        return self._walk(q)[link][1]

    def _collide(self, placed, a: str, b: str) -> bool:
        req = coal.CollisionRequest()
        for ga, pa in self.geometry[a]:
            Ta = placed[a][1] @ pa
            for gb, pb in self.geometry[b]:
                Tb = placed[b][1] @ pb
                if coal.collide(ga, coal.Transform3s(Ta[:3, :3], Ta[:3, 3]), gb,
                                coal.Transform3s(Tb[:3, :3], Tb[:3, 3]), req,
                                coal.CollisionResult()):
                    return True
        return False

    def _pairs(self, neighbours: bool):
        links = [k for k in self.body if self.geometry.get(k)]
        offs = {k for k, (_, _, off) in self._walk(np.zeros(len(self.chain))).items() if off}
        for i, a in enumerate(links):
            for b in links[i + 1:]:
                gap = abs(self.body[a] - self.body[b])
                if (gap == 1 and (a in offs or b in offs)) if neighbours else gap > 1:
                    yield a, b

    def touching(self, Q) -> np.ndarray:
        """Per row of ``Q``: whether two links on non-neighbouring bodies collide."""
        return self._any(Q, list(self._pairs(False)))

    def offchain_touch_neighbour(self, Q) -> np.ndarray:
        """Per row of ``Q``: whether a link behind an off-chain joint collides with a link of
        a neighbouring body."""
        return self._any(Q, list(self._pairs(True)))

    def distances_to(self, q, geometry, pose: np.ndarray) -> dict:
        """``{link: coal's signed distance}`` from each link with geometry at ``q`` to a coal
        ``geometry`` at world ``pose`` (negative: penetrating)."""
        placed, req = self._walk(q), coal.DistanceRequest()
        req.enable_signed_distance = True
        other = coal.Transform3s(pose[:3, :3], pose[:3, 3])
        out = {}
        for link, items in self.geometry.items():
            if link in placed and items:
                out[link] = min(coal.distance(g, coal.Transform3s((placed[link][1] @ P)[:3, :3],
                                                                  (placed[link][1] @ P)[:3, 3]),
                                              geometry, other, req, coal.DistanceResult())
                                for g, P in items)
        return out

    def _any(self, Q, pairs) -> np.ndarray:
        out = np.zeros(len(Q), dtype=bool)
        for k, q in enumerate(Q):
            placed = self._walk(q)
            out[k] = any(self._collide(placed, a, b) for a, b in pairs)
        return out
