"""The ``--out FILE`` option of the benchmark scripts: print as usual, and store the table.

Each benchmark prints its table to stdout. With ``--out FILE`` the same text is also
written to ``FILE`` (e.g. ``docs/results/fk.txt``, which the docs link to), after one
header line naming the command, the date, the machine and its load average, so a
stored table says where its numbers came from. Numbers in the docs are never typed
in by hand: they live in these files.

Use::

    parser.add_argument("--out", help=OUT_HELP)
    args = parser.parse_args()
    with table_output(args.out):
        ...  # print the tables
"""

from __future__ import annotations

import contextlib
import os
import platform
import shlex
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import TextIO

OUT_HELP = "also write the printed table to this file (after a header line)"


def header_line(argv: list[str] | None = None) -> str:
    """The first line of a stored table: command, date, machine and load average.

    Args:
        argv: The command line (``sys.argv`` when None); its script is named
            ``benchmarks/<script>``, so the line reads the same from any directory.

    Returns:
        A ``#`` comment line without a trailing newline.
    """
    argv = list(sys.argv if argv is None else argv)
    command = shlex.join([f"benchmarks/{Path(argv[0]).name}", *argv[1:]])
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return (f"# {command}; {time.strftime('%Y-%m-%d %H:%M')}, {platform.machine()}, "
            f"{os.cpu_count()} CPUs, Python {platform.python_version()}, "
            f"load average {load:.2f}")


class _Tee:
    """A text stream writing to the terminal's stream and to a file, flushing both."""

    def __init__(self, *, terminal: TextIO, file: TextIO) -> None:
        self._streams = (terminal, file)

    def write(self, text: str) -> int:
        for stream in self._streams:
            stream.write(text)
        return len(text)

    def flush(self) -> None:
        for stream in self._streams:
            stream.flush()


@contextlib.contextmanager
def table_output(path: str | os.PathLike[str] | None) -> Iterator[None]:
    """Within the block, everything printed also goes to ``path`` (when one is given).

    The header line (:func:`header_line`) is printed first, to both; the file is
    written as the run goes (flushed on every write), so an interrupted run keeps
    what it printed.

    Args:
        path: The file to write (created or replaced), or None to print only.

    Yields:
        Nothing; print as usual inside the block.
    """
    if path is None:
        yield
        return
    with open(path, "w") as file, contextlib.redirect_stdout(
            _Tee(terminal=sys.stdout, file=file)):
        print(header_line())
        yield
