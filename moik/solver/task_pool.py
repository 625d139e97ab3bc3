"""Per-item work handed to forked processes while the caller's threads run: :class:`TaskPool`.

A collision-aware batch on many workers solves its hard tail (the whole of ``solve_ik``,
Python under the GIL) in processes beside its threaded chunks, as each chunk ends. The
processes must be forked before the chunks' threads start (a process forked while threads
run may inherit a lock one of them holds), and forking a pool of ``W`` processes costs the
caller ``W`` forks of a large process (measured, panda with a scene, 2-CPU host: a
16-process ``multiprocessing.Pool`` took 0.07-0.10 s to start and 0.04-0.06 s to end), time
in which no chunk runs: on 16 cores, a fifth of a 12,000-target scene batch's ideal time.

So the caller forks one process, the *lead* (one fork: about 5 ms), and goes on; the lead
starts the pool of ``W`` workers itself (forked from the lead, which has no thread then:
the same inherited state as forked from the caller) while the caller's chunks run, passes
on the items the caller sends it, streams the results back, and ends its pool after the
caller is done, without the caller waiting for it. Items and results travel through two
one-way pipes, each with one writer (the caller's thread that submits; the lead's result
thread), so no lock is shared between the processes.

A lead whose caller dies sees its pipe end (every other copy of the caller's end is
closed) and ends its pool; a caller whose lead dies gets a :class:`~moik.exceptions.MoikError`
instead of waiting for results that never come. Ctrl-C reaches the caller only (the lead
and its workers ignore SIGINT); the caller then ends the lead, and the lead its pool.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import signal
import sys
from collections.abc import Callable, Iterable
from typing import Any

from moik._machine import available_cores
from moik.exceptions import MoikError

POLL_S = 0.5  # how often a waiting caller checks that its lead is alive (s)
END_WAIT_S = 5.0  # how long an interrupted caller waits for its lead to end before killing it

_TASK: dict[str, Any] = {}  # a pool worker's function and its common argument


def init_pool_worker(fn: Callable, common: Any, *close: Any) -> None:
    """A pool worker: Ctrl-C reaches only the parent (which ends the pool), and SIGTERM
    (the pool's end) ends it at once: a handler inherited from the parent (``moik``'s
    command raises on SIGTERM) would raise inside the pool's queue locks instead, print
    a traceback and could leave the parent waiting for a worker that never exits.
    ``close``: inherited pipe ends this worker must not hold (see :class:`TaskPool`)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    for conn in close:
        conn.close()
    _TASK["fn"], _TASK["common"] = fn, common


def run_task(item: Any) -> tuple[Any, Any]:
    """``(item, fn(common, item))`` in a pool worker."""
    return item, _TASK["fn"](_TASK["common"], item)


def process_count(workers: int, items: int) -> int:
    """Processes for ``items`` per-item tasks asked to run on ``workers``: at most one per
    item and one per CPU this process may run on (:func:`available_cores`; more would only
    share the same cores, each costing a fork and its memory)."""
    return max(1, min(workers, items, available_cores()))


def can_fork() -> bool:
    """Whether :class:`TaskPool` can start here: ``fork`` exists and this process is not a
    pool's own (daemonic) worker."""
    return ("fork" in multiprocessing.get_all_start_methods()
            and not multiprocessing.current_process().daemon)


def _end_lead(signum: int, frame: Any) -> None:
    sys.exit(0)  # unwinds the lead's ``with Pool``, which ends its workers


def _lead(fn: Callable, shared: Any, processes: int, tasks: Any, results: Any,
          other_ends: tuple) -> None:
    """The lead process: a pool of ``processes`` workers fed from ``tasks`` (lists of items;
    ``None`` or the caller's end: stop), each result sent on ``results`` as
    ``(True, (item, value))`` or ``(False, exception)``."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _end_lead)
    for conn in other_ends:  # the caller's ends: a dead caller then reads as EOF here
        conn.close()

    def send(ok: bool, value: Any) -> None:  # in the pool's result thread, the pipe's writer
        try:
            results.send((ok, value))
        except Exception as error:  # pickling failed: nothing was written
            results.send((False, MoikError(f"a task's {'result' if ok else 'error'} "
                                           f"({type(value).__name__}) could not be sent "
                                           f"back: {error}")))

    def sent(value: Any) -> None:
        send(True, value)

    def failed(error: BaseException) -> None:
        send(False, error)

    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(processes, initializer=init_pool_worker,
                  initargs=(fn, shared, tasks, results)) as pool:
        while True:
            try:
                items = tasks.recv()
            except EOFError:  # the caller is gone
                break
            if items is None:
                break
            for item in items:
                pool.apply_async(run_task, (item,), callback=sent, error_callback=failed)


class TaskPool:
    """``fn(shared, item)`` for items handed in while other work runs, in ``workers`` forked
    processes (at most :func:`process_count` for ``items``, the most that may be handed
    in), started through a lead process (module doc): create it before the caller starts
    any thread; the per-item work (the hard tail, Python under the GIL) then runs beside
    the caller's threaded chunks without taking its GIL from them (a thread returning from
    compiled code waits for the GIL while the caller runs Python, up to the interpreter's
    switch interval each time).

    Use as a context manager (the lead is told to end with it, and is not waited for);
    :meth:`submit` items as they are known (distinct items), :meth:`results` once all are
    submitted. ``fn`` must be a module-level function. Only where :func:`can_fork`.
    """

    def __init__(self, fn: Callable[[Any, Any], Any], shared: Any, workers: int, items: int):
        ctx = multiprocessing.get_context("fork")
        self.processes = process_count(workers, items)
        task_out, self._tasks = ctx.Pipe(duplex=False)
        self._results, result_in = ctx.Pipe(duplex=False)
        self._lead = ctx.Process(target=_lead, name="moik-task-lead", args=(
            fn, shared, self.processes, task_out, result_in, (self._tasks, self._results)))
        self._lead.start()
        task_out.close()  # the lead's ends: a dead lead then reads as EOF here
        result_in.close()
        self._submitted: set = set()

    def submit(self, items: Iterable) -> None:
        """Hand ``items`` to the processes (each to whichever is free); returns at once."""
        items = list(items)
        if items:
            self._submitted.update(items)
            self._tasks.send(items)

    def results(self) -> dict:
        """``{item: fn(shared, item)}`` of every item submitted (waits for them; raises the
        first error of an item to arrive).

        Raises:
            MoikError: The lead process ended before every result came back.
        """
        out: dict = {}
        while len(out) < len(self._submitted):
            try:
                if not self._results.poll(POLL_S):
                    if self._lead.is_alive():
                        continue
                    raise EOFError
                ok, value = self._results.recv()
            except EOFError:
                raise MoikError(f"the processes solving the per-item tasks ended with "
                                f"{len(self._submitted) - len(out)} of "
                                f"{len(self._submitted)} results still to come (exit code "
                                f"{self._lead.exitcode}; killed for memory?)") from None
            if not ok:
                raise value
            out[value[0]] = value[1]
        return out

    def __enter__(self) -> TaskPool:
        return self

    def __exit__(self, exc_type: Any, *exc: object) -> None:
        if exc_type is None:
            with contextlib.suppress(OSError):  # (a lead gone already needs no telling)
                self._tasks.send(None)  # the lead ends its pool on its own time
        else:  # interrupted: end the lead (and so its pool) now
            self._lead.terminate()
            self._lead.join(END_WAIT_S)
            if self._lead.exitcode is None:
                self._lead.kill()
                self._lead.join()
        self._tasks.close()
        self._results.close()
