"""What ``solve_ik_batch``'s design allows on W cores, measured on one: its critical path.

``batch_scaling.py`` measures speed-ups on the cores a machine has; a 2-CPU machine cannot
say whether the design would reach 12x on 16 cores. This script times each piece of a
``workers=W`` batch in this process, one after another, and schedules the pieces on W
ideal cores (each as fast as this one, nothing shared but what the design shares):

- each chunk (:func:`moik.solver.parallel.chunk_bounds`): its compiled calls that release
  the GIL (``run_batch``, the start streams, the clearance test), and the rest, its Python
  glue, which holds the GIL; W threads take the chunks in order, and one GIL serves every
  glue and the calling thread's work (the re-check of each ended chunk, ``settle``);
- the hard tail (targets left to the whole of ``solve_ik``), each target timed: with a
  collision check on more than :data:`~moik.solver.batch.TAIL_HERE_MAX_WORKERS` workers, W
  processes of a :class:`~moik.solver.task_pool.TaskPool` take each chunk's tail once its
  settle ends, and no sooner than the pool is up (its caller's cost and its readiness are
  measured here with W real processes); else, W processes after the chunks;
- what runs before and after (validation, the assembly of the answers).

The modelled time is where the last piece ends; ``serial s``, the instrumented call's own
time (its pieces one after another: about what ``workers=1`` takes, measured in the same
call, so that a busy host inflates both alike); the speed-up, the one over the other.
GIL load: the GIL's busy time over the modelled time (near 1, the GIL would cap the
threads). A host's own limits (two virtual CPUs on one core, memory bandwidth,
clock) are not modelled: ``batch_scaling.py``'s ``machine`` row measures those. Targets as
in ``batch_scaling.py``.

Run: python benchmarks/batch_critical_path.py [--n 12000] [--n-scene 3000]
[--workers 4 8 16 32] [--out FILE]
"""

from __future__ import annotations

import argparse
import heapq
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from _output import OUT_HELP, table_output
from batch_scaling import batch_targets

import moik.collision.kernels as collision_kernels
from moik.solver import batch, parallel, solve_ik_batch, start_streams, task_pool

NOGIL = [(batch, "run_batch"), (start_streams, "batch_streams"), (start_streams, "draw_starts"),
         (collision_kernels, "distances_below")]


class Record:
    """The pieces of one instrumented call (times in s)."""

    def __init__(self) -> None:
        self.kernel = 0.0  # compiled time of the chunk running now
        self.chunks: list[tuple[float, float, float]] = []  # (glue, kernels, settle)
        self.tail: dict[int, float] = {}  # target -> its solve_ik time
        self.tail_of_chunk: list[list[int]] = []  # the TaskPool's items, per chunk
        self.after: list[int] = []  # map_processes' items, after the chunks


REC = Record()


def _timed(fn: Callable) -> Callable:
    def run(*args: Any, **kw: Any) -> Any:
        t = time.perf_counter()
        try:
            return fn(*args, **kw)
        finally:
            REC.kernel += time.perf_counter() - t
    return run


def _map_chunks(fn, n, workers, then=None):
    """The chunks one after another, each timed: glue, kernels, settle."""
    for lo, hi in parallel.chunk_bounds(n, workers):
        REC.kernel = 0.0
        t = time.perf_counter()
        fn(lo, hi)
        t1, kernel = time.perf_counter(), REC.kernel
        REC.tail_of_chunk.append([])
        tail_before = sum(REC.tail.values())
        if then is not None:
            then(lo, hi, lambda: False)
        settle = time.perf_counter() - t1 - (sum(REC.tail.values()) - tail_before)
        REC.chunks.append((t1 - t - kernel, kernel, settle))


class _SerialPool:
    """TaskPool's interface, each item run here at once (its time recorded)."""

    def __init__(self, fn, shared, workers, items):
        self.fn, self.shared, self.out = fn, shared, {}

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def submit(self, items):
        for i in items:
            REC.tail_of_chunk[-1].append(int(i))
            self.out[int(i)] = self.fn(self.shared, int(i))

    def results(self):
        return self.out


def _map_processes(fn, shared, items, workers):
    REC.after = [int(i) for i in items]
    return [fn(shared, i) for i in REC.after]


def _tail_target(job, i):
    t = time.perf_counter()
    out = _TAIL(job, i)
    REC.tail[i] = time.perf_counter() - t
    return out


_TAIL = batch._tail_target


def instrument() -> None:
    for module, name in NOGIL:
        setattr(module, name, _timed(getattr(module, name)))
    parallel.map_chunks, parallel.TaskPool = _map_chunks, _SerialPool
    parallel.map_processes, parallel.can_fork = _map_processes, lambda: True
    batch._tail_target = _tail_target


def pool_costs(workers: int, repeats: int = 5) -> tuple[float, float]:
    """A TaskPool of ``workers`` real processes: the caller's time to start and end it, and
    the time from its start to its first result (s, medians)."""
    task_pool.available_cores = lambda: workers
    caller, ready = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        with task_pool.TaskPool(_identity, None, workers, workers) as pool:
            t1 = time.perf_counter()
            pool.submit([0])
            pool.results()
            t2 = time.perf_counter()
        caller.append(t1 - t0 + time.perf_counter() - t2)
        ready.append(t2 - t0)
        time.sleep(0.2)
    return float(np.median(caller)), float(np.median(ready))


