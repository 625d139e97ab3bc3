"""A child process that compiles one family of kernels while this process compiles others.

numba compiles one kernel at a time in a process. Where a first use needs two families
of kernels that do not call each other, :func:`start` runs a child process (``python -m
moik.warmup``, the family's name and arguments pickled on its stdin) that calls one
family on arguments of the same numba types, so that numba writes it to the disk cache,
while this process compiles the other. A dispatcher of this process loads from the cache
what the child has written by the time it needs it and compiles the rest itself, so the
child changes nothing but time: a child that fails, is slow or is stopped only leaves
more for this process to compile.

A child starts only where it can help: this process may use more than one CPU and at
least half of one was idle over the last tenth of a second (:func:`idle_cpus`; the load
average of the last minute where the system's CPU times cannot be read): on a busy machine
the child only takes CPU time from its parent (``benchmarks/startup.py
--without-background`` measured it so); ``MOIK_BACKGROUND_COMPILE`` is not ``0`` (a child
runs with it ``0``: no grandchild; so do ``moik compile``'s workers); and a probe kernel
of the family is not cached yet. ``MOIK_BACKGROUND_COMPILE=1`` starts it on a busy
machine too (to measure it).
"""

from __future__ import annotations

import atexit
import contextlib
import os
import pickle
import subprocess
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from moik import _jit
from moik._machine import available_cores

ENV_SWITCH = "MOIK_BACKGROUND_COMPILE"
CHILD_MODULE = "moik.warmup"  # what the child runs (``python -m``)
MIN_IDLE = 0.5  # CPUs that must be idle (idle_cpus) for a child to start


IDLE_WINDOW = 0.1  # seconds over which idle CPU time is measured (idle_cpus)
PROC_STAT = "/proc/stat"


def _cpu_times() -> tuple[float, float] | None:
    """(idle, total) CPU time of the system so far (Linux's /proc/stat), or None."""
    try:
        with open(PROC_STAT) as f:
            fields = [float(x) for x in f.readline().split()[1:]]
    except (OSError, ValueError):
        return None
    if len(fields) < 5:
        return None
    return fields[3] + fields[4], sum(fields[:8])  # idle + iowait; user .. steal


def idle_cpus() -> float:
    """CPUs this process may run on times the share of the system's CPU time that was
    idle over the last :data:`IDLE_WINDOW` seconds; where that cannot be read, the CPUs
    less the load average of the last minute (all of them where there is none either).
    The present, not the last minute: the load average still counts a command that has
    just ended (a first solve right after another reads a busy machine for a minute)."""
    before = _cpu_times()
    if before is not None:
        time.sleep(IDLE_WINDOW)
        after = _cpu_times()
        if after is not None and after[1] > before[1]:
            return available_cores() * (after[0] - before[0]) / (after[1] - before[1])
    try:
        return available_cores() - os.getloadavg()[0]
    except (AttributeError, OSError):  # not on every platform
        return float(available_cores())


class Background:
    """A running child process compiling kernels (from :func:`start`); stopped at exit."""

    def __init__(self, process: subprocess.Popen):
        self.process = process
        atexit.register(self.stop)

    def wait(self, seconds: float) -> None:
        """Return when the child has ended or ``seconds`` have passed."""
        with contextlib.suppress(subprocess.TimeoutExpired):
            self.process.wait(timeout=seconds)

    def stop(self) -> None:
        """Stop the child if it still runs."""
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()


def start(family: str, arguments: Any, probes: Sequence[Any]) -> Background | None:
    """Run ``python -m moik.warmup`` on ``(family, arguments)`` (pickled on its stdin, read
    back by :func:`child_arguments`), or return None where it cannot help (module
    docstring): ``probes`` (kernels of the family) are all cached already, or
    ``arguments`` cannot be pickled."""
    switch = os.environ.get(ENV_SWITCH)
    if (switch == "0" or available_cores() < 2
            or all(_jit.is_cached(kernel) for kernel in probes)
            or (switch != "1" and idle_cpus() < MIN_IDLE)):  # last: it takes a tenth of a second
        return None
    try:
        payload = pickle.dumps((family, arguments))
    except Exception:  # noqa: BLE001 - a robot pickle cannot take: compile here
        return None
    # the child imports this moik: ``-m`` puts its working folder first on sys.path (before
    # PYTHONPATH), so it runs in the folder this moik is imported from, not in ours (which
    # may hold another moik, a checkout: it would compile that one's kernels, of no use here)
    root = str(Path(__file__).resolve().parents[2])
    env = {**os.environ, ENV_SWITCH: "0",
           "PYTHONPATH": os.pathsep.join(p for p in (root, os.environ.get("PYTHONPATH")) if p)}
    try:
        process = subprocess.Popen([sys.executable, "-m", CHILD_MODULE], stdin=subprocess.PIPE,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                   env=env, cwd=root)
        assert process.stdin is not None
        process.stdin.write(payload)
        process.stdin.close()
    except (OSError, ValueError):  # no interpreter to start, no pipe: compile here
        return None
    child = Background(process)
    _jit.compiled_elsewhere(probes, child.wait)
    return child


def child_arguments() -> tuple[str, Any]:
    """In a child: the family and arguments :func:`start` was given."""
    return pickle.loads(sys.stdin.buffer.read())
