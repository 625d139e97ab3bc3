"""Collision-aware batch IK on the URDFs' own collision meshes beside the shipped capsules.

For panda, ur5 and iiwa14, two collision models side by side in one run: the shipped
capsule model of the catalog (``moik/collision/data``) and the model of the URDF's
collision meshes (``robot_model(get_robot(name))``: each link's meshes a compound, one
capsule fitted around them holding the convex hulls of pieces of them, measured on
the hulls where the capsules come close; the allowed-collision matrix judged on the
hulls). Targets: the FK poses of
``--targets`` random configurations (seed 3) free for both models in the table + 6 boxes
and spheres scene of ``benchmarks/collision_ik.py``; ``solve_ik_batch(..., scene=scene,
self_collision=True, collision=model)`` on all of them, median of 3 interleaved calls:
the share solved and collision-free solutions per second, and the ratio of the two
models' speeds.

Run: python benchmarks/urdf_collision.py [--targets 200] [--out FILE]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _output import OUT_HELP, table_output

from moik import get_robot, solve_ik_batch
from moik.collision import Box, CollisionChecker, HalfSpace, Scene, Sphere
from moik.collision.catalog import collision_model
from moik.collision.io import rpy_pose
from moik.collision.urdf import robot_model

ARMS = ("panda", "ur5", "iiwa14")


def clutter(model, *, rng: np.random.Generator) -> Scene:
    """benchmarks/collision_ik.py's table + 6 boxes and spheres, the table allowed
    against the two base bodies."""
    obstacles: dict = {"table": HalfSpace.plane([0, 0, 1], 0.0)}
    for k in range(6):
        c = rng.uniform([-0.8, -0.8, 0.05], [0.8, 0.8, 0.9])
        while np.linalg.norm(c[:2]) < 0.25:  # not through the base
            c = rng.uniform([-0.8, -0.8, 0.05], [0.8, 0.8, 0.9])
        if k % 2:
            obstacles[f"ball{k}"] = Sphere(radius=rng.uniform(0.04, 0.12), pose=rpy_pose(c))
        else:
            obstacles[f"box{k}"] = Box(size=rng.uniform(0.05, 0.25, 3),
                                       pose=rpy_pose(c, rng.uniform(-np.pi, np.pi, 3)))
    return Scene(obstacles, allowed=frozenset({("table", model.links[0]),
                                               ("table", model.links[1])}))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--targets", type=int, default=200, help="IK targets per arm")
    ap.add_argument("--out", help=OUT_HELP)
    args = ap.parse_args()
    with table_output(args.out):
        print("| arm | model | shapes | checked pairs | solved collision-free | "
              "collision-free solutions/s | speed vs shipped |")
        print("|---|---|---|---|---|---|---|")
        for name in ARMS:
            robot = get_robot(name)
            models = {"shipped capsules": collision_model(robot),
                      "URDF meshes (compounds)": robot_model(robot)}
            scenes = {k: clutter(m, rng=np.random.default_rng(5)) for k, m in models.items()}
            checkers = {k: CollisionChecker(model=m, scene=scenes[k], self_collision=True)
                        for k, m in models.items()}
            Q = robot.random_q(20 * args.targets, rng=np.random.default_rng(3))
            free = np.all([c.min_distance(Q) >= 0.0 for c in checkers.values()], axis=0)
            if not free.any():
                print(f"| {name} | both | | | none of {len(Q)} random configurations is free "
                      "for both models | | |")
                continue
            T = robot.fk(Q[free][:args.targets])
            times: dict[str, list[float]] = {k: [] for k in models}
            solved: dict[str, int] = {}
            for k, m in models.items():  # compiled before the clock starts
                solve_ik_batch(robot, T[:2], scene=scenes[k], self_collision=True, collision=m)
            for _ in range(3):
                for k, m in models.items():
                    t0 = time.perf_counter()
                    res = solve_ik_batch(robot, T, scene=scenes[k], self_collision=True,
                                         collision=m, seed=0)
                    times[k].append(time.perf_counter() - t0)
                    solved[k] = int(np.sum(res.success))
            base = None
            for k, m in models.items():
                rate = solved[k] / float(np.median(times[k]))
                base = rate if base is None else base
                shapes = sum(len(s) for s in m.shapes.values())
                print(f"| {name} | {k} | {shapes} | {checkers[k].n_pairs} | "
                      f"{solved[k]} of {len(T)} | {rate:,.0f} | {rate / base:.2f}x |")


if __name__ == "__main__":
    main()
