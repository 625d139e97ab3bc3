"""The entry point: parse the command line, run the subcommand's module, map errors to exit codes.

Each subcommand lives in its own module of :mod:`moik.cli`, named by the parser
(``handler="solve:run"``: the function ``run`` of :mod:`moik.cli.solve`) and
imported only when that subcommand runs: numba, pymoo and scipy take about a second
to import, which ``moik --help`` or ``moik experiment list`` need not pay. The
imports under ``TYPE_CHECKING`` state the same edges for the type checker and the
import-graph test.
"""

from __future__ import annotations

import importlib
import os
import sys
import warnings
from typing import TYPE_CHECKING

from moik.cli.parser import build_parser
from moik.exceptions import MoikError, MoikWarning

if TYPE_CHECKING:
    from moik.cli import algorithms, catalog, experiment, fk, report, solve  # noqa: F401


def _handler(spec: str):
    """The function named ``"module:function"`` in :mod:`moik.cli`."""
    module, function = spec.split(":")
    return getattr(importlib.import_module(f"moik.cli.{module}"), function)


def _show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """A warning as the command prints it: one line on stderr, no source location."""
    print(f"moik: warning: {message}", file=sys.stderr if file is None else file)


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``moik`` console script and of ``python -m moik``."""
    args = build_parser().parse_args(argv)
    try:
        with warnings.catch_warnings():
            warnings.showwarning = _show_warning
            warnings.simplefilter("default", MoikWarning)  # printed, whatever -W says
            return _handler(args.handler)(args)
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
