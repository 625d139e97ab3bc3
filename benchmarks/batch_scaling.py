"""Batch IK on every core: solutions/s of ``solve_ik_batch`` for 1, 2, 4, ... workers.

Targets: the FK poses of random configurations of panda (seeded); with the scene, of random
configurations free of collision (self pairs, and the table + shelf + side wall scene of
``benchmarks/collision_ik.py``), solved with ``scene=..., self_collision=True``. Rows:
``workers`` = 1, 2, 4, ... up to the CPUs this process may use (and that number itself),
then a Dask ``LocalCluster`` of that many single-threaded worker processes
(``client=``). Each row's time is the median of ``--repeats`` calls, the rows of one
repeat run one after another (interleaved: load on the machine hits every row alike);
the speed-up column is workers=1's median time over the row's, cpu/wall the CPU seconds
of this process over the wall seconds of its calls (how many cores the row really got;
the tail's forked processes and the Dask workers are not counted). Every row's answers are
compared with workers=1's, bit for bit (``same``). Start-up outside the timing: one
untimed call per row first (thread and process pools are made per call and are timed;
the Dask workers are started and warmed once).

Run: python benchmarks/batch_scaling.py [--n 4000] [--n-scene 1000] [--repeats 5]
[--no-dask] [--out FILE]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _output import OUT_HELP, table_output

from moik.collision import Box, CollisionChecker, HalfSpace, Scene
from moik.collision.catalog import collision_model
from moik.collision.io import rpy_pose
from moik.robots import get_robot
from moik.solver import solve_ik_batch
from moik.solver.parallel import available_cores

FIELDS = ("q", "status", "position_error", "orientation_error", "n_eval", "min_distance")


def shelf_scene(model) -> Scene:
    """The table, shelf and side wall of ``benchmarks/collision_ik.py``."""
    base = [("table", model.links[0]), ("table", model.links[1])]
    return Scene({"table": HalfSpace.plane([0, 0, 1], 0.0),
                  "shelf": Box(size=(0.3, 0.7, 0.02), pose=rpy_pose([0.55, 0, 0.35])),
                  "side-wall": Box(size=(0.3, 0.02, 0.7), pose=rpy_pose([0.55, 0.36, 0.35]))},
                 allowed=frozenset(base))


def worker_counts(cores: int) -> list[int]:
    """1, 2, 4, ... below ``cores``, and ``cores``."""
    counts, w = [], 1
    while w < cores:
        counts.append(w)
        w *= 2
    return [*counts, cores]


def same(a, b) -> bool:
    """Whether two batch results are equal bit for bit."""
    for field in FIELDS:
        x, y = getattr(a, field), getattr(b, field)
        if (x is None) != (y is None):
            return False
        if x is not None and not np.array_equal(x, y, equal_nan=field != "status"):
            return False
    return True


def table(title: str, robot, poses, kw: dict, rows: list, repeats: int) -> list[str]:
    """One block: solutions/s per row (``rows``: (label, extra keywords))."""
    first = {label: solve_ik_batch(robot, poses, seed=0, **kw, **extra)  # untimed
             for label, extra in rows}
    times: dict[str, list[float]] = {label: [] for label, _ in rows}
    cpu: dict[str, list[float]] = {label: [] for label, _ in rows}
    results = {}
    for _ in range(repeats):
        for label, extra in rows:
            c0, t0 = time.process_time(), time.perf_counter()
            results[label] = solve_ik_batch(robot, poses, seed=0, **kw, **extra)
            times[label].append(time.perf_counter() - t0)
            cpu[label].append(time.process_time() - c0)
    ref_label = rows[0][0]
    ref = results[ref_label]
    t_ref = float(np.median(times[ref_label]))
    lines = [title, f"{'row':>14s} {'median s':>9s} {'range s':>15s} {'solutions/s':>12s} "
                    f"{'speed-up':>9s} {'cpu s':>7s} {'cpu/wall':>9s} {'solved':>7s} "
                    f"{'same':>5s}"]
    for label, extra in rows:
        t = np.array(times[label])
        res = results[label]
        solved = int(res.success.sum())
        ok = same(ref, res) and same(ref, first[label])
        here = "client" not in extra  # a Dask row computes in the workers' processes
        busy = f"{np.sum(cpu[label]) / np.sum(times[label]):.2f}" if here else "-"
        cpu_s = f"{np.median(cpu[label]):.3f}" if here else "-"
        lines.append(f"{label:>14s} {np.median(t):9.3f} {t.min():7.3f}-{t.max():7.3f} "
                     f"{solved / np.median(t):12.0f} {t_ref / np.median(t):8.2f}x {cpu_s:>7s} "
                     f"{busy:>9s} {solved:7d} {'yes' if ok else 'NO':>5s}")
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=4000, help="targets without the scene")
    ap.add_argument("--n-scene", type=int, default=1000, help="targets with the scene")
    ap.add_argument("--repeats", type=int, default=5, help="timed calls per row")
    ap.add_argument("--no-dask", action="store_true", help="no Dask LocalCluster row")
    ap.add_argument("--out", help=OUT_HELP)
    args = ap.parse_args()
    robot = get_robot("panda")
    model = collision_model("panda")
    scene = shelf_scene(model)
    checker = CollisionChecker(model=model, scene=scene, self_collision=True)
    rng = np.random.default_rng(0)
    poses = robot.fk(robot.random_q(args.n, rng=rng))
    Q = robot.random_q(20 * args.n_scene, rng=rng)
    free = Q[checker.min_distance(Q) >= 0.0][:args.n_scene]
    scene_poses = robot.fk(free)
    cores = available_cores()
    rows: list = [(f"workers={w}", {"workers": w}) for w in worker_counts(cores)]
    client = cluster = None
    if not args.no_dask:
        import distributed

        cluster = distributed.LocalCluster(n_workers=cores, threads_per_worker=1,
                                           processes=True, dashboard_address=None)
        client = distributed.Client(cluster)
        rows.append((f"dask {cores}x1", {"client": client}))
    try:
        with table_output(args.out):
            print(f"solve_ik_batch on panda, tol 1e-9, {cores} CPUs; medians of {args.repeats} "
                  "interleaved calls; speed-up: workers=1's time over the row's; cpu s: "
                  "median CPU seconds of this process per call (the work, whatever the "
                  "cores; forked tail processes not counted); cpu/wall: "
                  "this process's CPU seconds over wall seconds (the cores the row got: a "
                  "busy machine gives fewer than the workers); same: answers equal to "
                  "workers=1's bit for bit")
            print("\n".join(table(f"\nplain: {len(poses)} random reachable poses", robot,
                                  poses, {}, rows, args.repeats)))
            print("\n".join(table(f"\nwith a scene (table, shelf, side wall) and self pairs: "
                                  f"{len(scene_poses)} collision-free reachable poses", robot,
                                  scene_poses, {"scene": scene, "self_collision": True}, rows,
                                  args.repeats)))
    finally:
        if client is not None:
            client.close()
            cluster.close()


if __name__ == "__main__":
    main()
