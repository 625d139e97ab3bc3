"""A robot's collision geometry, a scene of obstacles, and the compiled checker of both.

* :class:`CollisionModel`: shapes attached to the robot's bodies. Body ``j`` is the
  frame :meth:`Robot.frames` numbers ``j`` (0: the base, ``j``: moved by joints
  ``1 .. j``); bodies are named (``links``; default ``"link0" .. "link<dof>"``, URDF
  models use the URDF link names) and shapes are given per name. An allowed-collision
  matrix (``allowed``: pairs of link names never checked) comes on top of the rule
  that a body is never checked against itself or its neighbours in the chain
  (MoveIt's "adjacent" pairs); :func:`moik.collision.acm.sample_allowed` finds the
  pairs that never or always touch by sampling, as MoveIt's setup assistant does.
* :class:`Scene`: named obstacles in the world frame.
* :class:`CollisionChecker`: one model and (optionally) one scene compiled into the
  arrays of :mod:`moik.collision.kernels`, with batched distances, the minimum, its
  gradient, and per-pair distances.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from moik._validate import flag
from moik.collision import kernels
from moik.collision.compiled import CollisionSet, collision_set, smallest_distances
from moik.collision.shapes import (
    Box,
    Compound,
    ConvexHull,
    HalfSpace,
    Shape,
    expand_compounds,
    hull_arrays,
    hull_capsules,
    refinements,
    shape_arrays,
)
from moik.exceptions import GeometryError, ParameterError, UnknownNameError
from moik.robots.chain import Robot


def default_links(robot: Robot) -> tuple[str, ...]:
    """``("link0", ..., "link<dof>")``: the names of a robot's bodies without a URDF."""
    return tuple(f"link{j}" for j in range(robot.dof + 1))


def _shapes(owner: str, shapes: Any) -> tuple[Shape, ...]:
    items = (shapes,) if isinstance(shapes, Shape) else tuple(shapes)
    for s in items:
        if not isinstance(s, Shape):
            raise GeometryError(f"{owner} must be moik.collision shapes (Sphere, Capsule, Box, "
                                f"HalfSpace), got {type(s).__name__}")
    return items


