"""Soundness and tightness of the collision models against coal on the URDFs' own meshes.

For each arm (the shipped panda, ur5, iiwa14 URDFs with the collision meshes moik ships
in ``moik/robots/data/packages``; UR10 and KUKA KR16-2, which moik does not ship, from
``tests/data/urdf``), ``N`` random configurations within the limits (seed 1: not the
samples the allowed-collision matrix was drawn from) are checked for self-collision:

* moik: the model's smallest signed distance over its checked pairs, free when >= 0: the
  mesh-true model :func:`moik.collision.urdf.model_from_urdf` (each link's meshes a
  compound: a fitted capsule holding the hulls of slabs of its triangles, measured on the
  hulls where the capsules come close, compiled GJK; with its sampled allowed-collision
  matrix), the same model with its capsules alone (the bounds, no hulls), and for the
  catalog arms the shipped capsule model, ``moik/collision/data``;
* coal: ``coal.collide`` of the meshes of every pair of bodies that are not chain
  neighbours, *whether or not the allowed-collision matrix checks the pair* (a pair it
  never checks must never touch), touching when any pair collides.

Printed per arm and model: configurations called free where the meshes touch (must be
0), and the percentage of mesh-free configurations the model rejects (its
conservativeness; the goal is <= 5 %). Needs coal (the ``test`` extra) and trimesh.

    python -m studies.mesh_collision_check [--n 10000] [--out docs/results/mesh-collision.md]
"""

from __future__ import annotations

import argparse
import contextlib
import io
import sys
import time
from pathlib import Path

import coal
import numpy as np

from moik import get_robot, load_urdf, solve_ik
from moik.collision import CollisionChecker, collision_model
from moik.collision.meshes import read_mesh, resolve_mesh
from moik.collision.model import CollisionModel
from moik.collision.shapes import Compound
from moik.collision.urdf import robot_model
from moik.robots.urdf_geometry import mesh_geometry

ROOT = Path(__file__).resolve().parents[1]
CHECK_SEED = 1  # not moik.collision.urdf.ACM_SEED (0): the matrix is checked on other samples
SOLVE_SEED = 2
PACKAGES = [ROOT / "moik" / "robots" / "data" / "packages", ROOT / "tests" / "data" / "urdf"
            / "packages"]
ARMS = {  # name: (URDF, tip link, catalog name or None)
    "panda": (ROOT / "moik/robots/data/panda.urdf", "panda_hand_tcp", "panda"),
    "ur5": (ROOT / "moik/robots/data/ur5_robot.urdf", "tool0", "ur5"),
    "iiwa14": (ROOT / "moik/robots/data/lbr_iiwa_14_r820.urdf", "tool0", "iiwa14"),
    "ur10": (ROOT / "tests/data/urdf/ur10_robot.urdf", "tool0", None),
    "kr16": (ROOT / "tests/data/urdf/kr16_2.urdf", "tool0", None),
}


def body_meshes(urdf: Path, robot) -> dict[int, list]:
    """coal BVH models of each body's collision meshes, in the body's frame."""
    _, items = mesh_geometry(urdf, robot, "collision")
    out: dict[int, list] = {}
    for item in items:
        path = resolve_mesh(item["filename"], link=item["link"], urdf_dir=urdf.parent,
                            package_dirs=PACKAGES)
        mesh = read_mesh(path, link=item["link"], scale=item["scale"])
        P = mesh.vertices @ item["pose"][:3, :3].T + item["pose"][:3, 3]
        bvh = coal.BVHModelOBBRSS()
        bvh.beginModel(len(mesh.faces), len(P))
        bvh.addVertices(np.ascontiguousarray(P))
        bvh.addTriangles(np.ascontiguousarray(mesh.faces, dtype=np.int64))
        bvh.endModel()
        out.setdefault(item["body"], []).append(bvh)
    return out


def meshes_touch(robot, meshes: dict[int, list], Q: np.ndarray) -> np.ndarray:
    """Per row of ``Q``: whether the meshes of two non-neighbouring bodies collide."""
    bodies = sorted(meshes)
    pairs = [(i, j) for i in bodies for j in bodies if j > i + 1]
    req, out = coal.CollisionRequest(), np.zeros(len(Q), dtype=bool)
    for k, q in enumerate(Q):
        F = robot.frames(q)
        tf = {b: coal.Transform3s(F[b][:3, :3], F[b][:3, 3]) for b in bodies}
        for i, j in pairs:
            if any(coal.collide(a, tf[i], b, tf[j], req, coal.CollisionResult())
                   for a in meshes[i] for b in meshes[j]):
                out[k] = True
                break
    return out


