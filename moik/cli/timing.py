"""A solve's time as the command prints it: its own work, without the first run's compiling.

The first solve after installing compiles the kernels it needs (or waits for a child
process compiling them); that time is not the solve's. :func:`compiling` measures it
around a library call, and :meth:`Compiling.time_text` prints the rest, saying what was
compiled first: ``12.3 ms (compiled 10 kernels in 22.1 s first)``.
"""

from __future__ import annotations

import sys
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


def _so_far() -> tuple[int, float]:
    """Kernels compiled and seconds spent compiling so far in this process, read without
    importing ``moik._jit`` (nor numba; as :func:`moik.cli.main._compiled` does): before
    numba is loaded nothing has been compiled."""
    jit = sys.modules.get("moik._jit")
    if jit is None or "numba" not in sys.modules:
        return 0, 0.0
    return jit.compile_count(), jit.compile_seconds()


@contextmanager
def compiling() -> Iterator[Compiling]:
    """The kernels compiled, and the seconds spent compiling, inside the ``with`` block."""
    out = Compiling()
    kernels, seconds = _so_far()
    try:
        yield out
    finally:
        now_kernels, now_seconds = _so_far()
        out.kernels, out.seconds = now_kernels - kernels, now_seconds - seconds
