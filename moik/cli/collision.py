"""``moik solve ... --scene FILE [--clearance D]``: the answers' distances to a scene.

(The options are declared in :mod:`moik.cli.parser`, which imports nothing heavy.)

The scene is a JSON file (:func:`moik.collision.io.load_scene`); the arm's geometry is
its shipped capsule model (:mod:`moik.collision.catalog`; catalog arms only). The
checker (self pairs and the scene) and ``--clearance`` go to the solver
(``solve_ik(..., collision=checker, clearance=D)``), which returns only collision-free
solutions, or the status ``collides`` (exit status 1) when every exact one collides.
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
from moik.collision.catalog import collision_model
from moik.collision.io import load_scene
from moik.collision.model import CollisionChecker
from moik.robots import Robot


def checker(args: argparse.Namespace, robot: Robot) -> tuple[CollisionChecker, float] | None:
    """The checker and clearance of ``--scene``, or None without it (built before solving)."""
    if getattr(args, "scene", None) is None:
        return None
    clearance = given(args, "clearance").get("clearance", library_default("clearance"))
    return (CollisionChecker(model=collision_model(robot), scene=load_scene(args.scene)),
            number("--clearance", clearance, minimum=0.0))


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


def print_distances(rows: list[dict[str, Any]], unit: str) -> None:
    """One line per solution, in the order the solutions were printed."""
    for k, row in enumerate(rows, start=1):
        pair = " - ".join(row["closest_pair"]) if row["closest_pair"] else "no pair"
        verdict = "IN COLLISION" if row["collides"] else "collision-free"
        print(f"solution {k}: {verdict}, smallest distance {row['min_distance']:.4f} {unit} "
              f"({pair})")
