"""Soundness and tightness of the collision models against coal on the URDFs' own meshes.

For each arm (the shipped panda, also with its fingers open, ur5, iiwa14 URDFs with the
collision meshes moik ships in ``moik/robots/data/packages``; UR10 and KUKA KR16-2,
which moik does not ship, from ``tests/data/urdf``), ``N`` random configurations within
the limits (seed 1: not the samples the allowed-collision matrix was drawn from) are
checked for self-collision:

* moik: the model's smallest signed distance over its checked pairs, free when >= 0: the
  mesh-true model :func:`moik.collision.urdf.model_from_urdf` (each link's meshes a
  compound: a fitted capsule holding the hulls of pieces of its triangles, measured on the
  hulls where the capsules come close, compiled GJK; with its sampled allowed-collision
  matrix), the same model with its capsules alone (the bounds, no hulls), and for the
  catalog arms the shipped capsule model, ``moik/collision/data``;
* coal: ``coal.collide`` of the collision geometry (meshes and primitives) of every pair
  of links on bodies that are not chain neighbours, *whether or not the allowed-collision
  matrix checks the pair* (a pair it never checks must never touch), touching when any
  pair collides. The links are placed by :mod:`studies.urdf_oracle`, not by moik: its
  own URDF forward kinematics, the links behind off-chain joints (panda's fingers)
  included at the same joint values as the model (their zero clipped into their limits,
  or the values given: the "fingers open" row passes ``panda_finger_joint1 = 0.04`` to
  both). It also counts configurations where such a link touches the neighbouring body.

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
from moik.collision.model import CollisionModel
from moik.collision.shapes import Compound
from moik.collision.urdf import robot_model
from studies.urdf_oracle import URDFOracle

ROOT = Path(__file__).resolve().parents[1]
CHECK_SEED = 1  # not moik.collision.acm.ACM_SEED (0): the matrix is checked on other samples
SOLVE_SEED = 2
PACKAGES = [ROOT / "moik" / "robots" / "data" / "packages", ROOT / "tests" / "data" / "urdf"
            / "packages"]
PANDA = ROOT / "moik/robots/data/panda.urdf"
ARMS = {  # name: (URDF, tip link, catalog name or None, off-chain joint values or None)
    "panda": (PANDA, "panda_hand_tcp", "panda", None),
    "panda, fingers open": (PANDA, "panda_hand_tcp", None, {"panda_finger_joint1": 0.04}),
    "ur5": (ROOT / "moik/robots/data/ur5_robot.urdf", "tool0", "ur5", None),
    "iiwa14": (ROOT / "moik/robots/data/lbr_iiwa_14_r820.urdf", "tool0", "iiwa14", None),
    "ur10": (ROOT / "tests/data/urdf/ur10_robot.urdf", "tool0", None, None),
    "kr16": (ROOT / "tests/data/urdf/kr16_2.urdf", "tool0", None, None),
}


def oracle(name: str, robot) -> URDFOracle:
    """coal on the arm's own collision geometry (meshes and primitives, the links behind
    off-chain joints included), placed by :mod:`studies.urdf_oracle`, not by moik."""
    urdf, _, _, values = ARMS[name]
    return URDFOracle(urdf, robot.joint_names, PACKAGES, joint_values=values)


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
    for name, (urdf, tip, catalog, values) in ARMS.items():
        robot = load_urdf(urdf, tip_link=tip, package_dirs=PACKAGES)
        t0 = time.perf_counter()
        model = robot_model(robot, joint_values=values)
        built = time.perf_counter() - t0
        Q = robot.random_q(n, rng=np.random.default_rng(CHECK_SEED))
        truth = oracle(name, robot)
        touch = truth.touching(Q)
        beside = (f"; links behind off-chain joints ({', '.join(truth.values)}) touch the "
                  f"neighbouring body in {int(truth.offchain_touch_neighbour(Q).sum())} "
                  "(a pair no body-level model checks)" if truth.values else "")
        print(row(f"{name}: fitted capsules alone", bounds_only(model), Q, touch))
        print(row(f"{name}: capsules, then the hulls where they come close", model, Q, touch))
        if catalog is not None:
            shipped = collision_model(get_robot(catalog))
            print(row(f"{name}: shipped capsule model", shipped, Q, touch))
        print(f"| {name}: meshes touch in {100 * touch.mean():.1f} % of the configurations; "
              f"model built in {built:.1f} s{beside} | | | | | | |")


def solves(n: int) -> None:
    """``solve_ik(robot, T, self_collision=True)`` on ``n`` targets per arm, each the FK of
    a configuration whose meshes are free (seed :data:`SOLVE_SEED`): how many are solved,
    and how many answers coal finds touching."""
    print(f"\nsolve_ik(robot, T, self_collision=True), {n} targets per arm from mesh-free "
          f"configurations (seed {SOLVE_SEED}); the URDF model\n")
    print("| arm | solved | collides | other | answers whose meshes touch (coal) |")
    print("|---|---|---|---|---|")
    for name, (urdf, tip, _, values) in ARMS.items():
        robot = load_urdf(urdf, tip_link=tip, package_dirs=PACKAGES)
        truth = oracle(name, robot)
        model = robot_model(robot, joint_values=values)
        Q = robot.random_q(4 * n, rng=np.random.default_rng(SOLVE_SEED))
        Q = Q[~truth.touching(Q)][:n]
        status: dict[str, int] = {}
        answers = []
        for q in Q:
            res = solve_ik(robot, robot.fk(q), self_collision=True, collision=model, seed=0)
            status[res.status] = status.get(res.status, 0) + 1
            answers += list(res.solutions)
        touching = int(truth.touching(np.array(answers)).sum()) if answers else 0
        other = len(Q) - status.get("solved", 0) - status.get("collides", 0)
        print(f"| {name} | {status.get('solved', 0)} of {len(Q)} | {status.get('collides', 0)} "
              f"| {other} | {touching} of {len(answers)} |")


if __name__ == "__main__":
    main()
