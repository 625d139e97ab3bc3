"""``moik algorithms``: the registered algorithms (name, kind, source)."""

from __future__ import annotations

import argparse

from moik.algorithms import available, entry
from moik.cli import output


def cmd_algorithms(args: argparse.Namespace) -> int:
    """Print the registry: name, kind and source of each algorithm."""
    output.print_algorithms([entry(name) for name in available()], args.json)
    return 0
