"""``moik solve ... --scene FILE [--clearance D]``: the answers' distances to a scene.

(The options are declared in :mod:`moik.cli.parser`, which imports nothing heavy.)

The scene is a JSON file (:func:`moik.collision.io.load_scene`); the arm's geometry is
its shipped capsule model (:mod:`moik.collision.catalog`; catalog arms only). Each
printed solution gets its smallest distance (self pairs and the scene) and the pair
that attains it; a solution closer than ``--clearance`` (default 0) is marked in
collision, and ``--json`` adds ``min_distance``, ``closest_pair`` and ``collides`` per
solution. The solver itself does not avoid the scene yet: ``--scene`` checks its answers.
"""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from moik._validate import number
from moik.collision.catalog import collision_model
from moik.collision.io import load_scene
from moik.collision.model import CollisionChecker
from moik.robots import Robot


def checker(args: argparse.Namespace, robot: Robot) -> tuple[CollisionChecker, float] | None:
    """The checker and clearance of ``--scene``, or None without it (built before solving)."""
    if getattr(args, "scene", None) is None:
        return None
    return (CollisionChecker(model=collision_model(robot), scene=load_scene(args.scene)),
            number("--clearance", args.clearance))


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
