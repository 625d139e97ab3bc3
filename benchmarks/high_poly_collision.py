"""Collision-aware IK on an arm whose collision meshes are high-poly: exact hulls beside
the enclosing polytopes that replace them (moik.collision.outer_hull).

The panda's own URDF package, copied to a temporary folder with every collision mesh
Loop-subdivided ``--levels`` times (trimesh; 300 faces become 19,200 at 3 levels:
smooth, so nearly every vertex of a piece is on its hull, as in a visual mesh shipped as
the collision one). Two models of it, each built with empty fit and allowed-collision
caches (build time printed): the hulls of the pieces exact (``max_exact`` unbounded), and
as moik builds them (a piece's hull over 128 vertices replaced by an enclosing polytope).
Targets: the FK poses of ``--targets`` random configurations (seed 3) free for both
models, self-collision only; ``solve_ik_batch(..., self_collision=True, collision=model,
workers=1)``, median of 3 interleaved calls. The last columns: the largest vertex count
of a piece's hull in the model; of 2,000 random configurations (seed 4), those free on the
exact hulls that the model calls colliding, and, where both call them free, how far its
smallest distance falls below the exact hulls' (never above: the polytopes hold the
hulls; where bodies overlap the kernels report their overlap along the line of centres,
a bound of the depth, so those are not compared).

Run: python benchmarks/high_poly_collision.py [--levels 3] [--targets 300] [--out FILE]
"""

from __future__ import annotations

import argparse
import os
import shutil
import tempfile
import time
from pathlib import Path

import numpy as np
import trimesh
from _output import OUT_HELP, table_output

import moik
from moik import load_urdf, solve_ik_batch
from moik.collision import CollisionChecker, mesh_pieces, outer_hull, urdf

DATA = Path(moik.__file__).parent / "robots" / "data"
MESHES = Path("example-robot-data") / "robots" / "panda_description" / "meshes" / "collision"


def high_poly_panda(folder: Path, levels: int) -> Path:
    """The panda URDF beside a copy of its package, collision meshes subdivided."""
    shutil.copytree(DATA / "packages" / MESHES, folder / "packages" / MESHES)
    for path in sorted((folder / "packages" / MESHES).glob("*.stl")):
        mesh = trimesh.load(path, force="mesh")
        v, f = mesh.vertices, mesh.faces
        for _ in range(levels):
            v, f = trimesh.remesh.subdivide_loop(v, f)
        trimesh.Trimesh(v, f).export(path)
    shutil.copy(DATA / "panda.urdf", folder / "panda.urdf")
    return folder / "panda.urdf"


def build(path: Path, robot, packages: Path, exact: bool, cache: Path):
    """The URDF model with empty caches (under ``cache``), and its build time."""
    os.environ["XDG_CACHE_HOME"] = str(cache)
    keep = mesh_pieces.enclosing_polytope
    if exact:
        mesh_pieces.enclosing_polytope = (
            lambda P: outer_hull.enclosing_polytope(P, max_exact=10**9))
    try:
        t0 = time.perf_counter()
        model = urdf.model_from_urdf(path, robot, package_dirs=[packages])
        return model, time.perf_counter() - t0
    finally:
        mesh_pieces.enclosing_polytope = keep


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--levels", type=int, default=3, help="Loop subdivisions of each mesh")
    ap.add_argument("--targets", type=int, default=300, help="IK targets")
    ap.add_argument("--out", help=OUT_HELP)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp, table_output(args.out):
        folder = Path(tmp)
        path = high_poly_panda(folder, args.levels)
        robot = load_urdf(path, package_dirs=[folder / "packages"], tip_link="panda_hand_tcp")
        faces = len(trimesh.load(next((folder / "packages" / MESHES).glob("link4.stl")),
                                 force="mesh").faces)
        print(f"panda, collision meshes Loop-subdivided {args.levels} times (link4: {faces:,} "
              "faces), self-collision only, one worker\n")
        models, build_s = {}, {}
        for label, exact in (("exact piece hulls", True), ("enclosing polytopes", False)):
            models[label], build_s[label] = build(path, robot, folder / "packages", exact,
                                                  folder / f"cache-{exact}")
        checkers = {k: CollisionChecker(model=m, self_collision=True) for k, m in models.items()}
        Q = robot.random_q(20 * args.targets, rng=np.random.default_rng(3))
        free = np.all([c.min_distance(Q) >= 0.0 for c in checkers.values()], axis=0)
        T = robot.fk(Q[free][:args.targets])
        R = robot.random_q(2000, rng=np.random.default_rng(4))
        exact_d = checkers["exact piece hulls"].min_distance(R)
        times: dict[str, list[float]] = {k: [] for k in models}
        solved: dict[str, int] = {}
        for m in models.values():  # compiled before the clock starts
            solve_ik_batch(robot, T[:2], self_collision=True, collision=m, workers=1)
        for _ in range(3):
            for k, m in models.items():
                t0 = time.perf_counter()
                res = solve_ik_batch(robot, T, self_collision=True, collision=m, workers=1)
                times[k].append(time.perf_counter() - t0)
                solved[k] = int(np.sum(res.success))
        print("| model | build s (empty caches) | solved | solutions/s | speed vs exact | "
              "largest piece hull (vertices) | free on the exact hulls, called colliding | "
              "distance below exact where both free: largest, median (mm) |")
        print("|---|---|---|---|---|---|---|---|")
        base = None
        for k, m in models.items():
            rate = solved[k] / float(np.median(times[k]))
            base = rate if base is None else base
            largest = max(len(p.points) for s in m.shapes.values() for c in s
                          for p in getattr(c, "parts", ()))
            d = checkers[k].min_distance(R)
            lost = int(np.sum((exact_d >= 0.0) & (d < 0.0)))
            both = (exact_d >= 0.0) & (d >= 0.0)  # a negative value bounds a depth
            below = (exact_d - d)[both] * 1e3
            print(f"| {k} | {build_s[k]:.1f} | {solved[k]} of {len(T)} | {rate:,.0f} | "
                  f"{rate / base:.2f}x | {largest} | {lost} of {int(np.sum(exact_d >= 0))} | "
                  f"{below.max():.3f}, {float(np.median(below)):.3f} |")


if __name__ == "__main__":
    main()
