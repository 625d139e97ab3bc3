"""The machine moik runs on: the CPUs this process may use (the batch solver's workers and
the background compiles; the collision package, below them, counts its own)."""

from __future__ import annotations

import os


def available_cores() -> int:
    """The CPUs this process may run on (its affinity where the platform tells it)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # macOS, Windows
        return os.cpu_count() or 1