def bounds_only(model: CollisionModel) -> CollisionModel:
    """``model`` with each compound replaced by its bound (the capsules alone)."""
    shapes = {link: [s.bound if isinstance(s, Compound) else s for s in items]
              for link, items in model.shapes.items()}
    return CollisionModel(robot=model.robot, shapes=shapes, links=model.links,
                          allowed=model.allowed, source=model.source)


def row(name: str, model, Q: np.ndarray, touch: np.ndarray) -> str:
    checker = CollisionChecker(model=model, self_collision=True)
    measure = checker.min_distance
    measure(Q[:2])  # compiled before the clock starts
    t0 = time.perf_counter()
    d = measure(Q)
    per = (time.perf_counter() - t0) / len(Q) * 1e6
    free = d >= 0.0
    unsound = int(np.sum(free & touch))
    mesh_free = ~touch
    rejected = 100.0 * np.sum(~free & mesh_free) / max(1, int(mesh_free.sum()))
    shapes = sum(len(s) for s in model.shapes.values())
    return (f"| {name} | {shapes} | {len(model.checked_body_pairs())} | {len(model.allowed)} | "
            f"{unsound} of {len(Q)} | {rejected:.1f} % | {per:.1f} |")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10_000, help="random configurations per arm")
    parser.add_argument("--solves", type=int, default=50,
                        help="targets per arm for solve_ik (0: none)")
    parser.add_argument("--out", type=Path, help="also write the printed tables to this file")
    args = parser.parse_args(argv)
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        report(args.n)
        if args.solves:
            solves(args.solves)
    sys.stdout.write(text.getvalue())
    if args.out is not None:
        args.out.write_text("---\nhide: [toc]\n---\n\n"  # wide tables: no table of contents
                            "```\n$ python -m studies.mesh_collision_check"
                            f"{'' if args.n == 10_000 else f' --n {args.n}'}"
                            f"{'' if args.solves == 50 else f' --solves {args.solves}'}\n"
                            f"{text.getvalue()}```\n")


def report(n: int) -> None:
    """Print the table for ``n`` configurations per arm."""
    print(f"self-collision, {n} random configurations per arm (seed {CHECK_SEED}, not the "
          f"allowed-collision matrix's samples); coal "
          f"{coal.__version__} on the URDFs' collision meshes\n")
    print("| arm: model | shapes | checked body pairs | allowed pairs | called free where the "
          "meshes touch | mesh-free configurations rejected | us per configuration |")
    print("|---|---|---|---|---|---|---|")
    for name, (urdf, tip, catalog) in ARMS.items():
        robot = load_urdf(urdf, tip_link=tip, package_dirs=PACKAGES)
        t0 = time.perf_counter()
        model = robot_model(robot)
        built = time.perf_counter() - t0
        Q = robot.random_q(n, rng=np.random.default_rng(CHECK_SEED))
        touch = meshes_touch(robot, body_meshes(urdf, robot), Q)
        print(row(f"{name}: fitted capsules alone", bounds_only(model), Q, touch))
        print(row(f"{name}: capsules, then the hulls where they come close", model, Q, touch))
        if catalog is not None:
            shipped = collision_model(get_robot(catalog))
            print(row(f"{name}: shipped capsule model", shipped, Q, touch))
        print(f"| {name}: meshes touch in {100 * touch.mean():.1f} % of the configurations; "
              f"model built in {built:.1f} s | | | | | | |")


def solves(n: int) -> None:
    """``solve_ik(robot, T, self_collision=True)`` on ``n`` targets per arm, each the FK of
    a configuration whose meshes are free (seed :data:`SOLVE_SEED`): how many are solved,
    and how many answers coal finds touching."""
    print(f"\nsolve_ik(robot, T, self_collision=True), {n} targets per arm from mesh-free "
          f"configurations (seed {SOLVE_SEED}); the URDF model\n")
    print("| arm | solved | collides | other | answers whose meshes touch (coal) |")
    print("|---|---|---|---|---|")
    for name, (urdf, tip, _) in ARMS.items():
        robot = load_urdf(urdf, tip_link=tip, package_dirs=PACKAGES)
        meshes = body_meshes(urdf, robot)
        Q = robot.random_q(4 * n, rng=np.random.default_rng(SOLVE_SEED))
        Q = Q[~meshes_touch(robot, meshes, Q)][:n]
        status: dict[str, int] = {}
        answers = []
        for q in Q:
            res = solve_ik(robot, robot.fk(q), self_collision=True, seed=0)
            status[res.status] = status.get(res.status, 0) + 1
            answers += list(res.solutions)
        touching = int(meshes_touch(robot, meshes, np.array(answers)).sum()) if answers else 0
        other = len(Q) - status.get("solved", 0) - status.get("collides", 0)
        print(f"| {name} | {status.get('solved', 0)} of {len(Q)} | {status.get('collides', 0)} "
              f"| {other} | {touching} of {len(answers)} |")


if __name__ == "__main__":
    main()