def _identity(shared, item):
    return item


def schedule(rec: Record, workers: int, fixed: float, pool: tuple[float, float] | None
             ) -> tuple[float, float]:
    """The modelled end time and the GIL's busy time of ``rec`` on ``workers`` cores."""
    start = fixed / 2 + (pool[0] if pool else 0.0)  # validation, then the pool's start
    threads = [start] * workers
    gil = main = start
    ends = []
    for glue, kernel, _ in rec.chunks:  # in order, to the first free thread
        k = int(np.argmin(threads))
        begin = max(threads[k], gil)  # the glue waits for the GIL
        gil = begin + glue
        threads[k] = gil + kernel
        ends.append(threads[k])
    free_at: dict[int, float] = {}
    for c in np.argsort(ends, kind="stable"):  # settles in the order the chunks end
        main = max(main, ends[c], gil) + rec.chunks[c][2]
        gil = max(gil, main)
        free_at[int(c)] = main
    gil_busy = sum(g + s for g, _, s in rec.chunks)
    end = max(main, max(threads))
    items = sorted((max(free_at[c], start + (pool[1] if pool else 0.0)), i)
                   for c, its in enumerate(rec.tail_of_chunk) for i in its)
    procs = [0.0] * workers
    for at, i in items:
        k = int(np.argmin(procs))
        procs[k] = max(procs[k], at) + rec.tail[i]
    end = max(end, *procs)
    if rec.after:  # a pool after the chunks
        after = [end] * workers
        for i in rec.after:
            heapq.heappush(after, heapq.heappop(after) + rec.tail[i])
        end = max(after)
    return end + fixed / 2, gil_busy


def block(title: str, robot, targets, kw: dict, counts: list[int], repeats: int) -> list[str]:
    global REC
    solve_ik_batch(robot, targets[:300], seed=0, workers=1, **kw)  # compiled, warm
    serial = []
    for _ in range(repeats):
        t = time.perf_counter()
        solve_ik_batch(robot, targets, seed=0, workers=1, **kw)
        serial.append(time.perf_counter() - t)
    t1 = float(np.median(serial))
    lines = [title, f"workers=1 measured: {t1:.3f} s (median of {repeats})",
             f"{'workers':>8s} {'chunks':>7s} {'glue ms':>8s} {'settle ms':>10s} "
             f"{'tail':>5s} {'tail s':>7s} {'pool ms':>8s} {'fixed ms':>9s} {'model s':>8s} "
             f"{'serial s':>9s} {'speed-up':>9s} "
             f"{'GIL load':>9s}"]
    for w in counts:
        runs = []
        for _ in range(repeats):
            REC = Record()
            t = time.perf_counter()
            solve_ik_batch(robot, targets, seed=0, workers=w, **kw)
            total = time.perf_counter() - t
            pieces = sum(g + k + s for g, k, s in REC.chunks) + sum(REC.tail.values())
            runs.append((total, total - pieces, REC))
        total, fixed, rec = sorted(runs, key=lambda r: r[0])[len(runs) // 2]
        uses_pool = bool(kw) and w > batch.TAIL_HERE_MAX_WORKERS
        pool = pool_costs(w) if uses_pool else None
        end, gil = schedule(rec, w, max(fixed, 0.0), pool)
        lines.append(f"{w:8d} {len(rec.chunks):7d} {1e3 * sum(g for g, _, _ in rec.chunks):8.1f} "
                     f"{1e3 * sum(s for _, _, s in rec.chunks):10.1f} {len(rec.tail):5d} "
                     f"{sum(rec.tail.values()):7.3f} "
                     f"{'-' if pool is None else f'{1e3 * pool[0]:.1f}':>8s} "
                     f"{1e3 * max(fixed, 0.0):9.1f} {end:8.3f} "
                     f"{total:9.3f} {total / end:8.2f}x {gil / end:9.2f}")
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=12000, help="targets without the scene")
    ap.add_argument("--n-scene", type=int, default=3000, help="targets with the scene")
    ap.add_argument("--workers", type=int, nargs="+", default=[4, 8, 16, 32])
    ap.add_argument("--repeats", type=int, default=3, help="instrumented calls per row")
    ap.add_argument("--out", help=OUT_HELP)
    args = ap.parse_args()
    robot, scene, poses, scene_poses = batch_targets(args.n, args.n_scene)
    instrument()
    with table_output(args.out):
        print("solve_ik_batch on panda, tol 1e-9: each piece of a workers=W call timed on one "
              "core of this machine, scheduled on W ideal cores with one GIL (module doc); "
              "glue: the chunks' Python under the GIL; settle: the calling thread's re-check; "
              "tail: targets left to solve_ik and their time; pool: the caller's time to "
              "start and end the tail's processes; fixed: the call's own time before and "
              "after the chunks (validation, assembly); model s: where the last piece ends; "
              "serial s: the instrumented call's time (its pieces one after another); "
              "speed-up: serial s / model s")
        for title, targets, kw in (
                (f"\nplain: {len(poses)} random reachable poses", poses, {}),
                (f"\nwith a scene (table, shelf, side wall) and self pairs: {len(scene_poses)} "
                 "collision-free reachable poses", scene_poses,
                 {"scene": scene, "self_collision": True})):
            print("\n".join(block(title, robot, targets, kw, args.workers, args.repeats)))


if __name__ == "__main__":
    main()
