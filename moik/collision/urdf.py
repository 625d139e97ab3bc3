"""A :class:`CollisionModel` from a URDF's ``<collision>`` geometry: primitives and meshes.

Boxes, spheres and capsules are taken as they are; cylinders become their enclosing
capsules (:func:`moik.collision.shapes.cylinder`); meshes (``package://``, ``file://`` or
file paths, :mod:`moik.collision.meshes`) are read and enclosed in capsules fitted to
their triangles (:mod:`moik.collision.mesh_fit`: every triangle inside, so a
configuration the capsules call free is free for the meshes), cached on disk. Bodies
are named by their URDF links.

The allowed-collision matrix is sampled as MoveIt's setup assistant does
(:mod:`moik.collision.acm`: adjacent links and the pairs in collision in none of
``samples`` random configurations are not checked), judged on the meshes' convex hulls
(:func:`sample_never`: the capsules, and the exact stage where they overlap), and cached
on disk by the chain, the shapes, their hulls and the settings. MoveIt's third rule, pairs
in collision (nearly) always, is not applied: capsules that always overlap say nothing
of the meshes inside them, which may touch only sometimes (measured: UR5's base and
upper arm), and a pair never checked must never touch.

A body of the chain with no collision geometry at all is an error (a check that
silently skips a link is no check): pass ``missing="ignore"`` to accept it; the
model's ``source`` then names the bodies left unchecked.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from moik._validate import choice, integer
from moik.collision.acm import DEFAULT_SAMPLES
from moik.collision.exact import HULLS, ExactStage, hull_pieces
from moik.collision.fit import body_axes
from moik.collision.mesh_fit import cached_link_fit, digest, load_cached, store_cached
from moik.collision.meshes import read_mesh, resolve_mesh
from moik.collision.model import CollisionChecker, CollisionModel
from moik.collision.shapes import Box, Capsule, Shape, Sphere, cylinder
from moik.exceptions import GeometryError
from moik.robots.chain import Robot
from moik.robots.urdf_geometry import collision_geometry, mesh_geometry

MISSING = ("error", "ignore")
DEFAULT_CAPSULES = 1  # per link with meshes: the largest number of fitted capsules (measured:
# splitting a link's triangles in two gave halves whose capsules stick out beyond the one
# capsule around the whole link, and rejected more mesh-free configurations, not fewer)
ACM_SEED = 0
HULL_PIECES = 12  # convex hulls per link for the exact stage (slabs of its triangles)


def _shape(item: dict[str, Any]) -> Shape:
    kind, pose = item["type"], item["pose"]
    if kind == "box":
        return Box(size=item["size"], pose=pose)
    if kind == "sphere":
        return Sphere(radius=item["radius"], pose=pose)
    build = Capsule if kind == "capsule" else cylinder
    return build(radius=item["radius"], length=item["length"], pose=pose)


def _urdf_dir(source: Any) -> Path | None:
    if isinstance(source, str) and source.lstrip().startswith("<"):
        return None
    return Path(source).resolve().parent


def mesh_capsules(source: Any, robot: Robot, *, package_dirs: Any = None,
                  capsules: int = DEFAULT_CAPSULES, use_cache: bool = True
                  ) -> dict[str, list[Capsule]]:
    """The fitted capsules of every URDF link with ``<collision>`` meshes, in the frame of
    the body the link is on: ``{link: [Capsule, ...]}``.

    Raises:
        GeometryError: A mesh not found (the message says where it was looked for),
            unreadable, empty, non-finite, or of an absurd size.
    """
    _, items = mesh_geometry(source, robot, "collision")
    folder = _urdf_dir(source)
    by_link: dict[str, list[dict[str, Any]]] = {}
    for item in items:
        by_link.setdefault(item["link"], []).append(item)
    candidates = body_axes(robot) if by_link else []
    out: dict[str, list[Capsule]] = {}
    for link, group in by_link.items():
        body = group[0]["body"]
        vertices, faces, identity = [], [], []
        offset = 0
        for item in group:
            path = resolve_mesh(item["filename"], link=link, urdf_dir=folder,
                                package_dirs=package_dirs)
            mesh = read_mesh(path, link=link, scale=item["scale"])
            pose = np.asarray(item["pose"], dtype=float)
            vertices.append(mesh.vertices @ pose[:3, :3].T + pose[:3, 3])
            faces.append(mesh.faces + offset)
            offset += len(mesh.vertices)
            identity += [mesh.digest, np.asarray(item["scale"], dtype=float), pose]
        fits = cached_link_fit(np.vstack(vertices), np.vstack(faces), identity=identity,
                               axes=candidates[body], capsules=capsules, split_gain=0.85,
                               use_cache=use_cache)
        hulls = hull_pieces(np.vstack(vertices), np.vstack(faces), HULL_PIECES)
        out[link] = [Capsule.between(a.tolist(), b.tolist(), r) for a, b, r in fits]
        for capsule in out[link]:
            HULLS[capsule] = hulls  # the exact stage's geometry (moik.collision.exact)
    return out


def sample_never(model: CollisionModel, samples: int) -> list[tuple[str, str]]:
    """The body pairs in collision in none of ``samples`` random configurations (seed
    :data:`ACM_SEED`), judged on the meshes' hulls: the capsules first, the exact stage
    (:class:`~moik.collision.exact.ExactStage`) where they overlap."""
    checker = CollisionChecker(model=model)
    if checker.n_pairs == 0:
        return []
    Q = model.robot.random_q(samples, rng=np.random.default_rng(ACM_SEED))
    D = ExactStage(checker).distances(Q, below=0.0)
    hit: dict[tuple[int, int], bool] = {}
    for k, pair in enumerate(checker.pair_bodies):
        hit[pair] = hit.get(pair, False) or bool(np.any(D[:, k] < 0.0))
    return [(model.links[i], model.links[j]) for (i, j), h in hit.items() if not h]


def _cached_allowed(model: CollisionModel, samples: int, use_cache: bool) -> CollisionModel:
    """The model with :func:`sample_never`'s pairs allowed, read from the disk cache
    when there (keyed by the chain, the shapes, their hulls and the settings)."""
    robot = model.robot
    chain = robot.kinematic_chain
    parts: list[Any] = [{"samples": samples, "seed": ACM_SEED, "links": list(model.links),
                         "rule": "never, on the hulls"},
                        chain.origins, chain.joint_types.astype(float), robot.lower, robot.upper]
    for body, shape in model.items:
        parts += [body, type(shape).__name__, shape.pose, np.array(shape.sizes),
                  *HULLS.get(shape, [])]
    key = digest(parts)
    cached = load_cached("acm", key) if use_cache else None
    if isinstance(cached, list) and all(isinstance(p, list) and len(p) == 2
                                        and all(n in model.links for n in p) for p in cached):
        return model.with_allowed(cached)
    never = sample_never(model, samples)
    if use_cache:
        store_cached("acm", key, sorted(sorted(p) for p in never))
    return model.with_allowed(never)


def model_from_urdf(source: Any, robot: Robot, *, package_dirs: Any = None,
                    missing: str = "error", capsules: int = DEFAULT_CAPSULES,
                    samples: int = DEFAULT_SAMPLES, use_cache: bool = True) -> CollisionModel:
    """The URDF's collision geometry on ``robot``, with its sampled allowed-collision matrix.

    Args:
        source: The URDF file path or text ``robot`` was loaded from.
        robot: The robot :func:`~moik.robots.urdf.load_urdf` returned for it.
        package_dirs: Where ``package://`` meshes are found
            (:func:`moik.collision.meshes.resolve_mesh`).
        missing: ``"error"``: a body with no collision geometry raises;
            ``"ignore"``: such bodies are left unchecked (named in the model's ``source``).
        capsules: The largest number of capsules fitted per link with meshes.
        samples: Random configurations of the allowed-collision matrix (0: none
            sampled; only adjacent links are skipped).
        use_cache: Read and write the fits and the matrix in the disk cache.

    Raises:
        URDFError: The URDF is not ``robot``'s. GeometryError: A mesh that cannot be used
            (see :func:`mesh_capsules`), a body without geometry (``missing="error"``).
    """
    missing = choice("missing", missing, MISSING)
    capsules = integer("capsules", capsules, minimum=1, maximum=16)
    samples = integer("samples", samples, minimum=0)
    names, items = collision_geometry(source, robot)
    shapes: dict[str, list[Shape]] = {}
    for item in items:
        if not item.get("skipped"):
            shapes.setdefault(names[item["body"]], []).append(_shape(item))
    fitted = mesh_capsules(source, robot, package_dirs=package_dirs, capsules=capsules,
                           use_cache=use_cache)
    body_of = {item["link"]: item["body"] for item in items}
    for link, caps in fitted.items():
        shapes.setdefault(names[body_of[link]], []).extend(caps)
    shapes = {name: shapes[name] for name in names if name in shapes}  # in body order
    bare = [name for name in names if name not in shapes]
    label = robot.source or robot.name
    if bare and missing == "error":
        raise GeometryError(f"{label}: bodies {bare} have no <collision> geometry, so their "
                            "collisions cannot be checked; add <collision> elements to the URDF, "
                            "or pass missing='ignore' to leave them unchecked")
    source_text = f"<collision> geometry of {label} (meshes in fitted enclosing capsules)"
    if bare:
        source_text += f"; bodies without geometry, NOT checked: {', '.join(bare)}"
    model = CollisionModel(robot=robot, shapes=shapes, links=tuple(names), source=source_text)
    return _cached_allowed(model, samples, use_cache) if samples else model


def robot_model(robot: Robot, *, missing: str = "error") -> CollisionModel:
    """:func:`model_from_urdf` of the URDF ``robot`` was loaded from (``robot.description``).

    Raises:
        GeometryError: ``robot`` was not loaded from a URDF.
    """
    desc = robot.description
    if desc is None:
        raise GeometryError(f"robot {robot.name!r} was not loaded from a URDF: it has no collision "
                            "geometry of its own; pass collision= a CollisionModel")
    return model_from_urdf(desc.source, robot, package_dirs=desc.package_dirs, missing=missing)
