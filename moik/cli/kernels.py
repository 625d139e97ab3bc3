"""``moik compile``: compile every family of moik's kernels once, in parallel processes.

numba compiles a kernel at its first call and stores it in its on-disk cache
(:mod:`moik._jit`); a compilation holds the interpreter, so one process compiles one
kernel at a time. This command runs one small workload per kernel family, each in its
own process (as many at once as there are cores), so that the first real solve, Pareto
solve or experiment only loads kernels. It prints each family as it finishes.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import multiprocessing
import os
import time
from concurrent.futures import ProcessPoolExecutor, as_completed

import numpy as np
from pymoo.optimize import minimize

from moik import _jit
from moik._background import ENV_SWITCH
from moik._validate import integer
from moik.algorithms import available, get_algorithm
from moik.algorithms.registry import is_multi_objective
from moik.problems import BiObjectiveIK, PoseIK, random_reachable_targets
from moik.robots import get_robot
from moik.solver import solve_ik
from moik.solver.batch import solve_ik_batch
from moik.solver.pareto import solve_ik_pareto
from moik.solver.path import solve_path

FAMILIES = ("solve", "solve-position", "unreachable", "pareto", "batch-path", "collision",
            "algorithms-single", "algorithms-multi")
"""The workloads, one process each (see :func:`compile_family`)."""


def _solve_families(name: str) -> None:
    for arm in (get_robot("eosma7"), get_robot("ur5")):  # a DH arm and a URDF chain
        target = random_reachable_targets(arm, 3, seed=1)
        if name == "solve":
            solve_ik(arm, target[0].pose, n_solutions=2)
            arm.fk(target[0].q_source)
        elif name == "solve-position":
            solve_ik(arm, target[0].position)
        elif name == "unreachable":
            far = target[0].position * (3.0 * arm.reach / np.linalg.norm(target[0].position))
            pose = target[0].pose.copy()
            pose[:3, 3] = far
            solve_ik(arm, far, max_evals=2000)
            solve_ik(arm, pose, max_evals=2000)
        elif name == "pareto":
            solve_ik_pareto(arm, target[0].pose, objectives=("joint_motion", "manipulability"),
                            q_current=target[1].q_source, n_solutions=5)
            solve_ik_pareto(arm, target[0].position, objectives=("limit_margin", "orientation"),
                            rotation=target[1].rotation, n_solutions=5)
        elif name == "collision":  # the start loop with a distance test (self pairs)
            solve_ik(arm, target[0].pose, self_collision=True)
            solve_ik_batch(arm, np.array([t.pose for t in target]), self_collision=True)
        else:
            solve_ik_batch(arm, np.array([t.pose for t in target]))
            solve_path(arm, [t.pose for t in target])


def _algorithm_families(multi: bool) -> None:
    arm = get_robot("eosma7-m")
    target = random_reachable_targets(arm, 1, seed=1)[0]
    problem = BiObjectiveIK(arm, target) if multi else PoseIK(arm, target)
    for name in available():
        if is_multi_objective(name) == multi:
            minimize(problem, get_algorithm(name, pop_size=10), ("n_gen", 3), seed=1)


def compile_family(name: str) -> tuple[str, float, int]:
    """Run the workload of family ``name``; ``(name, seconds, kernels compiled)``."""
    t0 = time.perf_counter()
    with contextlib.redirect_stderr(io.StringIO()):  # the per-process notice: ours instead
        if name.startswith("algorithms"):
            _algorithm_families(name.endswith("multi"))
        else:
            _solve_families(name)
    return name, time.perf_counter() - t0, _jit.compile_count()


def worker_setup() -> None:
    """In each worker: no background compile of its own (a Pareto solve's child process,
    :mod:`moik.solver.memetic`): the pool already runs the families side by side."""
    os.environ[ENV_SWITCH] = "0"


def cmd_compile(args: argparse.Namespace) -> int:
    """Compile every family, in ``--processes`` processes (default: the cores)."""
    workers = integer("--processes", args.processes if args.processes is not None
                      else os.cpu_count() or 1, minimum=1)
    workers = min(workers, len(FAMILIES))
    print(f"compiling moik's kernels ({len(FAMILIES)} families, {workers} processes at once; "
          "first run only: later runs load them from numba's cache)", flush=True)
    t0 = time.perf_counter()
    ctx = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=workers, mp_context=ctx,
                             initializer=worker_setup) as pool:
        futures = [pool.submit(compile_family, name) for name in FAMILIES]
        failed = 0
        for k, future in enumerate(as_completed(futures), start=1):
            try:
                name, seconds, count = future.result()
            except Exception as exc:  # a family that fails must not hide the others
                failed += 1
                print(f"  [{k}/{len(FAMILIES)}] failed: {type(exc).__name__}: {exc}", flush=True)
                continue
            print(f"  [{k}/{len(FAMILIES)}] {name}: {seconds:.1f} s ({count} kernels compiled)",
                  flush=True)
    print(f"done in {time.perf_counter() - t0:.1f} s" + (f"; {failed} failed" if failed else ""))
    return 1 if failed else 0