@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class CollisionModel:
    """Collision shapes on a robot's bodies, and the body pairs never checked.

    Args:
        robot: The arm.
        shapes: ``{link name: shape or shapes}`` in that link's frame.
        links: The names of bodies ``0 .. dof`` (default :func:`default_links`).
        allowed: Pairs of link names whose collisions are not checked (besides a link
            with itself and its chain neighbours).
        source: Where the geometry comes from.
        aliases: ``{other link name: one of links}``: a URDF's links fixed to a body (its
            root above the base, ``tool0``, ...), accepted wherever a link is named. A
            scene's allowed pair naming one skips only that link's own shapes (see
            ``origins``); naming the body skips every shape on it. In ``allowed`` (self
            pairs, checked per body) an alias stands for its body, and is refused where
            the body also carries other links' shapes (allowing it would skip them too).
        origins: ``{link: the link each of its shapes belongs to}``: for a body, its own
            name or an alias (a URDF link fixed to it) per shape, in order (default: every
            shape the body's own).

    Raises:
        UnknownNameError: A link name that is not one of ``links`` (or ``aliases``).
        GeometryError: A half-space on a link, a wrong number of link names, not shapes.
    """

    robot: Robot
    shapes: Mapping[str, Any]
    links: tuple[str, ...] = ()
    allowed: frozenset[frozenset[str]] = field(default_factory=frozenset)
    source: str = ""
    aliases: Mapping[str, str] = field(default_factory=dict)
    origins: Mapping[str, Sequence[str]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if not isinstance(self.robot, Robot):
            raise GeometryError(f"robot must be a moik Robot, got {type(self.robot).__name__}")
        links = tuple(self.links) or default_links(self.robot)
        if len(links) != self.robot.dof + 1 or len(set(links)) != len(links):
            raise GeometryError(f"links must be {self.robot.dof + 1} distinct names (the base and "
                                f"one per joint of {self.robot.name!r}), got {list(links)}")
        object.__setattr__(self, "links", links)
        if not isinstance(self.shapes, Mapping):
            raise GeometryError("shapes must be a mapping {link name: shapes}, got "
                                f"{type(self.shapes).__name__}")
        checked: dict[str, tuple[Shape, ...]] = {}
        for link, shapes in self.shapes.items():
            if link not in links:
                raise UnknownNameError(f"link of robot {self.robot.name!r}", link, links)
            items = _shapes(f"shapes of link {link!r}", shapes)
            if any(isinstance(s, HalfSpace) for s in items):
                raise GeometryError(f"link {link!r}: a half-space is unbounded and cannot be part "
                                    "of a robot; use a box")
            checked[link] = items
        object.__setattr__(self, "shapes", checked)
        if not isinstance(self.aliases, Mapping) or any(
                not isinstance(k, str) or k in links or v not in links
                for k, v in self.aliases.items()):
            raise GeometryError("aliases must map other link names to names of links, got "
                                f"{self.aliases!r:.200}")
        object.__setattr__(self, "aliases", dict(self.aliases))
        object.__setattr__(self, "origins", self._checked_origins())
        for pair in self.allowed:
            for name in pair:
                body = self.body_name(name)
                others = sorted(set(self.origins.get(body, ())) - {name})
                if name != body and others:
                    raise GeometryError(
                        f"allowed pair {sorted(pair)}: {name!r} is fixed to {body!r}, which also "
                        f"carries the geometry of {others}; self pairs are checked per body, so "
                        f"allowing {name!r} would skip that too: name {body!r} to allow the "
                        "whole body")
        object.__setattr__(self, "allowed", frozenset(
            frozenset(self.body_name(name) for name in pair) for pair in self.allowed))

    def _checked_origins(self) -> dict[str, tuple[str, ...]]:
        if not isinstance(self.origins, Mapping):
            raise GeometryError(f"origins must map links to link names, got {self.origins!r:.200}")
        out = {}
        for link, shapes in self.shapes.items():
            given = tuple(self.origins.get(link, (link,) * len(shapes)))
            if len(given) != len(shapes) or any(
                    o != link and self.aliases.get(o) != link for o in given):
                raise GeometryError(f"origins of link {link!r} must name, for each of its "
                                    f"{len(shapes)} shapes, {link!r} or a link fixed to it "
                                    f"(aliases), got {list(given)!r:.200}")
            out[link] = given
        unknown = set(self.origins) - set(self.shapes)
        if unknown:
            raise GeometryError(f"origins name links without shapes: {sorted(unknown)}")
        return out

    @property
    def item_origins(self) -> list[str]:
        """The link each shape of :attr:`items` belongs to (its body or a link fixed to it)."""
        return [o for link in self.shapes for o in self.origins[link]]

    @property
    def unchecked_links(self) -> tuple[str, ...]:
        """The links (bodies) with no geometry: never checked (a URDF model built with
        ``missing="ignore"``, or a model that leaves them out)."""
        return tuple(name for name in self.links if name not in self.shapes)

    def body_name(self, name: str) -> str:
        """The link (body) ``name`` is on: itself, or for a URDF link fixed to a body
        (:attr:`aliases`, e.g. ``base_link`` under ``world``) that body's name.

        Raises:
            UnknownNameError: ``name`` is neither.
        """
        if name in self.links:
            return name
        if isinstance(name, str) and name in self.aliases:
            return self.aliases[name]
        raise UnknownNameError(f"link of robot {self.robot.name!r}", name,
                               [*self.links, *self.aliases])

    @property
    def items(self) -> list[tuple[int, Shape]]:
        """``(body index, shape)`` for every shape, in link order."""
        index = {name: j for j, name in enumerate(self.links)}
        return [(index[link], s) for link, shapes in self.shapes.items() for s in shapes]

    def checked_body_pairs(self) -> list[tuple[int, int]]:
        """Body pairs ``i < j`` checked for self-collision (not adjacent, not allowed)."""
        used = sorted({b for b, _ in self.items})
        return [(i, j) for i in used for j in used if j > i + 1
                and frozenset((self.links[i], self.links[j])) not in self.allowed]

    def __repr__(self) -> str:
        n = sum(len(s) for s in self.shapes.values())
        return (f"CollisionModel({self.robot.name!r}, {n} shapes on {len(self.shapes)} of "
                f"{len(self.links)} links, {len(self.allowed)} allowed pairs)")

    def with_allowed(self, pairs: Iterable[Sequence[str]]) -> CollisionModel:
        """The model with ``pairs`` added to the allowed-collision matrix."""
        return CollisionModel(robot=self.robot, shapes=self.shapes, links=self.links,
                              allowed=self.allowed | {frozenset(p) for p in pairs},
                              source=self.source, aliases=self.aliases, origins=self.origins)


@dataclass(frozen=True, eq=False, repr=False)
class Scene:
    """Obstacles in the world frame (the robot's base frame is placed by ``robot.base``).

    Args:
        obstacles: ``{name: shape}`` (or a sequence of shapes, named ``obstacle0`` ...).
        allowed: ``(obstacle name, link name)`` pairs never checked (the table an arm is
            mounted on and its base link, as in MoveIt's allowed-collision matrix); the link
            names are checked against the model when a :class:`CollisionChecker` is built.
    """

    obstacles: Mapping[str, Shape] = field(default_factory=dict)
    allowed: frozenset[tuple[str, str]] = field(default_factory=frozenset)

    def __post_init__(self) -> None:
        pairs = frozenset(tuple(p) for p in self.allowed)
        if any(len(p) != 2 for p in pairs):
            raise GeometryError("scene allowed pairs must be (obstacle name, link name) pairs")
        object.__setattr__(self, "allowed", pairs)
        obs = self.obstacles
        if not isinstance(obs, Mapping):
            obs = {f"obstacle{k}": s for k, s in enumerate(_shapes("scene obstacles", obs))}
        for name, s in obs.items():
            if not isinstance(name, str) or not name:
                raise GeometryError(f"obstacle names must be non-empty strings, got {name!r}")
            _shapes(f"obstacle {name!r}", s)
        object.__setattr__(self, "obstacles", dict(obs))
        for name, _ in self.allowed:
            if name not in self.obstacles:
                raise UnknownNameError("obstacle", name, self.obstacles)

    def __repr__(self) -> str:
        items = ", ".join(f"{name!r}: {shape!r}" for name, shape in self.obstacles.items())
        allowed = f", allowed={sorted(self.allowed)}" if self.allowed else ""
        return f"Scene({{{items}}}{allowed})"


SCENE_RANGE_FACTOR = 100.0
"""An obstacle wholly farther than this many reaches from the arm's base is refused: a scene
in other units (millimetres for an arm in metres), never a silent "collision-free"."""


def _bounding_radius(shape: Shape) -> float | None:
    """Radius of a sphere about the shape's origin that holds it (None: unbounded)."""
    if isinstance(shape, HalfSpace):
        return None
    if isinstance(shape, ConvexHull):
        return shape.sizes[1]
    if isinstance(shape, Compound):
        return _bounding_radius(shape.bound)  # its pose is the bound's, which holds it
    if isinstance(shape, Box):
        return float(np.linalg.norm(shape.sizes))  # half extents: the half diagonal
    return shape.sizes[0] + shape.sizes[1]  # sphere (r, 0, 0), capsule (r, h, 0)


def check_scene_for(model: CollisionModel, scene: Scene) -> None:
    """Refuse a scene that cannot be meant for ``model``'s arm: an obstacle with the name of
    one of its links or shapes (a pair ``link - obstacle`` would read as a self pair), or
    an obstacle larger than :data:`SCENE_RANGE_FACTOR` reaches (its bounding radius) or
    wholly beyond that many reaches of the base (a scene in other units).

    Raises:
        GeometryError: Naming the obstacle.
    """
    names = set(model.links) | set(shape_names(model))
    robot = model.robot
    base = np.asarray(robot.base, dtype=float)[:3, 3]
    for name, shape in scene.obstacles.items():
        if name in names:
            raise GeometryError(f"obstacle {name!r} has the name of a link or shape of "
                                f"{robot.name!r}: give it another name")
        radius = _bounding_radius(shape)
        if radius is None:
            continue
        with np.errstate(over="ignore", invalid="ignore"):
            gap = float(np.linalg.norm(shape.pose[:3, 3] - base)) - radius
        if not radius <= SCENE_RANGE_FACTOR * robot.reach:
            raise GeometryError(
                f"obstacle {name!r} extends {radius:.4g} {robot.unit} from its centre, more "
                f"than {SCENE_RANGE_FACTOR:g}x the reach of {robot.name!r} ({robot.reach:.4g} "
                f"{robot.unit}); expected a scene in {robot.unit} (a floor: a half-space)")
        if not gap <= SCENE_RANGE_FACTOR * robot.reach:
            raise GeometryError(
                f"obstacle {name!r} lies {gap:.4g} {robot.unit} from the base of "
                f"{robot.name!r}, more than {SCENE_RANGE_FACTOR:g}x its reach "
                f"({robot.reach:.4g} {robot.unit}); expected a scene in {robot.unit}")


def shape_names(model: CollisionModel) -> list[str]:
    """The names of a model's shapes, in :attr:`CollisionModel.items` order: the link's name
    when the link has one shape, else ``link#k``, its ``k``-th shape (from 1, in the order
    given)."""
    names = []
    for link, shapes in model.shapes.items():
        names += [link] if len(shapes) == 1 else [f"{link}#{k}" for k in range(1, len(shapes) + 1)]
    return names


def keeps_clearance(distances, clearance: float):
    """Whether signed distances keep ``clearance`` (``distance >= clearance``; NaN never
    does): the one place moik writes this rule (a bool, or a bool array for an array)."""
    if isinstance(distances, float):
        return bool(distances >= clearance)  # NaN >= x is False too
    ok = np.greater_equal(distances, clearance)
    return bool(ok) if np.ndim(ok) == 0 else ok


class CollisionChecker:
    """A model (self-collision) and a scene, compiled for batched distance queries.

    Args:
        model: The robot's :class:`CollisionModel`.
        scene: Obstacles (or ``None``).
        self_collision: Whether the model's checked body pairs are evaluated (off by
            default, as in :func:`~moik.solver.solve_ik`).

    The pairs are the robot's checked self pairs (if ``self_collision``) and every robot
    shape against every obstacle; :attr:`pair_names` names them (:func:`shape_names`).
    """

    def __init__(self, *, model: CollisionModel, scene: Scene | None = None,
                 self_collision: bool = False) -> None:
        if not isinstance(model, CollisionModel):
            raise GeometryError(f"model must be a CollisionModel, got {type(model).__name__}")
        if scene is not None and not isinstance(scene, Scene):
            raise GeometryError(f"scene must be a Scene, got {type(scene).__name__}")
        self.model, self.scene = model, scene
        self.self_collision = flag("self_collision", self_collision)
        if scene is not None:
            check_scene_for(model, scene)
        if scene is None and not self.self_collision:
            raise ParameterError("a CollisionChecker with nothing to check: pass scene= and/or "
                                 "self_collision=True")
        items = model.items
        tops = [s for _, s in items] + list(() if scene is None else scene.obstacles.values())
        top_bodies = [b for b, _ in items] + [-1] * (len(tops) - len(items))
        names = list(shape_names(model)) + list(() if scene is None else scene.obstacles)
        shapes, bodies, parts = expand_compounds(tops, top_bodies)
        kinds, local, sizes = shape_arrays(shapes)
        hull_points, hull_ranges = hull_arrays(shapes, sizes)
        pairs = []
        if self.self_collision:  # item pairs a < b on checked body pairs, in that order
            checked = np.zeros((len(model.links), len(model.links)), dtype=bool)
            for i, j in model.checked_body_pairs():
                checked[i, j] = checked[j, i] = True
            on = np.array(top_bodies[:len(items)], dtype=np.int64)
            for a in range(len(items)):
                pairs += [(a, b) for b in (a + 1 + np.flatnonzero(checked[on[a], on[a + 1:]])
                                           ).tolist()]
        allowed = frozenset() if scene is None else scene.allowed
        for _, link in allowed:
            model.body_name(link)  # a link of the arm (or fixed to one of its bodies)
        origins = model.item_origins  # a body named skips all its shapes; a link its own
        obstacles = {} if scene is None else scene.obstacles
        pairs += [(a, len(items) + o) for a in range(len(items))
                  for o, obstacle in enumerate(obstacles)
                  if (obstacle, model.links[top_bodies[a]]) not in allowed
                  and (obstacle, origins[a]) not in allowed]
        refine = refinements(pairs, parts)
        self._shapes = {"body": np.array(bodies, dtype=np.int64), "local": local,
                        "kinds": kinds, "sizes": sizes,
                        "pairs": np.array(pairs, dtype=np.int64).reshape(-1, 2),
                        "refine": refine,
                        "hull_points": hull_points, "hull_ranges": hull_ranges,
                        "hull_caps": hull_capsules(shapes)}
        names = names + [f"{names[t]}.{i}" for t, ks in enumerate(parts) for i in range(len(ks))
                         if ks != [t]]
        bodies = top_bodies
        self.shape_names = tuple(names)
        self.pair_names = tuple((names[a], names[b]) for a, b in pairs)
        self.pair_bodies = tuple((bodies[a], bodies[b]) for a, b in pairs)  # -1: the world

    def __getstate__(self) -> dict:
        """The checker but its :attr:`compiled` value (a numba StructRef does not pickle; it
        is built again where the checker is unpickled)."""
        return {k: v for k, v in self.__dict__.items() if k != "compiled"}

    @property
    def robot(self) -> Robot:
        """The model's robot."""
        return self.model.robot

    @property
    def n_pairs(self) -> int:
        """Number of evaluated pairs."""
        return len(self.pair_names)

    def distances(self, q) -> np.ndarray:
        """Signed distance of every pair, ``(n, n_pairs)`` (or ``(n_pairs,)`` for one ``q``)."""
        Q = self.robot.check_q(q)
        Q2 = Q[None] if Q.ndim == 1 else Q
        out = np.empty((Q2.shape[0], self.n_pairs))
        kernels.pair_distances(self.compiled, Q2, out)
        return out[0] if Q.ndim == 1 else out

    def min_distance(self, q) -> np.ndarray:
        """Smallest signed distance over the pairs, ``(n,)`` (a float for one ``q``).

        ``inf`` when there is no pair to check.
        """
        Q = self.robot.check_q(q)
        d = self.min_distance_batch(Q[None] if Q.ndim == 1 else Q)
        return d[0] if Q.ndim == 1 else d

    def min_distance_batch(self, Q: np.ndarray) -> np.ndarray:
        """:meth:`min_distance` of a 2-D batch without the finiteness check (hot path)."""
        return smallest_distances(self.compiled, self.robot.kernel_batch(Q))[0]

    def closest_pair(self, q) -> tuple[float, tuple[str, str] | None]:
        """The smallest distance of one joint vector and the names of the pair attaining it."""
        Q = self.robot.check_q(q, "q")
        if Q.ndim != 1:
            raise GeometryError(f"closest_pair takes one joint vector, got shape {Q.shape}")
        d, which = smallest_distances(self.compiled, Q[None])
        return float(d[0]), (self.pair_names[which[0]] if which[0] >= 0 else None)

    def min_distance_and_gradient(self, q) -> tuple[np.ndarray, np.ndarray]:
        """Smallest distance ``(n,)`` and its gradient w.r.t. ``q``, ``(n, dof)``."""
        Q = self.robot.check_q(q)
        Q2 = Q[None] if Q.ndim == 1 else Q
        d, g = np.empty(Q2.shape[0]), np.empty((Q2.shape[0], self.robot.dof))
        kernels.min_distance_gradients(self.compiled, Q2, d, g)
        return (d[0], g[0]) if Q.ndim == 1 else (d, g)

    @property
    def compiled_arrays(self) -> dict[str, np.ndarray]:
        """The arrays of :attr:`compiled` but the arm's record (for a set of one's own:
        ``collision_set(chain=..., **checker.compiled_arrays)``)."""
        return dict(self._shapes)

    @cached_property
    def compiled(self) -> CollisionSet:
        """The checker as one compiled value (:class:`~moik.collision.compiled.CollisionSet`),
        for the solver's start loop."""
        return collision_set(chain=self.robot.chain_model, **self._shapes)

    def world_shapes(self, q) -> list[tuple[str, Shape]]:
        """Every shape placed in the world at one joint vector (for plots and oracles)."""
        frames = self.robot.frames(q)
        out: list[tuple[str, Shape]] = []
        for k, (b, s) in enumerate(self.model.items):
            out.append((self.shape_names[k], s.moved(frames[b])))
        if self.scene is not None:
            out += list(self.scene.obstacles.items())
        return out
