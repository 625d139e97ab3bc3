"""Collision-aware acceptance of IK answers: the :class:`CollisionGuard` of one solve.

``solve_ik(..., scene=..., self_collision=..., clearance=d)`` (and ``solve_ik_batch``,
``solve_path``) accept a configuration only when its smallest signed distance (the
robot's checked self pairs when ``self_collision``, every robot shape against every
obstacle when a scene is given; :class:`~moik.collision.CollisionChecker`) is at least
``clearance``. The method is reject-and-restart: a converged Levenberg-Marquardt start
(or a polished search candidate) whose end collides is not counted as found, and the
start loop goes on with its further starts until enough collision-free solutions are
known or the budget is spent (:meth:`moik.solver.session.SolveSession.local_starts`).
The distances of the answers are recomputed at the end (:func:`moik.solver.result.ik_result`),
as the pose errors are.

``solve_ik_pareto`` takes the same arguments: its members keep the clearance, and the
criterion name ``"clearance"`` (maximise the smallest distance) becomes
:func:`clearance_criterion`.

Geometry of the robot: ``collision=`` a :class:`~moik.collision.CollisionModel` (of
this robot) or a ready :class:`~moik.collision.CollisionChecker` (used as it is: its
own scene and self pairs); by default (:func:`default_model`) the ``<collision>``
geometry of the URDF the robot was loaded from (``load_urdf(path, package_dirs=...)``, and
the catalog's panda, ur5 and iiwa14; :func:`moik.collision.urdf.robot_model`: its meshes as
compounds, fitted capsules holding the meshes' convex pieces, built once per robot and
cached on disk), else the shipped capsule model of a catalog arm
(:func:`moik.collision.collision_model`).

Never a silent answer: a check with no pair to evaluate (no shape on the robot, or every
pair allowed) is an error, not ``min_distance=inf``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any
from weakref import WeakKeyDictionary

import numpy as np

from moik._lazy import lazy_module
from moik._validate import flag, number
from moik.exceptions import GeometryError, ParameterError
from moik.kinematics.criteria import MAXIMIZE, Criterion
from moik.robots.chain import Robot

if TYPE_CHECKING:
    from moik.collision import catalog as collision_catalog
    from moik.collision import compiled as collision_compiled
    from moik.collision import io as collision_io
    from moik.collision import kernels as collision_kernels
    from moik.collision import model as collision_models
    from moik.collision import urdf as collision_urdf
    from moik.collision.model import CollisionChecker, CollisionModel, Scene
else:  # loaded when a solve checks collisions (moik._lazy): a blind solve imports none of it
    collision_catalog = lazy_module("moik.collision.catalog")
    collision_compiled = lazy_module("moik.collision.compiled")
    collision_kernels = lazy_module("moik.collision.kernels")
    collision_io = lazy_module("moik.collision.io")
    collision_models = lazy_module("moik.collision.model")
    collision_urdf = lazy_module("moik.collision.urdf")

COLLISION_OPTIONS = ("scene", "self_collision", "clearance", "collision")
_CHECKERS: dict[tuple[int, int, bool], tuple[Any, Any, CollisionChecker]] = {}
_MODELS: dict[str, CollisionModel] = {}
_URDF_MODELS: WeakKeyDictionary[Robot, CollisionModel] = WeakKeyDictionary()
_CACHE_SIZE = 16


@dataclass(frozen=True)
class CollisionGuard:
    """The collision test of one solve: a checker and the clearance an answer needs.

    Attributes:
        checker: The compiled pairs (self and/or scene).
        clearance: Smallest accepted signed distance (robot unit, >= 0).
    """

    checker: CollisionChecker
    clearance: float

    def distances(self, Q: np.ndarray) -> np.ndarray:
        """Smallest signed distance of each row of ``Q`` (``(n,)``; ``inf``: no pair)."""
        return self.checker.min_distance_batch(np.atleast_2d(np.asarray(Q, dtype=float)))

    def below(self, Q: np.ndarray) -> np.ndarray:
        """The clearance test of each row of ``Q`` (``(n,)``): its smallest signed distance
        when below the clearance, else a number at least the clearance (only the pairs that
        come close are measured, :func:`~moik.collision.kernels.distance_below`)."""
        Q2 = self.checker.robot.kernel_batch(np.atleast_2d(np.asarray(Q, dtype=float)))
        out = np.empty(Q2.shape[0])
        collision_kernels.distances_below(self.checker.compiled, Q2, self.clearance, out)
        return out

    def keeps(self, distances):
        """Whether signed distances keep the clearance
        (:func:`~moik.collision.model.keeps_clearance`)."""
        return collision_models.keeps_clearance(distances, self.clearance)

    def free(self, Q: np.ndarray) -> np.ndarray:
        """Whether each row of ``Q`` keeps the clearance (``(n,)`` bool)."""
        return self.keeps(self.distances(Q))

    def target_bound(self, q: np.ndarray, pose: bool
                     ) -> tuple[float, tuple[str, str] | None, float]:
        """The smallest distance at ``q`` over the pairs the target alone places, that pair,
        and the smallest distance of ``q`` over every pair (:meth:`distances`).

        Obstacles (body -1) and the base (body 0) never move; for a pose target
        (``pose``) neither does the last body at an exact answer (it moves with the end
        effector). A pair of two such bodies has the same distance at every exact answer
        (up to the pose tolerance), so no exact answer is farther from contact than this
        bound: when it is below the clearance, none is collision-free. ``(inf, None, ...)``
        when no checked pair is placed by the target alone.
        """
        least = float(self.distances(q)[0])
        fixed = self._target_pairs(pose)
        if fixed is None:
            return np.inf, None, least
        Q = self.checker.robot.kernel_batch(np.atleast_2d(np.asarray(q, dtype=float)))
        d, which = np.empty(1), np.empty(1, dtype=np.int64)
        collision_kernels.min_distances(fixed[0], Q, d, which)
        return float(d[0]), (fixed[1][which[0]] if which[0] >= 0 else None), least

    def _target_pairs(self, pose: bool) -> tuple[Any, tuple[tuple[str, str], ...]] | None:
        """The compiled pairs placed by the target alone (see :meth:`target_bound`) and their
        names, made once per guard; ``None`` when there is none."""
        cache = self.__dict__.setdefault("_target_sets", {})
        if pose not in cache:
            checker = self.checker
            fixed = {-1, 0, checker.robot.dof} if pose else {-1, 0}
            idx = [k for k, (a, b) in enumerate(checker.pair_bodies)
                   if a in fixed and b in fixed]
            arrays = checker.compiled_arrays
            arrays["pairs"], arrays["refine"] = arrays["pairs"][idx], arrays["refine"][idx]
            cache[pose] = None if not idx else (
                collision_compiled.collision_set(chain=checker.robot.chain_model, **arrays),
                tuple(checker.pair_names[k] for k in idx))
        return cache[pose]


def same_arm(a: Robot, b: Robot) -> bool:
    """Whether two robots have the same joints (chain, joint types, base)."""
    if a is b:
        return True
    ca, cb = a.kinematic_chain, b.kinematic_chain
    return (a.dof == b.dof and ca.origins.shape == cb.origins.shape
            and bool(np.allclose(ca.origins, cb.origins, atol=1e-12))
            and bool(np.array_equal(ca.joint_types, cb.joint_types))
            and bool(np.allclose(a.base, b.base, atol=1e-12)))


def default_model(robot: Robot) -> CollisionModel:
    """The geometry a solve checks when ``collision=`` is not given: a URDF arm's own
    collision geometry (its meshes as compounds, :func:`moik.collision.urdf.robot_model`;
    built once per robot), the catalog arms of
    :data:`~moik.collision.catalog.MESH_ARMS` included; else the shipped capsule model of
    a catalog arm (parsed once per name; another arm of that name is refused by
    :func:`~moik.collision.collision_model`)."""
    if robot.description is not None and (
            robot.name not in collision_catalog.shipped_models()
            or robot.name in collision_catalog.MESH_ARMS):
        model = _URDF_MODELS.get(robot)
        if model is None:
            model = collision_urdf.robot_model(robot)
            _URDF_MODELS[robot] = model
        return model
    model = _MODELS.get(robot.name)
    if model is None or not same_arm(model.robot, robot):
        model = collision_catalog.collision_model(robot)
        _MODELS[robot.name] = model
    return model


def _checker(model: CollisionModel, scene: Scene | None, self_collision: bool
             ) -> CollisionChecker:
    """A :class:`CollisionChecker`, reused for the same model and scene objects."""
    key = (id(model), id(scene), self_collision)
    hit = _CHECKERS.get(key)
    if hit is not None and hit[0] is model and hit[1] is scene:
        return hit[2]
    checker = collision_models.CollisionChecker(model=model, scene=scene,
                                                self_collision=self_collision)
    if len(_CHECKERS) >= _CACHE_SIZE:
        _CHECKERS.pop(next(iter(_CHECKERS)))
    _CHECKERS[key] = (model, scene, checker)  # the objects kept alive: their ids stay theirs
    return checker


def collision_guard(robot: Robot, *, scene=None, self_collision=False, clearance=0.0,
                    collision=None) -> CollisionGuard | None:
    """The :class:`CollisionGuard` of a solve, or ``None`` when it checks nothing.

    Args:
        robot: The arm solved for.
        scene: ``None``, a :class:`~moik.collision.Scene`, or a path to a scene JSON
            file (:func:`~moik.collision.load_scene`).
        self_collision: Check the model's self pairs too.
        clearance: Smallest accepted distance (robot unit; finite, >= 0).
        collision: ``None`` (the catalog's shipped model of ``robot``), a
            :class:`~moik.collision.CollisionModel` of ``robot``, or a
            :class:`~moik.collision.CollisionChecker` of ``robot`` used as it is (then
            ``scene`` and ``self_collision`` must be left at their defaults).

    Raises:
        ParameterError: NaN, infinite or negative ``clearance``; a non-bool
            ``self_collision``; ``scene``/``self_collision`` given beside a checker.
        GeometryError: A scene or geometry of the wrong type, or for another robot.
        UnknownNameError: No model shipped for the robot and it was not loaded from a URDF
            (pass ``collision=``).
        GeometryError: Nothing to check (no pair); a URDF mesh that cannot be used.
    """
    clearance = number("clearance", clearance, minimum=0.0)
    self_collision = flag("self_collision", self_collision)
    if isinstance(scene, str | Path):
        scene = collision_io.load_scene(scene)
    if scene is not None and not isinstance(scene, collision_models.Scene):
        raise GeometryError(f"scene must be a moik.collision.Scene or a path to a scene JSON "
                            f"file, got {type(scene).__name__}")
    if isinstance(collision, collision_models.CollisionChecker):
        if scene is not None or self_collision:
            raise ParameterError("collision= is a CollisionChecker, which has its own scene and "
                                 "self pairs: leave scene= and self_collision= unset, or pass "
                                 "a CollisionModel instead")
        _check_robot(collision.robot, robot)
        if collision.n_pairs == 0:
            raise GeometryError("nothing to check: the CollisionChecker given has no pair to "
                                "evaluate; a collision-free answer would mean nothing")
        return CollisionGuard(collision, clearance)
    if collision is not None and not isinstance(collision, collision_models.CollisionModel):
        raise GeometryError(f"collision must be a CollisionModel or a CollisionChecker, got "
                            f"{type(collision).__name__}")
    if scene is None and not self_collision:
        if collision is not None or clearance > 0.0:
            raise ParameterError(f"{'collision=' if collision is not None else 'clearance='} "
                                 "was given but nothing is checked: pass scene= and/or "
                                 "self_collision=True")
        return None
    if collision is not None:
        _check_robot(collision.robot, robot)
    model = default_model(robot) if collision is None else collision
    checker = _checker(model, scene, self_collision)
    if checker.n_pairs == 0:
        raise GeometryError(f"nothing to check: the collision geometry of {robot.name!r} "
                            f"({model.source or 'no source'}) gives no pair to evaluate "
                            f"({'no robot shape' if not model.items else 'every pair allowed'}"
                            f"{', no obstacle' if scene is None or not scene.obstacles else ''})"
                            "; a collision-free answer would mean nothing")
    return CollisionGuard(checker, clearance)


def _check_robot(model_robot: Robot, robot: Robot) -> None:
    if not same_arm(model_robot, robot):
        raise GeometryError(f"the collision geometry is for robot {model_robot.name!r} "
                            f"({model_robot.dof} joints), not for the robot solved for, "
                            f"{robot.name!r} ({robot.dof} joints)")


def clearance_criterion(checker: CollisionChecker) -> Criterion:
    """The criterion ``clearance`` of :func:`~moik.solver.solve_ik_pareto` (maximised):
    the smallest signed distance of each joint vector over the checker's pairs."""
    return Criterion("clearance", checker.min_distance_batch, MAXIMIZE)


def with_clearance(objectives: Any, guard: CollisionGuard | None) -> Any:
    """``objectives`` with the name ``"clearance"`` replaced by :func:`clearance_criterion`.

    Raises:
        ParameterError: ``"clearance"`` named without a collision check.
    """
    items = (objectives,) if isinstance(objectives, str) else objectives
    if not isinstance(items, list | tuple) or not any(
            isinstance(o, str) and o.lower() == "clearance" for o in items):
        return objectives
    if guard is None:
        raise ParameterError("criterion 'clearance' needs geometry to measure: pass scene= "
                             "and/or self_collision=True (or collision=a CollisionChecker)")
    return tuple(clearance_criterion(guard.checker)
                 if isinstance(o, str) and o.lower() == "clearance" else o for o in items)
