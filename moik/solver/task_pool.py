"""Per-item work handed to forked processes while the caller's threads run: :class:`TaskPool`.

A collision-aware batch on many workers solves its hard tail (the whole of ``solve_ik``,
Python under the GIL) in processes beside its threaded chunks, as each chunk ends. The
processes must be forked before the chunks' threads start (a process forked while threads
run may inherit a lock one of them holds), and forking ``W`` processes of a large process
costs the caller ``W`` forks, time in which no chunk runs (``docs/batch.md`` gives the
measured cost of a ``multiprocessing.Pool``); and a ``Pool`` hands out no task before its
last process is forked.

So the caller forks one process, the *lead* (a single fork), and goes on. The lead
forks the ``W`` workers (from a process without threads: the caller's state, inherited),
each taking items as soon as it exists, then waits for them. Items go from the caller to
the workers through one pipe (each worker reads an item under a lock), results from the
workers to the caller through another (each written whole under a lock, read by a thread
of the caller as they come, so no worker ever waits on a full pipe). The caller does not
wait for the processes to end.

A worker that dies (killed for memory, a crash) is reported by the lead as an error
instead of leaving its item unanswered; a caller whose lead dies gets an error instead
of waiting; the lead and workers of a caller that dies read its pipe as closed and end.
Ctrl-C reaches the caller only (the lead and the workers ignore SIGINT); the caller then
ends the lead, and the lead its workers.
"""

from __future__ import annotations

import contextlib
import ctypes
import multiprocessing
import os
import signal
import sys
import threading
from collections.abc import Callable, Iterable
from multiprocessing import connection
from multiprocessing.reduction import ForkingPickler
from typing import Any

from moik._machine import available_cores
from moik.exceptions import MoikError

POLL_S = 0.5  # how often a waiting caller checks that its lead is alive (s)
END_WAIT_S = 5.0  # how long an interrupted caller waits for its lead to end before killing it
PR_SET_PDEATHSIG = 1  # prctl(2)


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


def _send(results: Any, lock: Any, ok: bool, value: Any) -> None:
    """``(ok, value)`` written whole on the results pipe (pickled first: a value that cannot
    be pickled is sent as an error, and nothing half-written is left)."""
    try:
        data = ForkingPickler.dumps((ok, value))
    except Exception as error:
        data = ForkingPickler.dumps((False, MoikError(
            f"a task's {'result' if ok else 'error'} ({type(value).__name__}) could not be "
            f"sent back: {error}")))
    with lock:
        results.send_bytes(data)


def _worker(fn: Callable, shared: Any, pipes: tuple) -> None:
    """A worker: items from the task pipe until ``None`` or its end; each answer sent."""
    tasks, task_lock, results, result_lock = pipes
    while True:
        with task_lock:
            try:
                item = tasks.recv()
            except EOFError:  # the caller is gone
                return
        if item is None:
            return
        try:
            _send(results, result_lock, True, (item, fn(shared, item)))
        except Exception as error:
            _send(results, result_lock, False, error)


def _die_with(lead: int) -> None:
    """This process is killed when the process ``lead`` ends (Linux ``PR_SET_PDEATHSIG``:
    a lead killed outright takes its workers with it), or ends now if it has already."""
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() != lead:
        os._exit(1)


