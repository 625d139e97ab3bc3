"""Kernels compiled in a second process while this one compiles others (a cold start).

numba compiles one kernel at a time in a process. Where a first use needs two families
of kernels that do not call each other, :func:`start` runs a child process (``python -m
module``, its arguments pickled on its stdin) that calls one family on stand-in
arguments of the same types, so that numba writes it to the disk cache, while this
process compiles the other. A dispatcher of this process loads from the cache what the
child has written by the time it needs it and compiles the rest itself, so the child
changes nothing but time: a child that fails, is slow or is stopped only leaves more
for this process to compile. A child may say on its stdout (:func:`ready`) that a part
of its work is done; :meth:`Background.wait` waits for that line.

A child starts only where it can help: this process may use more than one CPU,
``MOIK_BACKGROUND_COMPILE`` is not ``0`` (a child runs with it ``0``: no grandchild; so do
``moik compile``'s workers), and a probe kernel of the family is not cached yet.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import pickle
import subprocess
import sys
import threading
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from moik import _jit

ENV_SWITCH = "MOIK_BACKGROUND_COMPILE"
READY = "ready\n"  # a child's line once the part of its work waited for is cached
WAIT_LIMIT = 120.0  # seconds :meth:`Background.wait` waits at most


def cpus() -> int:
    """CPUs this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on every platform
        return os.cpu_count() or 1


class Background:
    """A running child process compiling kernels (from :func:`start`); stopped at exit."""

    def __init__(self, process: subprocess.Popen):
        self.process = process
        self._ready = threading.Event()
        threading.Thread(target=self._read, daemon=True).start()
        atexit.register(self.stop)

    def _read(self) -> None:
        with contextlib.suppress(Exception):  # a closed pipe: as if the child ended
            self.process.stdout.readline()  # type: ignore[union-attr]
        self._ready.set()

    def wait(self) -> None:
        """Wait until the child says :data:`READY` (or ends), at most :data:`WAIT_LIMIT` s
        (then it is stopped); the time waited counts as compiling
        (:func:`moik._jit.compile_seconds`)."""
        t0 = time.perf_counter()
        if not self._ready.wait(timeout=WAIT_LIMIT):
            self.stop()
        _jit.add_compile_seconds(time.perf_counter() - t0)

    def stop(self) -> None:
        """Stop the child if it still runs."""
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()


def start(module: str, arguments: Any, probes: Sequence[Any]) -> Background | None:
    """Run ``python -m module`` with ``arguments`` (pickled on its stdin, read back by
    :func:`child_arguments`), or return None where it cannot help (module docstring):
    ``probes`` are kernels of the child's family, all already cached, or ``arguments``
    cannot be pickled."""
    if (os.environ.get(ENV_SWITCH) == "0" or cpus() < 2
            or all(_jit.is_cached(kernel) for kernel in probes)):
        return None
    try:
        payload = pickle.dumps(arguments)
    except Exception:  # noqa: BLE001 - a robot pickle cannot take: compile here
        return None
    # the child imports this moik: ``-m`` puts its working folder first on sys.path (before
    # PYTHONPATH), so it runs in the folder this moik is imported from, not in ours (which
    # may hold another moik, a checkout: it would compile that one's kernels, of no use here)
    root = str(Path(__file__).resolve().parents[1])
    env = {**os.environ, ENV_SWITCH: "0",
           "PYTHONPATH": os.pathsep.join(p for p in (root, os.environ.get("PYTHONPATH")) if p)}
    try:
        process = subprocess.Popen([sys.executable, "-m", module], stdin=subprocess.PIPE,
                                   stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                   env=env, cwd=root)
        assert process.stdin is not None
        process.stdin.write(payload)
        process.stdin.close()
    except (OSError, ValueError):  # no interpreter to start, no pipe: compile here
        return None
    return Background(process)


def child_arguments() -> Any:
    """In a child: the arguments :func:`start` was given."""
    return pickle.loads(sys.stdin.buffer.read())


def ready() -> None:
    """In a child: say that the part of the work its parent waits for is cached."""
    sys.stdout.write(READY)
    sys.stdout.flush()
