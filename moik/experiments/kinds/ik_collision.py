"""The collision keys of an IK experiment's ``problem`` (a scene beside the arm).

- ``scene``: the obstacles, as :func:`moik.collision.io.load_scene` reads them
  (``{"obstacles": [...]}``);
- ``clearance``: required distance (robot unit, default 0);
- ``self_collision``: check the arm against itself (default false, as in ``solve_ik``);
- ``collision_groups``: ``"min"`` (one aggregate constraint) or ``"links"`` (one per body).

With a ``scene`` (or ``self_collision`` true and no scene) the problem is wrapped in
:class:`~moik.problems.collision_ik.CollisionIK` with the arm's shipped capsule model; a
multi-objective trial then records ``n_feasible`` (returned members whose recomputed
minimum distance is >= the clearance) and ``min_distance`` (the smallest over the
returned members), and its HV counts the feasible members only.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from moik.collision.catalog import collision_model
from moik.collision.io import load_scene
from moik.collision.model import CollisionChecker
from moik.problems.collision_ik import CollisionIK

COLLISION_KEYS = ("scene", "clearance", "self_collision", "collision_groups")


def with_collision(ik, problem: Mapping):
    """``ik`` wrapped with the collision constraints of ``problem``, or ``ik`` itself."""
    if "scene" not in problem and not problem.get("self_collision", False):
        return ik
    scene = load_scene(problem["scene"]) if "scene" in problem else None
    checker = CollisionChecker(model=collision_model(ik.robot), scene=scene,
                               self_collision=problem.get("self_collision", False))
    return CollisionIK(ik, checker=checker, clearance=problem.get("clearance", 0.0),
                       groups=problem.get("collision_groups", "min"))


def feasibility(problem, X: np.ndarray, record: dict) -> np.ndarray:
    """Which rows of ``X`` are collision-free (all, without constraints); fills ``record``."""
    if not isinstance(problem, CollisionIK):
        return np.ones(len(X), dtype=bool)
    d = problem.min_distance(X)
    ok = problem.keeps(d)
    record.update(n_feasible=int(ok.sum()), min_distance=float(d.min()))
    return ok
