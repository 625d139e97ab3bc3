"""A solve's time as the command prints it: its own work, without the first run's compiling.

The first solve after installing compiles the kernels it needs (or waits for a child
process compiling them); that time is not the solve's. :func:`compiling` measures it
around a library call, and :meth:`Compiling.time_text` prints the rest, saying what was
compiled first: ``12.3 ms (compiled 10 kernels in 22.1 s first)``.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass


@dataclass
class Compiling:
    """Kernels this process compiled during a call, and the seconds that took."""

    kernels: int = 0
    seconds: float = 0.0

    def time_text(self, seconds: float) -> str:
        """``seconds`` (a call's wall time) less the compiling, in ms, and what was compiled."""
        text = f"{max(seconds - self.seconds, 0.0) * 1e3:.1f} ms"
        if self.kernels:
            text += f" (compiled {self.kernels} kernels in {self.seconds:.1f} s first)"
        elif self.seconds >= 0.05:
            text += f" (waited {self.seconds:.1f} s for kernels compiled in the background)"
        return text


@contextmanager
def compiling() -> Iterator[Compiling]:
    """The kernels compiled, and the seconds spent compiling, inside the ``with`` block."""
    from moik import _jit  # numba: only for a command that solves

    out = Compiling()
    kernels, seconds = _jit.compile_count(), _jit.compile_seconds()
    try:
        yield out
    finally:
        out.kernels = _jit.compile_count() - kernels
        out.seconds = _jit.compile_seconds() - seconds
