"""``moik compile``: compile every family of moik's kernels once, in parallel processes.

numba compiles a kernel at its first call and stores it in its on-disk cache
(:mod:`moik._jit`); a compilation holds the interpreter, so one process compiles one
kernel at a time. This command runs one small workload per kernel family
(:mod:`moik.warmup.families`), each in its own process (as many at once as there are
cores), so that the first real solve, Pareto solve or experiment only loads kernels. It
prints each family as it finishes.
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import time
from concurrent.futures import ProcessPoolExecutor, as_completed

from moik._validate import integer
from moik.warmup.background import ENV_SWITCH
from moik.warmup.families import FAMILIES, compile_family


def worker_setup() -> None:
    """In each worker: no background compile of its own (:mod:`moik.warmup.background`):
    the pool already runs the families side by side."""
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
            kernels = "1 kernel" if count == 1 else f"{count} kernels"
            print(f"  [{k}/{len(FAMILIES)}] {name}: {seconds:.1f} s ({kernels} compiled)",
                  flush=True)
    print(f"done in {time.perf_counter() - t0:.1f} s" + (f"; {failed} failed" if failed else ""))
    return 1 if failed else 0
