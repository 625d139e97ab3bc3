"""Running trials: serially, in a process pool, or on a Dask distributed cluster.

Every executor is an iterator over ``(record, arrays)`` pairs in completion
order; the runner stores each pair as soon as it arrives. Workers never touch
the results folder (remote Dask workers need no shared file system).

- ``serial``: in this process.
- ``pool``: ``multiprocessing.Pool(workers)`` with ``imap_unordered`` (chunks
  of one trial); workers ignore SIGINT, so Ctrl-C reaches only the parent, which
  terminates the pool: the trials in flight are lost, the stored ones are not.
  A worker whose parent is killed (even with SIGKILL) exits at once, quietly.

SIGTERM is handled as Ctrl-C (:func:`sigterm_as_interrupt`, used by the runner):
the message, the stored trials kept, the lock released, the session end recorded.
- ``dask``: ``distributed.Client(address)`` (connected before the results folder
  is made); ``client.map(warm_trial, specs)`` and ``distributed.as_completed``;
  on interrupt the futures are cancelled.
  Needs the optional extra ``dask`` and moik installed on the workers.

:class:`Progress` is a tqdm bar when tqdm is installed, else a plain line on
stderr at most every two seconds: trials done/total, failures, ETA.
"""

from __future__ import annotations

import contextlib
import ctypes
import dataclasses
import json
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Iterator, Sequence

from moik.exceptions import ParameterError
from moik.experiments.spec import TrialSpec
from moik.experiments.trials import run_trial

_WARMED: set[str] = set()  # this process's warmed-up (kind, algorithm, robot, problem)


def warm_trial(spec: TrialSpec) -> tuple[dict, dict]:
    """:func:`run_trial`, after an untimed warm-up the first time this process meets the
    trial's algorithm and problem: the same trial with one iteration (and no evaluation
    budget), so that the trial's ``time`` excludes the one-off load (or compilation) of
    the compiled kernels, which a worker process would otherwise charge to its first
    trial (for a quick trial, two orders of magnitude more than the trial itself)."""
    key = json.dumps([spec.kind, spec.algorithm, spec.robot, spec.problem], sort_keys=True,
                     default=str)
    if key not in _WARMED:
        _WARMED.add(key)
        problem = {k: v for k, v in spec.problem.items() if k != "evaluations"}
        run_trial(dataclasses.replace(spec, iterations=1, problem=problem, protocol=None,
                                      record_history=False))
    return run_trial(spec)


_PR_SET_PDEATHSIG = 1  # linux/prctl.h


def run_serial(specs: Sequence[TrialSpec]) -> Iterator[tuple[dict, dict]]:
    """Run the trials one after another in this process (each warmed up: :func:`warm_trial`)."""
    for spec in specs:
        yield warm_trial(spec)


class Terminated(KeyboardInterrupt):
    """SIGTERM arrived: handled as Ctrl-C (the stored trials are kept, the lock released)."""


def _raise_terminated(signum, frame) -> None:
    raise Terminated(f"signal {signum}")


@contextlib.contextmanager
def sigterm_as_interrupt() -> Iterator[None]:
    """While inside, SIGTERM raises :class:`Terminated` (a ``KeyboardInterrupt``), so a run
    ended by ``kill`` or a batch system stops as Ctrl-C does. Only in the main thread
    (where Python delivers signals); elsewhere a no-op."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    before = signal.signal(signal.SIGTERM, _raise_terminated)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, before)


def _parent_watch(parent: int) -> None:
    """Exit quietly (``os._exit``) once ``parent`` is gone (this process is re-parented)."""
    while os.getppid() == parent:
        time.sleep(0.25)
    os._exit(0)


def _init_worker(parent: int) -> None:
    """A pool worker: Ctrl-C reaches only the parent; SIGTERM ends the worker at once (the
    parent's handler is not inherited); the worker dies with its parent (Linux: the kernel's
    parent-death signal; elsewhere a thread that watches the parent id) instead of
    computing on and failing with ``BrokenPipeError`` when it sends its result."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    if os.getppid() != parent:  # the parent died before this worker got here
        os._exit(0)
    threading.Thread(target=_parent_watch, args=(parent,), daemon=True,
                     name="moik-parent-watch").start()


