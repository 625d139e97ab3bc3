"""``moik solve ... --scene FILE | --self-collision [--clearance D]``: the answers' distances.

(The options are declared in :mod:`moik.cli.parser`, which imports nothing heavy.)

The scene is a JSON file (:func:`moik.collision.io.load_scene`); the arm's geometry is
its shipped model (:mod:`moik.collision.catalog`) for a catalog arm, else the
``<collision>`` geometry of its URDF file (meshes found through ``--package-dir`` and
``ROS_PACKAGE_PATH``; :func:`moik.collision.urdf.robot_model`), as the library picks it
(:func:`moik.solver.collision.collision_guard`). The checker (the scene's obstacles,
and the self pairs with ``--self-collision``: the library's default, off, as for
``solve_ik``) and ``--clearance`` go to the solver
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
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np

from moik.cli.parser import given, library_default
from moik.collision.io import load_scene
from moik.collision.urdf import robot_model
from moik.exceptions import MoikError, ParameterError
from moik.robots import Robot
from moik.solver.collision import CollisionGuard, collision_guard

# the library's keywords in its collision messages, as this command's options
_OPTION_NAMES = ((" (or collision=a CollisionChecker)", ""),
                 ("self_collision=True", "--self-collision"),
                 ("clearance=", "--clearance"), ("scene=", "--scene FILE"),
                 ("clearance must ", "--clearance must "),
                 ("pass package_dirs=[a folder holding", "give --package-dir [a folder holding"),
                 ("pass missing='ignore' to leave them unchecked",
                  "give --allow-missing-geometry to leave them unchecked"))


@contextmanager
def option_names() -> Iterator[None]:
    """Library errors about the collision check raised again naming this command's options
    (the rules stay the library's: :func:`moik.solver.collision.collision_guard`,
    :func:`moik.solver.collision.with_clearance`)."""
    try:
        yield
    except MoikError as exc:
        if exc.args and isinstance(exc.args[0], str):
            text = exc.args[0]
            for keyword, option in _OPTION_NAMES:
                text = text.replace(keyword, option)
            exc.args = (text, *exc.args[1:])
        raise


def checker(args: argparse.Namespace, robot: Robot) -> CollisionGuard | None:
    """The collision check of ``--scene`` / ``--self-collision`` / ``--clearance`` (built
    before solving, by the library's :func:`~moik.solver.collision.collision_guard`), or
    None without geometry.

    Raises:
        ParameterError: As ``collision_guard`` (e.g. ``--clearance`` with nothing to
            check), naming the options.
    """
    scene = getattr(args, "scene", None)
    clearance = given(args, "clearance").get("clearance", library_default("clearance"))
    self_collision = getattr(args, "self_collision", False)
    with option_names():
        model = None
        if getattr(args, "allow_missing_geometry", False):
            if scene is None and not self_collision:
                raise ParameterError("--allow-missing-geometry goes with --scene or "
                                     "--self-collision: without them nothing is checked")
            if robot.description is None:
                raise ParameterError("--allow-missing-geometry is for a URDF arm (a catalog "
                                     f"arm {robot.name!r} has its shipped collision model)")
            model = robot_model(robot, missing="ignore")
        return collision_guard(robot, scene=None if scene is None else load_scene(scene),
                               self_collision=self_collision, clearance=clearance,
                               collision=model)


def solver_options(check: CollisionGuard | None) -> dict[str, Any]:
    """The keywords of ``solve_ik`` for ``--scene`` / ``--clearance`` (none without)."""
    return {} if check is None else {"collision": check.checker, "clearance": check.clearance}


def distances(check: CollisionGuard, Q: np.ndarray) -> list[dict[str, Any]]:
    """Per row of ``Q``: its smallest distance, the pair, and whether it collides."""
    out = []
    for q in np.atleast_2d(Q):
        d, pair = check.checker.closest_pair(q)
        out.append({"min_distance": d, "closest_pair": list(pair) if pair else None,
                    "collides": not check.keeps(d)})
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
