"""Running a batch on every core, or on a Dask cluster: the machinery, without the IK.

Three ways to spread independent work, each used by
:func:`~moik.solver.batch.solve_ik_batch` and each leaving every answer as the serial
run gives it (an answer depends on its target and its own seed only):

- :func:`map_chunks`: threads over contiguous (guided) chunks of a batch, for a stage
  whose chunk is a few compiled calls that release the GIL (numba ``nogil``): the
  Python glue is per chunk, never per item, and nothing is shared between chunks but
  read-only arrays, so there is no lock to wait on; the calling thread, idle otherwise,
  may work on each chunk's result as it ends (``then``).
- :func:`map_processes`: a process pool for per-item Python work (the hard tail: the
  whole of ``solve_ik``, search and polish, which holds the GIL). ``fork`` where the
  platform has it, so the children inherit this process's compiled kernels instead of
  loading (or compiling) them; the first items run in this process, and a pool starts
  only for what is left after :data:`POOL_AFTER_S` seconds (a cheap tail never pays
  for one), never inside a daemonic process (a pool's own worker cannot have children).
- :func:`map_client`: chunks as tasks of a ``dask.distributed`` client, gathered in
  order; a task whose worker is lost is run again by the scheduler (its result is the
  same: it depends only on its chunk), and a task that raises is retried.
"""

from __future__ import annotations

import math
import multiprocessing
import signal
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import ThreadPoolExecutor, as_completed
from typing import Any

from moik._machine import available_cores
from moik._validate import integer
from moik.exceptions import ParameterError
from moik.solver.task_pool import TaskPool, can_fork, process_count

__all__ = ["TaskPool", "can_fork", "check_client", "chunk_bounds", "client_workers",
           "map_chunks", "map_client", "map_processes", "process_count", "worker_count"]

MIN_CHUNK = 128  # items per chunk at least: its Python glue (measured 0.2 ms, under the GIL)
# stays about 4 % of the smallest chunk of easy targets (~0.04 ms each) and 1 % of the average
# guided chunk (48,000 targets on 16 workers: 109 chunks, 26 ms of glue in 1.7 s of kernels)
GUIDE = 2  # a chunk takes 1 / (GUIDE x workers) of the rows left (guided chunks, below)
POOL_MIN_TASKS = 2  # fewer per-item tasks run in this process (a pool costs a fork each)
POOL_AFTER_S = 0.25  # per-item tasks run here first; a pool takes the rest after this long
# (starting one costs ~0.05-0.1 s: a cheap tail, e.g. targets proven out of reach, ends first)
POOL_START_S = 0.1  # or sooner: once the items left, at the pace so far, would take longer
# here than this (the cost of a pool's start) times workers / (workers - 1), the idle cores'
# share: a tail of slow items goes to the pool after its first item
SPAWN_MIN_TASKS = 8  # where processes are spawned (each imports moik and loads its kernels)
TASK_RETRIES = 2  # a Dask task that raised is run again this often


def worker_count(workers: Any) -> int:
    """``workers`` validated (an integer >= 1); ``None``: :func:`available_cores`."""
    if workers is None:
        return available_cores()
    return integer("workers", workers, minimum=1)


def chunk_bounds(n: int, workers: int, *, min_chunk: int = MIN_CHUNK,
                 guide: int = GUIDE) -> list[tuple[int, int]]:
    """Contiguous ``(lo, hi)`` chunks of ``range(n)``: one for one worker, else guided
    chunks (OpenMP's ``schedule(guided)``): each takes ``1 / (guide x workers)`` of the
    rows left, at least ``min_chunk`` (a remainder smaller than that joins the last). The
    first chunks are large (little glue per row) and the last small, so a thread that
    ends early finds small chunks left: the threads end close together."""
    if workers <= 1 or n <= min_chunk:
        return [(0, n)]
    bounds, lo = [], 0
    while lo < n:
        hi = lo + max(min_chunk, math.ceil((n - lo) / (guide * workers)))
        if n - hi < min_chunk:
            hi = n
        bounds.append((lo, hi))
        lo = hi
    return bounds


def map_chunks(fn: Callable[[int, int], None], n: int, workers: int,
               then: Callable[[int, int, Callable[[], bool]], None] | None = None) -> None:
    """``fn(lo, hi)`` for the chunks of ``range(n)`` (:func:`chunk_bounds`) on ``workers``
    threads (in this thread when there is one chunk). ``fn`` writes its chunk's rows of
    arrays the caller owns; it should spend its time in compiled code that releases the
    GIL. The first exception of a chunk is raised once all chunks have ended.

    ``then(lo, hi, busy)``, if given, runs in this thread as each chunk ends (in the order
    they end, while the others go on; after ``fn`` for one chunk), ``busy()`` telling
    whether chunks are still running: per-row work that needs the chunk's result (and the
    GIL) overlaps the chunks left instead of following them all. Not called once a chunk
    has raised.
    """
    bounds = chunk_bounds(n, workers)
    if len(bounds) == 1:
        fn(0, n)
        if then is not None:
            then(0, n, lambda: False)
        return
    with ThreadPoolExecutor(max_workers=min(workers, len(bounds)),
                            thread_name_prefix="moik-batch") as pool:
        futures = {pool.submit(fn, lo, hi): (lo, hi) for lo, hi in bounds}
        if then is not None:
            def busy() -> bool:
                return not all(future.done() for future in futures)

            for future in as_completed(futures):
                if future.exception() is not None:
                    break
                then(*futures[future], busy)
    for future in futures:
        future.result()


