"""Batch IK on every core: solutions/s of ``solve_ik_batch`` for 1, 2, 4, ... workers.

Targets: the FK poses of random configurations of panda (seeded); with the scene, of random
configurations free of collision (self pairs, and the table + shelf + side wall scene of
``benchmarks/collision_ik.py``), solved with ``scene=..., self_collision=True``. Rows:
``workers`` = 1, 2, 4, ... up to the CPUs this process may use (and that number itself),
and ``machine``: the machine's own ceiling, a compiled loop with no moik in it (the same
work split over that many threads, ``nogil``), timed interleaved with the others; its
speed-up is what the cores give to code that shares nothing (a host that places two
virtual CPUs on one physical core gives less than their number). Then, in a phase of its
own (a live cluster's processes take CPU time from the rows above), a Dask
``LocalCluster`` of that many single-threaded worker processes (``client=``) beside
workers=1 again. Each row's time is the median of ``--repeats`` calls, the rows of one
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
from concurrent.futures import ThreadPoolExecutor

import numba
import numpy as np
from _output import OUT_HELP, table_output

from moik.collision import Box, CollisionChecker, HalfSpace, Scene
from moik.collision.catalog import collision_model
from moik.collision.io import rpy_pose
from moik.robots import get_robot
from moik.solver import solve_ik_batch
from moik.solver.parallel import available_cores

CEILING_PER_CPU = 2_500_000  # iterations of the machine-ceiling loop per call and CPU (about
# 0.05 s on one core): each of 16 threads still runs for about 0.05 s, long enough that thread
# start-up and wake-up latencies do not set the row (5M iterations in all gave a 16-CPU host
# 0.01 s per thread, and a ceiling of 7-9x from those latencies, not from its cores)


@numba.njit(nogil=True, cache=False)
def _loop(n: int) -> float:
    s = 0.0
    for i in range(n):
        s += np.sin(i * 1e-3) * np.cos(i * 2e-3)
    return s


def ceiling(workers: int, cpus: int) -> None:
    """The machine row: ``CEILING_PER_CPU x cpus`` iterations of a compiled loop, split over
    ``workers`` threads (the same work for every row, nothing shared)."""
    parts = [CEILING_PER_CPU * cpus // workers] * workers
    if workers == 1:
        _loop(parts[0])
        return
    with ThreadPoolExecutor(workers) as pool:
        list(pool.map(_loop, parts))

FIELDS = ("q", "status", "position_error", "orientation_error", "n_eval", "min_distance")


def shelf_scene(model) -> Scene:
    """The table, shelf and side wall of ``benchmarks/collision_ik.py``."""
    base = [("table", model.links[0]), ("table", model.links[1])]
    return Scene({"table": HalfSpace.plane([0, 0, 1], 0.0),
                  "shelf": Box(size=(0.3, 0.7, 0.02), pose=rpy_pose([0.55, 0, 0.35])),
                  "side-wall": Box(size=(0.3, 0.02, 0.7), pose=rpy_pose([0.55, 0.36, 0.35]))},
                 allowed=frozenset(base))


def batch_targets(n: int, n_scene: int) -> tuple:
    """``(panda, the shelf scene, n random reachable poses, n_scene collision-free ones)``,
    seeded (module doc)."""
    robot = get_robot("panda")
    model = collision_model("panda")
    scene = shelf_scene(model)
    checker = CollisionChecker(model=model, scene=scene, self_collision=True)
    rng = np.random.default_rng(0)
    poses = robot.fk(robot.random_q(n, rng=rng))
    Q = robot.random_q(20 * n_scene, rng=rng)
    return robot, scene, poses, robot.fk(Q[checker.min_distance(Q) >= 0.0][:n_scene])


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


def table(title: str, robot, poses, kw: dict, rows: list, repeats: int,
          machine: int = 0) -> list[str]:
    """One block: solutions/s per row (``rows``: (label, extra keywords)); with ``machine``,
    the ceiling row on that many threads, timed interleaved with them."""
    solve = {label: (lambda extra=extra: solve_ik_batch(robot, poses, seed=0, **kw, **extra))
             for label, extra in rows}
    if machine:
        solve[f"machine {machine}"] = lambda: ceiling(machine, machine)
        solve["machine 1"] = lambda: ceiling(1, machine)
    first = {label: fn() for label, fn in solve.items()}  # untimed
    times: dict[str, list[float]] = {label: [] for label in solve}
    cpu: dict[str, list[float]] = {label: [] for label in solve}
    results = {}
    for _ in range(repeats):
        for label, fn in solve.items():
            c0, t0 = time.process_time(), time.perf_counter()
            results[label] = fn()
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
    if machine:
        t1, tw = np.median(times["machine 1"]), np.median(times[f"machine {machine}"])
        label = f"machine {machine}"
        busy = np.sum(cpu[label]) / np.sum(times[label])
        lines.append(f"{'machine':>14s} {tw:9.3f} {'':>15s} {'':>12s} {t1 / tw:8.2f}x "
                     f"{np.median(cpu[label]):7.3f} {busy:9.2f}   (a compiled loop on "
                     f"{machine} threads against 1: the cores' ceiling)")
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=4000, help="targets without the scene")
    ap.add_argument("--n-scene", type=int, default=1000, help="targets with the scene")
    ap.add_argument("--repeats", type=int, default=5, help="timed calls per row")
    ap.add_argument("--no-dask", action="store_true", help="no Dask LocalCluster row")
    ap.add_argument("--out", help=OUT_HELP)
    args = ap.parse_args()
    robot, scene, poses, scene_poses = batch_targets(args.n, args.n_scene)
    cores = available_cores()
    rows: list = [(f"workers={w}", {"workers": w}) for w in worker_counts(cores)]
    blocks = [(f"\nplain: {len(poses)} random reachable poses", poses, {}),
              (f"\nwith a scene (table, shelf, side wall) and self pairs: {len(scene_poses)} "
               f"collision-free reachable poses", scene_poses,
               {"scene": scene, "self_collision": True})]
    with table_output(args.out):
        print(f"solve_ik_batch on panda, tol 1e-9, {cores} CPUs; medians of {args.repeats} "
              "interleaved calls; speed-up: workers=1's time over the row's; cpu s: "
              "median CPU seconds of this process per call (the work, whatever the "
              "cores; forked tail processes not counted); cpu/wall: "
              "this process's CPU seconds over wall seconds (the cores the row got: a "
              "busy machine gives fewer than the workers); same: answers equal to "
              "workers=1's bit for bit; machine: the cores' own ceiling (module doc)")
        for title, targets, kw in blocks:
            print("\n".join(table(title, robot, targets, kw, rows, args.repeats,
                                   machine=cores)))
        if args.no_dask:
            return
        import distributed

        cluster = distributed.LocalCluster(n_workers=cores, threads_per_worker=1,
                                           processes=True, dashboard_address=None)
        client = distributed.Client(cluster)
        try:
            print(f"\nDask: a LocalCluster of {cores} single-threaded worker processes, beside "
                  "workers=1 with the cluster up")
            for title, targets, kw in blocks:
                print("\n".join(table(title, robot, targets, kw,
                                       [rows[0], (f"dask {cores}x1", {"client": client})],
                                       args.repeats)))
        finally:
            client.close()
            cluster.close()


if __name__ == "__main__":
    main()