def _lead(fn: Callable, shared: Any, processes: int, pipes: tuple, callers: tuple) -> None:
    """The lead process: forks ``processes`` workers, then waits for them; a worker that
    dies is reported on the results pipe. SIGTERM: its workers are killed, and it ends
    (held back while it forks, so that no worker is left out)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for conn in callers:  # the caller's ends: a dead caller then reads as EOF
        conn.close()
    workers: list[int] = []

    def end(signum: int, frame: Any) -> None:
        for pid in workers:
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)
        os._exit(0)

    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM})
    signal.signal(signal.SIGTERM, end)
    lead = os.getpid()
    for _ in range(processes):
        pid = os.fork()
        if pid == 0:  # a worker; os._exit: nothing of the lead's exit runs here
            code = 0
            try:
                signal.signal(signal.SIGTERM, signal.SIG_DFL)
                signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGTERM})
                _die_with(lead)
                _worker(fn, shared, pipes)
            except BaseException:
                code = 1
            os._exit(code)
        workers.append(pid)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGTERM})  # a SIGTERM held: now
    pipes[0].close()  # the task pipe is the workers'
    _, _, results, result_lock = pipes
    while workers:
        pid, status = os.wait()
        workers.remove(pid)
        if status != 0:
            how = (f"killed by signal {os.WTERMSIG(status)}" if os.WIFSIGNALED(status)
                   else f"exit code {os.waitstatus_to_exitcode(status)}")
            with contextlib.suppress(OSError):  # (a caller gone has no use for it)
                _send(results, result_lock, False, MoikError(
                    f"a process solving per-item tasks died ({how}; killed for memory?): "
                    f"its item has no answer"))
    os._exit(0)


class TaskPool:
    """``fn(shared, item)`` for items handed in while other work runs, in ``workers`` forked
    processes (at most :func:`process_count` for ``items``, the most that may be handed
    in), forked by a lead process (module doc): create it before the caller starts any
    thread; the per-item work (the hard tail, Python under the GIL) then runs beside the
    caller's threaded chunks without taking its GIL from them (a thread returning from
    compiled code waits for the GIL while the caller runs Python, up to the interpreter's
    switch interval each time).

    Use as a context manager (the processes are told to end with it, and not waited for);
    :meth:`submit` items as they are known (distinct, picklable), :meth:`results` once all
    are submitted. Only where :func:`can_fork`.
    """

    def __init__(self, fn: Callable[[Any, Any], Any], shared: Any, workers: int, items: int):
        ctx = multiprocessing.get_context("fork")
        self.processes = process_count(workers, items)
        task_out, self._tasks = ctx.Pipe(duplex=False)
        self._results, result_in = ctx.Pipe(duplex=False)
        pipes = (task_out, ctx.Lock(), result_in, ctx.Lock())
        self._lead = ctx.Process(target=_lead, name="moik-task-lead", args=(
            fn, shared, self.processes, pipes, (self._tasks, self._results)))
        self._lead.start()
        task_out.close()  # the processes' ends: EOF here once they are all gone
        result_in.close()
        self._submitted: set = set()
        self._answers: dict = {}
        self._errors: list[BaseException] = []
        self._ended = False  # the results pipe's end: every process is gone
        self._came = threading.Condition()
        self._wake_r, self._wake_w = ctx.Pipe(duplex=False)  # after the fork: ours alone
        self._reader = threading.Thread(target=self._read, name="moik-task-results",
                                        daemon=True)
        self._reader.start()

    def _read(self) -> None:
        """The reader thread: every answer into ``_answers`` as it comes, until the pipe's
        end or :meth:`__exit__` wakes it."""
        while self._wake_r not in connection.wait([self._results, self._wake_r]):
            try:
                ok, value = self._results.recv()
            except (EOFError, OSError):
                break
            with self._came:
                if ok:
                    self._answers[value[0]] = value[1]
                else:
                    self._errors.append(value)
                self._came.notify_all()
        with self._came:
            self._ended = True
            self._came.notify_all()

    def submit(self, items: Iterable) -> None:
        """Hand ``items`` to the processes (each to whichever is free); returns at once."""
        for item in items:
            self._submitted.add(item)
            self._tasks.send(item)

    def results(self) -> dict:
        """``{item: fn(shared, item)}`` of every item submitted (waits for them; raises the
        first error of an item to arrive).

        Raises:
            MoikError: A process ended before every result came back.
        """
        with self._came:
            while not self._errors and len(self._answers) < len(self._submitted):
                if self._ended or not self._lead.is_alive():
                    self._came.wait(POLL_S)  # answers sent just before the end
                    if self._errors or len(self._answers) >= len(self._submitted):
                        break
                    raise MoikError(
                        f"the processes solving the per-item tasks ended with "
                        f"{len(self._submitted) - len(self._answers)} of "
                        f"{len(self._submitted)} results still to come (lead's exit code "
                        f"{self._lead.exitcode})")
                self._came.wait(POLL_S)
            if self._errors:
                raise self._errors[0]
            return {item: self._answers[item] for item in self._submitted}

    def __enter__(self) -> TaskPool:
        return self

    def __exit__(self, exc_type: Any, *exc: object) -> None:
        if exc_type is None:
            with contextlib.suppress(OSError):  # (processes gone already need no telling)
                for _ in range(self.processes):
                    self._tasks.send(None)  # each worker ends after its item
        else:  # interrupted: end the lead, which kills its workers
            self._lead.terminate()
            self._lead.join(END_WAIT_S)
            if self._lead.exitcode is None:
                self._lead.kill()
                self._lead.join()
        self._wake_w.send(None)  # the reader thread ends now: no thread of this pool is left
        self._reader.join()
        for conn in (self._tasks, self._results, self._wake_r, self._wake_w):
            conn.close()