_TASK: dict[str, Any] = {}  # a pool worker's function and its common argument


def _init_pool_worker(fn: Callable, common: Any) -> None:
    """A pool worker: Ctrl-C reaches only the parent (which ends the pool), and SIGTERM
    (the pool's end) ends it at once: a handler inherited from the parent (``moik``'s
    command raises on SIGTERM) would raise inside the pool's queue locks instead, print
    a traceback and could leave the parent waiting for a worker that never exits."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    _TASK["fn"], _TASK["common"] = fn, common


def _run_task(item: Any) -> tuple[Any, Any]:
    return item, _TASK["fn"](_TASK["common"], item)


def map_processes(fn: Callable[[Any, Any], Any], shared: Any, items: Iterable,
                  workers: int) -> list:
    """``[fn(shared, item) for item in items]``, in up to ``workers`` processes (at most
    one per CPU and per item: :func:`process_count`).

    ``fn`` must be a module-level function; ``shared`` is handed to each worker once
    (inherited with ``fork``, pickled otherwise), each item is sent to whichever worker is
    free. The items run in this process for the first :data:`POOL_AFTER_S` seconds, or
    until the pace so far says the rest would outlast a pool's start
    (:data:`POOL_START_S`); a pool takes the rest only if at least :data:`POOL_MIN_TASKS`
    remain then
    (:data:`SPAWN_MIN_TASKS` where processes cannot be forked: a spawned one imports moik
    and loads its kernels first). All in this process for one worker or inside a
    daemonic process.
    """
    items = list(items)
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    least = POOL_MIN_TASKS if method == "fork" else SPAWN_MIN_TASKS
    serial = workers <= 1 or multiprocessing.current_process().daemon
    out: list = []
    t0 = time.perf_counter()
    for item in items:  # here first: a tail that ends within POOL_AFTER_S needs no pool
        left = len(items) - len(out)
        if not serial and left >= least:
            spent = time.perf_counter() - t0
            if spent > POOL_AFTER_S or (out and spent / len(out) * left
                                        > POOL_START_S * workers / (workers - 1)):
                break
        out.append(fn(shared, item))
    rest = items[len(out):]
    if not rest:
        return out
    ctx = multiprocessing.get_context(method)
    with ctx.Pool(process_count(workers, len(rest)), initializer=_init_pool_worker,
                  initargs=(fn, shared)) as pool:
        done = dict(pool.imap_unordered(_run_task, rest))
    return out + [done[item] for item in rest]


def check_client(client: Any) -> Any:
    """``client`` if it looks like a ``dask.distributed.Client`` (``map``, ``gather``)."""
    if not (callable(getattr(client, "map", None)) and callable(getattr(client, "gather", None))
            and callable(getattr(client, "submit", None))):
        raise ParameterError(f"client must be a dask.distributed.Client, got "
                             f"{type(client).__name__}")
    return client


def client_workers(client: Any) -> int:
    """The number of worker threads of a Dask ``client``'s cluster (at least 1)."""
    try:
        return max(1, sum(client.nthreads().values()))
    except Exception:  # a client that cannot tell: one chunk per task still works
        return 1


def map_client(client: Any, fn: Callable[[Any], Any], jobs: Sequence,
               progress: Callable[[Any], None] | None = None) -> list:
    """``[fn(job) for job in jobs]`` as tasks of the Dask ``client``, in order.

    Each job is pickled into its own task (no scattered data: a lost worker takes
    nothing with it that its task cannot rebuild); the scheduler runs a task again on
    another worker when its worker is lost, and a task that raised is retried
    :data:`TASK_RETRIES` times before its error is raised here. ``progress(result)`` is
    called as each task finishes (in completion order).
    """
    from distributed import as_completed  # the optional extra moik[dask], present with a client

    futures = client.map(fn, list(jobs), pure=False, retries=TASK_RETRIES)
    try:
        index = {future.key: k for k, future in enumerate(futures)}
        results: list = [None] * len(futures)
        for future in as_completed(futures):
            results[index[future.key]] = future.result()
            if progress is not None:
                progress(results[index[future.key]])
        return results
    finally:
        client.cancel(futures)