def run_pool(specs: Sequence[TrialSpec], workers: int) -> Iterator[tuple[dict, dict]]:
    """Run the trials in ``workers`` processes (``fork`` where available)."""
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else None
    ctx = multiprocessing.get_context(method)
    pool = ctx.Pool(processes=workers, initializer=_init_worker, initargs=(os.getpid(),))
    try:
        yield from pool.imap_unordered(warm_trial, specs, chunksize=1)
        pool.close()
    except BaseException:
        pool.terminate()
        raise
    finally:
        pool.join()


def connect_dask(address: str, *, timeout: float = 20.0):
    """A ``distributed.Client`` of the scheduler at ``address`` (connecting for ``timeout`` s).

    The runner connects before it creates the results folder, so an unreachable
    scheduler leaves nothing behind.

    Raises:
        ParameterError: If ``dask.distributed`` is not installed or the scheduler
            cannot be reached.
    """
    try:
        from distributed import Client
    except ImportError:
        raise ParameterError("--dask-scheduler needs dask.distributed: "
                             "pip install -e '.[dask]' in the moik repository") from None
    try:
        return Client(address, timeout=timeout)
    except (OSError, TimeoutError, ValueError) as exc:
        raise ParameterError(f"cannot connect to the Dask scheduler {address!r}: {exc}") from None


def run_on_client(specs: Sequence[TrialSpec], client) -> Iterator[tuple[dict, dict]]:
    """Run the trials on a connected Dask ``client`` (cancelled on interrupt, not closed)."""
    from distributed import as_completed

    futures = []
    try:
        futures = client.map(warm_trial, list(specs), pure=False)
        for future in as_completed(futures):
            yield future.result()
    finally:
        if futures:
            client.cancel(futures)


def run_dask(specs: Sequence[TrialSpec], address: str, *,
             timeout: float = 20.0) -> Iterator[tuple[dict, dict]]:
    """Run the trials on the Dask scheduler at ``address`` (see :func:`connect_dask`)."""
    client = connect_dask(address, timeout=timeout)
    try:
        yield from run_on_client(specs, client)
    finally:
        client.close()


def execute(specs: Sequence[TrialSpec], *, workers: int = 1, dask_scheduler: str | None = None,
            dask_client=None) -> Iterator[tuple[dict, dict]]:
    """Pick the executor: Dask if a client or an address is given, a pool if ``workers > 1``,
    else serial."""
    if dask_client is not None:
        return run_on_client(specs, dask_client)
    if dask_scheduler:
        return run_dask(specs, dask_scheduler)
    if workers > 1 and len(specs) > 1:
        return run_pool(specs, min(workers, len(specs)))
    return run_serial(specs)


class Progress:
    """Trials done/total, failures and ETA (tqdm if installed, else a plain stderr line).

    Args:
        total: Trials to run in this session.
        done: Trials already finished before (resume), shown in the description.
        label: Shown before the counts.
        enabled: False silences it.
    """

    def __init__(self, *, total: int, done: int = 0, label: str = "", enabled: bool = True):
        self.total, self.count, self.failures = total, 0, 0
        self.label = f"{label} (+{done} resumed)" if done else label
        self.enabled = enabled
        self._t0 = self._last = time.monotonic()
        self._bar = None
        if enabled:
            try:
                from tqdm import tqdm
            except ImportError:  # optional: a plain line per trial instead
                pass
            else:
                self._bar = tqdm(total=total, desc=self.label, unit="trial", file=sys.stderr)

    def update(self, ok: bool) -> None:
        """Count one finished trial (``ok`` False counts a failure)."""
        self.count += 1
        self.failures += not ok
        if not self.enabled:
            return
        if self._bar is not None:
            self._bar.set_postfix(failures=self.failures, refresh=False)
            self._bar.update(1)
            return
        now = time.monotonic()
        if now - self._last >= 2.0 or self.count == self.total:
            self._last = now
            print(self.line(now), file=sys.stderr, flush=True)

    def line(self, now: float | None = None) -> str:
        """The fallback progress line."""
        elapsed = (time.monotonic() if now is None else now) - self._t0
        rate = elapsed / self.count if self.count else 0.0
        eta = rate * (self.total - self.count)
        return (f"{self.label}: {self.count}/{self.total} trials, {self.failures} failed, "
                f"elapsed {elapsed:.0f} s, ETA {eta:.0f} s")

    def close(self) -> None:
        """Finish the bar."""
        if self._bar is not None:
            self._bar.close()
