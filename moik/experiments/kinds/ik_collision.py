"""The collision keys of an IK experiment's ``problem`` (a scene beside the arm).

- ``scene``: the obstacles, as :func:`moik.collision.io.load_scene` reads them
  (``{"obstacles": [...]}``);
- ``clearance``: required distance (robot unit, default 0);
- ``self_collision``: check the arm against itself (default false, as in ``solve_ik``);
- ``collision_groups``: ``"min"`` (one aggregate constraint) or ``"links"`` (one per body);
- ``missing_geometry``: ``"error"`` (default: a link of a URDF arm without ``<collision>``
  geometry is refused, as in ``solve_ik``) or ``"ignore"`` (such links are left unchecked;
  each trial records them as ``unchecked_links``).

With a ``scene`` (or ``self_collision`` true and no scene) the problem is wrapped in
:class:`~moik.problems.collision_ik.CollisionIK` with the geometry ``solve_ik`` checks by
default (:func:`moik.solver.collision.default_model`: the ``<collision>`` geometry of the
URDF the arm was loaded from, its meshes as compounds, for a URDF robot of the config
and the catalog's panda, ur5 and iiwa14; the shipped capsule model of another catalog
arm), so an experiment's "collision-free" means what a solve's does. A check with no
pair to evaluate is refused, as the solver refuses it. A multi-objective trial then
records ``n_feasible`` (returned members whose recomputed minimum distance is >= the
clearance) and ``min_distance`` (the smallest over the returned members), and its HV
counts the feasible members only.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from moik._validate import choice
from moik.collision.io import load_scene
from moik.collision.model import CollisionChecker
from moik.collision.urdf import MISSING, robot_model
from moik.exceptions import GeometryError
from moik.problems.collision_ik import CollisionIK
from moik.robots import Robot
from moik.solver.collision import default_model

COLLISION_KEYS = ("scene", "clearance", "self_collision", "collision_groups", "missing_geometry")
_MISSING_HINT = ("pass missing='ignore' to leave them unchecked",
                 'set missing_geometry = "ignore" in the problem to leave them unchecked')


def is_checked(problem: Mapping) -> bool:
    """Whether ``problem`` (the config dict) asks for a collision check."""
    return "scene" in problem or bool(problem.get("self_collision", False))


def checker_of(robot: Robot, problem: Mapping) -> CollisionChecker:
    """The checker of ``problem``'s collision keys on ``robot``, with the geometry a solve
    checks by default (:func:`~moik.solver.collision.default_model`).

    Raises:
        GeometryError: Nothing to check (no robot shape, or every pair allowed).
    """
    scene = load_scene(problem["scene"]) if "scene" in problem else None
    missing = choice("missing_geometry", problem.get("missing_geometry", "error"), MISSING)
    try:
        if missing == "ignore" and robot.description is not None:
            model = robot_model(robot, missing="ignore")
        else:
            model = default_model(robot)
    except GeometryError as exc:
        raise GeometryError(str(exc).replace(*_MISSING_HINT)) from None
    checker = CollisionChecker(model=model, scene=scene,
                               self_collision=problem.get("self_collision", False))
    if checker.n_pairs == 0:
        raise GeometryError(f"nothing to check: the collision geometry of {robot.name!r} "
                            f"({model.source or 'no source'}) gives no pair to evaluate with "
                            "this scene and self_collision; a collision-free answer would "
                            "mean nothing")
    return checker


def with_collision(ik, problem: Mapping):
    """``ik`` wrapped with the collision constraints of ``problem``, or ``ik`` itself."""
    if not is_checked(problem):
        return ik
    return CollisionIK(ik, checker=checker_of(ik.robot, problem),
                       clearance=problem.get("clearance", 0.0),
                       groups=problem.get("collision_groups", "min"))


def feasibility(problem, X: np.ndarray, record: dict) -> np.ndarray:
    """Which rows of ``X`` are collision-free (all, without constraints); fills ``record``."""
    if not isinstance(problem, CollisionIK):
        return np.ones(len(X), dtype=bool)
    d = problem.min_distance(X)
    ok = problem.keeps(d)
    record.update(n_feasible=int(ok.sum()), min_distance=float(d.min()))
    unchecked = problem.checker.model.unchecked_links
    if unchecked:
        record["unchecked_links"] = list(unchecked)
    return ok
