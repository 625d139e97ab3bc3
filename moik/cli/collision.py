"""``moik solve ... --scene FILE | --self-collision [--clearance D]``: the answers' distances.

(The options are declared in :mod:`moik.cli.parser`, which imports nothing heavy.)

The scene is a JSON file (:func:`moik.collision.io.load_scene`); the arm's geometry is
its shipped capsule model (:mod:`moik.collision.catalog`) for a catalog arm, else the
``<collision>`` geometry of its URDF file (meshes found through ``--package-dir`` and
``ROS_PACKAGE_PATH``; :func:`moik.collision.urdf.robot_model`). The
checker (self pairs and the scene; the self pairs alone with ``--self-collision`` and
no scene) and ``--clearance`` go to the solver
(``solve_ik(..., collision=checker, clearance=D)``), which returns only collision-free
solutions, or the status ``collides`` (exit status 1) when every exact one collides;
with ``--pareto`` to ``solve_ik_pareto`` (members keep the clearance; the criterion
``clearance`` maximises the smallest distance).
Each printed solution gets its smallest distance and the pair that attains it (marked
in collision when closer than ``--clearance``, default 0); ``--json`` adds
``min_distance``, ``closest_pair`` and ``collides`` per solution, and ``min_distance``
of ``q`` at the top level.
"""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from moik._validate import number
from moik.cli.parser import given, library_default
from moik.collision.catalog import collision_model, shipped_models
from moik.collision.io import load_scene
from moik.collision.model import CollisionChecker
from moik.collision.urdf import robot_model
from moik.exceptions import GeometryError, ParameterError
from moik.robots import Robot


def checker(args: argparse.Namespace, robot: Robot) -> tuple[CollisionChecker, float] | None:
    """The checker and clearance of ``--scene`` / ``--self-collision``, or None without
    either (built before solving).

    Raises:
        ParameterError: ``--clearance`` given with neither (nothing would be checked).
    """
    scene = getattr(args, "scene", None)
    clearance = given(args, "clearance").get("clearance")
    if scene is None and not getattr(args, "self_collision", False):
        if clearance is not None:
            raise ParameterError("--clearance needs geometry to keep clear of: give --scene "
                                 "FILE and/or --self-collision")
        return None
    clearance = library_default("clearance") if clearance is None else clearance
    if robot.name in shipped_models():
        model = collision_model(robot)
    else:
        try:
            model = robot_model(robot)
        except GeometryError as exc:  # the library's keywords, in the command's words
            raise GeometryError(str(exc).replace("pass package_dirs=[a folder holding",
                                                 "give --package-dir [a folder holding").replace(
                "pass missing='ignore' to leave them unchecked",
                "use the library's missing='ignore' to leave them unchecked")) from None
    check = CollisionChecker(model=model, scene=None if scene is None else load_scene(scene))
    if check.n_pairs == 0:
        raise GeometryError(f"nothing to check: {model.source} gives no pair to evaluate")
    return check, number("--clearance", clearance, minimum=0.0)


def solver_options(check: tuple[CollisionChecker, float] | None) -> dict[str, Any]:
    """The keywords of ``solve_ik`` for ``--scene`` / ``--clearance`` (none without)."""
    return {} if check is None else {"collision": check[0], "clearance": check[1]}


def distances(check: tuple[CollisionChecker, float], Q: np.ndarray) -> list[dict[str, Any]]:
    """Per row of ``Q``: its smallest distance, the pair, and whether it collides."""
    ch, clearance = check
    out = []
    for q in np.atleast_2d(Q):
        d, pair = ch.closest_pair(q)
        out.append({"min_distance": d, "closest_pair": list(pair) if pair else None,
                    "collides": bool(d < clearance)})
    return out


def print_distances(rows: list[dict[str, Any]], unit: str, label: str = "solution",
                    start: int = 1) -> None:
    """One line per solution, in the order the solutions were printed (numbered from
    ``start``, as their table numbers them)."""
    for k, row in enumerate(rows, start=start):
        pair = " - ".join(row["closest_pair"]) if row["closest_pair"] else "no pair"
        verdict = "IN COLLISION" if row["collides"] else "collision-free"
        print(f"{label} {k}: {verdict}, smallest distance {row['min_distance']:.4f} {unit} "
              f"({pair})")
