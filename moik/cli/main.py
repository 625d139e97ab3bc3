"""The entry point: parse the command line, run the subcommand's module, map errors to exit codes.

Each subcommand lives in its own module of :mod:`moik.cli`, named by the parser
(``handler="solve:run"``: the function ``run`` of :mod:`moik.cli.solve`) and
imported only when that subcommand runs: numba, pymoo and scipy take about a second
to import, which ``moik --help`` or ``moik experiment list`` need not pay. The
imports under ``TYPE_CHECKING`` state the same edges for the type checker and the
import-graph test.
"""

from __future__ import annotations

import contextlib
import importlib
import os
import signal
import sys
import threading
import time
import warnings
from collections.abc import Iterator
from typing import TYPE_CHECKING

from moik.cli.parser import build_parser
from moik.exceptions import MoikError, MoikWarning

if TYPE_CHECKING:
    from moik.cli import (  # noqa: F401
        algorithms,
        batch,
        catalog,
        experiment,
        fk,
        kernels,
        problems,
        report,
        solve,
    )


def _handler(spec: str):
    """The function named ``"module:function"`` in :mod:`moik.cli`."""
    module, function = spec.split(":")
    return getattr(importlib.import_module(f"moik.cli.{module}"), function)


def _show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """A warning as the command prints it: one line on stderr, no source location."""
    print(f"moik: warning: {message}", file=sys.stderr if file is None else file)


def _compiled() -> int:
    """Kernels compiled so far in this process; never imports ``moik._jit`` (nor numba):
    ``sys.modules`` may hold it as a lazy module (:func:`moik._lazy.lazy_module`), loaded
    at its first attribute access, so numba's presence tells whether it is loaded."""
    jit = sys.modules.get("moik._jit")
    return jit.compile_count() if jit is not None and "numba" in sys.modules else 0


def _compile_summary(count: int, seconds: float) -> None:
    """After a command that compiled kernels (the notice said so): how many, how long."""
    if count:
        print(f"moik: compiled {count} kernels (the command took {seconds:.1f} s); the next "
              "runs load them from the cache", file=sys.stderr)


class Terminated(KeyboardInterrupt):
    """SIGTERM arrived (handled as Ctrl-C: files being written are removed, locks released)."""


def _terminate(signum, frame) -> None:
    raise Terminated(f"signal {signum}")


@contextlib.contextmanager
def _signals_honoured() -> Iterator[None]:
    """While inside, SIGTERM raises :class:`Terminated` (SIGINT raises ``KeyboardInterrupt``
    as always, unless the caller ignored it), so either ends the command through the same
    clean-up and one line. Only in the main thread; the handler is restored."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    before = signal.signal(signal.SIGTERM, _terminate)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, before)


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``moik`` console script and of ``python -m moik``.

    SIGINT (Ctrl-C) and SIGTERM are honoured from the first instruction: the command
    stops with one line on stderr and exit status 130 (SIGINT) or 143 (SIGTERM), no
    traceback; a file being written is removed, a run keeps its finished trials.
    """
    with _signals_honoured():
        try:
            return _main(argv)
        except KeyboardInterrupt as exc:
            term = isinstance(exc, Terminated) or type(exc).__name__ == "Terminated"
            print(f"moik: interrupted ({'SIGTERM' if term else 'SIGINT'})", file=sys.stderr)
            return 143 if term else 130


def _main(argv: list[str] | None) -> int:
    args = build_parser().parse_args(argv)
    try:
        with warnings.catch_warnings():
            warnings.showwarning = _show_warning
            warnings.simplefilter("default", MoikWarning)  # printed, whatever -W says
            t0, before = time.perf_counter(), _compiled()
            status = _handler(args.handler)(args)
            _compile_summary(_compiled() - before, time.perf_counter() - t0)
            return status
    except MoikError as exc:
        print(f"moik: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. `moik experiment list | head`: stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except OSError as exc:  # a folder or file that cannot be written (--out, --plot)
        what = f"cannot use {exc.filename}: " if exc.filename else ""
        print(f"moik: error: {what}{exc.strerror or exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
