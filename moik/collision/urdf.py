"""A :class:`CollisionModel` from a URDF's ``<collision>`` geometry: primitives and meshes.

The geometry of every link below the chain's base is used: links behind movable joints
outside the chain (a gripper's fingers) ride on the body of the chain link they hang
from, at the joint values the caller gives or their zero clipped into their limits
(``joint_values=``, :mod:`moik.robots.urdf_joints`; the model's ``source`` says where
each was placed, and the caches below are keyed by those values too).

Boxes, spheres and capsules are taken as they are; a cylinder becomes a compound: its
enclosing capsule holding a 32-sided prism that holds the cylinder
(:mod:`moik.collision.prism`); meshes (``package://``, ``file://`` or
file paths, :mod:`moik.collision.meshes`) are read and each link's become one
:class:`~moik.collision.shapes.Compound`: a capsule fitted to their triangles
(:mod:`moik.collision.mesh_fit`: every triangle inside), cached on disk, holding the
convex hulls of pieces of the triangles (every triangle in one piece: slabs along the
mesh's principal axis, cut further where a hull holds deep empty space,
:mod:`moik.collision.decompose`; cached on disk, :mod:`moik.collision.mesh_pieces`; a hull
of a piece with more than :data:`~moik.collision.outer_hull.MAX_EXACT_VERTICES` vertices is
replaced by an enclosing polytope with fewer, about 0.5 mm outside it:
:mod:`moik.collision.outer_hull`).
The kernels measure a pair on the capsules and, where they come close, on the hulls
(:mod:`moik.collision.gjk`): the hulls hold the meshes, so a configuration called free
is free for the meshes, and they follow a link far closer than one capsule. Bodies are
named by their URDF links.

The allowed-collision matrix is sampled as MoveIt's setup assistant does
(:func:`moik.collision.acm.cached_allowed`: adjacent links and the pairs in collision in
none of ``samples`` random configurations are not checked), judged on the compounds'
parts (the capsules, and the hulls where they overlap), and cached on disk by the chain,
the shapes, their hulls and the settings. MoveIt's third rule, pairs in collision (nearly)
always, is not applied (a pair never checked must never touch, and convex pieces that
always overlap say nothing of the meshes inside them, which may touch only sometimes):
such pairs are named in a :class:`~moik.exceptions.GeometryWarning` and the model's
``source`` instead, since every answer will be rejected for them.

A body of the chain with no collision geometry at all is an error (a check that
silently skips a link is no check): pass ``missing="ignore"`` to accept it; the
model's ``source`` then names the bodies left unchecked.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from moik._validate import choice, integer
from moik.collision.acm import DEFAULT_SAMPLES, cached_allowed
from moik.collision.fit import body_axes
from moik.collision.mesh_fit import cached_link_fit
from moik.collision.mesh_pieces import parts_of_meshes
from moik.collision.meshes import LARGEST_SIZE, read_mesh, resolve_mesh
from moik.collision.model import CollisionModel
from moik.collision.prism import cylinder_compound
from moik.collision.shapes import Box, Capsule, Compound, ConvexHull, Shape, Sphere
from moik.collision.srdf import body_pairs
from moik.exceptions import GeometryError, MoikError
from moik.robots.chain import Robot
from moik.robots.urdf_geometry import (
    collision_geometry,
    link_placements,
    mesh_geometry,
    offchain_placement,
    urdf_links,
)

MISSING = ("error", "ignore")


def _shape(item: dict[str, Any], label: str) -> Shape:
    """The primitive of a URDF ``<collision>`` item; its sizes within the sizes a mesh may
    have (:data:`~moik.collision.meshes.LARGEST_SIZE`: metres), an error naming the link."""
    kind, pose = item["type"], item["pose"]
    what = f"{label}: <{'cylinder' if kind == 'cylinder' else kind}> of link {item['link']!r}"
    sizes = {"box": ("size",), "sphere": ("radius",)}.get(kind, ("radius", "length"))
    for key in sizes:
        value = np.asarray(item.get(key, np.nan), dtype=float)
        if not np.all(np.isfinite(value)):
            raise GeometryError(f"{what} needs a finite {key}=, got {item.get(key)}")
        if np.any(value <= 0) or np.any(value > LARGEST_SIZE):
            raise GeometryError(f"{what}: {key} must be in (0, {LARGEST_SIZE:g}] m (a URDF's "
                                f"unit is the metre), got {value.tolist()}")
    try:
        if kind == "box":
            return Box(size=item["size"], pose=pose)
        if kind == "sphere":
            return Sphere(radius=item["radius"], pose=pose)
        build = Capsule if kind == "capsule" else cylinder_compound
        return build(radius=item["radius"], length=item["length"], pose=pose)
    except MoikError as exc:
        raise GeometryError(f"{what}: {exc}") from None


def _urdf_dir(source: Any) -> Path | None:
    if isinstance(source, str) and source.lstrip().startswith("<"):
        return None
    return Path(source).resolve().parent


MESH_REACH_FACTOR = 10.0
"""A link's mesh larger than this many reaches of the arm is refused: a unit mistake (a mesh
in millimetres without ``scale``, or a scale of 1000), never a link left practically
unchecked inside a capsule of tens of metres."""


def _check_against_reach(mesh: Any, robot: Robot, *, link: str, path: Any, scale: Any) -> None:
    size = float(np.ptp(mesh.vertices, axis=0).max())
    if size > MESH_REACH_FACTOR * robot.reach:
        raise GeometryError(
            f"link {link!r}: mesh {str(path)!r} is {size:.3g} m across after scale "
            f"{np.asarray(scale, dtype=float).tolist()}, more than {MESH_REACH_FACTOR:g}x the "
            f"arm's reach ({robot.reach:.3g} m): a URDF's unit is the metre (a mesh in "
            "millimetres needs scale=\"0.001 0.001 0.001\")")


def mesh_shapes(source: Any, robot: Robot, *, package_dirs: Any = None,
                use_cache: bool = True, joint_values: Any = None) -> dict[str, Compound]:
    """Every URDF link with ``<collision>`` meshes as a :class:`Compound` in the frame of the
    body the link is on: a capsule fitted to its triangles holding the hulls of pieces of
    them (:mod:`moik.collision.decompose`), ``{link: Compound}``. Links behind off-chain
    joints are placed at ``joint_values`` (:mod:`moik.robots.urdf_joints`): their pose on the body
    is part of the fit's cache key, so another placement is fitted anew.

    Raises:
        GeometryError: A mesh not found (the message says where it was looked for),
            unreadable, empty, non-finite, or of an absurd size (outside [1 um, 100 m], or
            more than :data:`MESH_REACH_FACTOR` reaches of the arm).
    """
    _, items = mesh_geometry(source, robot, "collision", joint_values=joint_values)
    folder = _urdf_dir(source)
    by_link: dict[str, list[dict[str, Any]]] = {}
    for item in items:
        by_link.setdefault(item["link"], []).append(item)
    candidates = body_axes(robot) if by_link else []
    meshes, bounds = [], []
    for link, group in by_link.items():
        body = group[0]["body"]
        vertices, faces, identity = [], [], []
        offset = 0
        for item in group:
            path = resolve_mesh(item["filename"], link=link, urdf_dir=folder,
                                package_dirs=package_dirs)
            mesh = read_mesh(path, link=link, scale=item["scale"])
            _check_against_reach(mesh, robot, link=link, path=path, scale=item["scale"])
            pose = np.asarray(item["pose"], dtype=float)
            vertices.append(mesh.vertices @ pose[:3, :3].T + pose[:3, 3])
            faces.append(mesh.faces + offset)
            offset += len(mesh.vertices)
            identity += [mesh.digest, np.asarray(item["scale"], dtype=float), pose]
        V, F = np.vstack(vertices), np.vstack(faces)
        (a, b, r), = cached_link_fit(V, F, identity=identity, axes=candidates[body], capsules=1,
                                     split_gain=0.85, use_cache=use_cache)
        meshes.append((V, F, identity))
        bounds.append(Capsule.between(a.tolist(), b.tolist(), r))
    parts = parts_of_meshes(meshes, use_cache=use_cache)  # the links side by side
    return {link: Compound(bound=bound, parts=tuple(ConvexHull(points=P) for P in pieces))
            for link, bound, pieces in zip(by_link, bounds, parts, strict=True)}


def model_from_urdf(source: Any, robot: Robot, *, package_dirs: Any = None,
                    missing: str = "error", samples: int = DEFAULT_SAMPLES,
                    use_cache: bool = True, joint_values: Any = None,
                    srdf: Any = None) -> CollisionModel:
    """The URDF's collision geometry on ``robot``, with its sampled allowed-collision matrix.

    Args:
        source: The URDF file path or text ``robot`` was loaded from.
        robot: The robot :func:`~moik.robots.urdf.load_urdf` returned for it.
        package_dirs: Where ``package://`` meshes are found
            (:func:`moik.collision.meshes.resolve_mesh`).
        missing: ``"error"``: a body with no collision geometry raises;
            ``"ignore"``: such bodies are left unchecked (named in the model's ``source``).
        samples: Random configurations of the allowed-collision matrix (0: none
            sampled; only adjacent links are skipped).
        use_cache: Read and write the fits and the matrix in the disk cache.
        joint_values: ``{joint: value}`` for movable joints outside ``robot``'s chain
            (e.g. ``{"panda_finger_joint1": 0.04}``, fingers open): the links behind them
            are on the body of the chain link they hang from, placed there; a joint not
            given is at its zero clipped into its limits, a ``<mimic>`` joint follows its
            leader (:mod:`moik.robots.urdf_joints`). The model's ``source`` says where
            each was placed.
        srdf: A MoveIt SRDF (path or XML text) whose disabled pairs are not checked, a
            body pair when all its links' pairs are (:mod:`moik.collision.srdf`; named in
            the model's ``source``); the sampled matrix adds its own.

    Raises:
        ParameterError: ``joint_values`` names a joint that is not an off-chain joint of
            the URDF, or a value that is not finite or outside the joint's limits.
        URDFError: The URDF is not ``robot``'s; an off-chain joint that cannot be placed
            (a mimic of a chain joint, a floating joint with links behind it).
        GeometryError: A mesh that cannot be used (see :func:`mesh_shapes`), a body
            without geometry (``missing="error"``), an SRDF that cannot be read or names
            links the URDF does not have.
    """
    missing = choice("missing", missing, MISSING)
    samples = integer("samples", samples, minimum=0)
    placement = offchain_placement(source, robot, joint_values)
    names, items = collision_geometry(source, robot, joint_values=joint_values)
    shapes: dict[str, list[Shape]] = {}
    origins: dict[str, list[str]] = {}  # the URDF link of each shape
    for item in items:
        if not item.get("skipped"):
            shapes.setdefault(names[item["body"]], []).append(
                _shape(item, robot.source or robot.name))
            origins.setdefault(names[item["body"]], []).append(item["link"])
    fitted = mesh_shapes(source, robot, package_dirs=package_dirs, use_cache=use_cache,
                         joint_values=joint_values)
    body_of = {item["link"]: item["body"] for item in items}
    for link, compound in fitted.items():
        shapes.setdefault(names[body_of[link]], []).append(compound)
        origins.setdefault(names[body_of[link]], []).append(link)
    shapes = {name: shapes[name] for name in names if name in shapes}  # in body order
    bare = [name for name in names if name not in shapes]
    label = robot.source or robot.name
    if bare and missing == "error":
        raise GeometryError(f"{label}: bodies {bare} have no <collision> geometry, so their "
                            "collisions cannot be checked; add <collision> elements to the URDF, "
                            "or pass missing='ignore' to leave them unchecked")
    source_text = (f"<collision> geometry of {label} (meshes: convex hulls of pieces of each "
                   "link's triangles in a fitted enclosing capsule; cylinders: a prism holding "
                   "each, in its enclosing capsule)")
    if placement:
        source_text += ("; off-chain joints placed at "
                        + ", ".join(p.describe(n) for n, p in placement.items()))
    if bare:
        source_text += f"; bodies without geometry, NOT checked: {', '.join(bare)}"
    _, placed = link_placements(source, robot, joint_values=joint_values)
    aliases = {link: names[body] for link, (body, _) in placed.items() if link not in names}
    model = CollisionModel(robot=robot, shapes=shapes, links=tuple(names), source=source_text,
                           aliases=aliases, origins={n: origins[n] for n in shapes})
    if srdf is not None:
        pairs, srdf_label = body_pairs(model, srdf, urdf_links(source))
        model = CollisionModel(robot=robot, shapes=shapes, links=tuple(names),
                               allowed=frozenset(frozenset(p) for p in pairs),
                               source=f"{source_text}; SRDF {srdf_label}: {len(pairs)} body "
                                      "pairs not checked",
                               aliases=aliases, origins=model.origins)
    values = {n: p.value for n, p in placement.items()}
    return cached_allowed(model, samples, use_cache, values) if samples else model


def robot_model(robot: Robot, *, missing: str = "error", joint_values: Any = None
                ) -> CollisionModel:
    """:func:`model_from_urdf` of the URDF ``robot`` was loaded from (``robot.description``),
    its off-chain joints at ``joint_values`` (as there; a solve's default model has them
    at their defaults: pass ``collision=robot_model(robot, joint_values=...)`` for others).

    Raises:
        GeometryError: ``robot`` was not loaded from a URDF.
    """
    desc = robot.description
    if desc is None:
        raise GeometryError(f"robot {robot.name!r} was not loaded from a URDF: it has no collision "
                            "geometry of its own; pass collision= a CollisionModel")
    return model_from_urdf(desc.source, robot, package_dirs=desc.package_dirs, missing=missing,
                           joint_values=joint_values, srdf=desc.srdf)
