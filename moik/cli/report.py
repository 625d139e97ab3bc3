"""``moik report DIR [DIR ...]``, ``moik report DIR ... --docs DOCS`` and ``moik report DIR
--html [FILE]`` (the interactive page, :func:`moik.experiments.report_explorer`)."""

from __future__ import annotations

import argparse
from pathlib import Path

from moik.exceptions import ParameterError
from moik.experiments.docs import write_docs
from moik.experiments.explorer import report_explorer
from moik.experiments.report import make_report


def cmd_report(args: argparse.Namespace) -> int:
    """Write the report of each results folder, or with ``--docs`` the docs (1 if one failed)."""
    if args.force and args.docs is None:
        raise ParameterError("--force goes with --docs (writing the docs from a tree with "
                             "uncommitted changes)")
    if args.docs is not None:
        if args.html is not None:
            raise ParameterError("--docs writes the docs folder; --html the interactive report: "
                                 "give one of them")
        if args.output is not None:
            raise ParameterError("--output names the report file of one folder; --docs writes "
                                 "the docs folder instead: give one of them")
        return _docs(args)
    if args.html is not None:
        return _html(args)
    if args.output is not None and len(args.folder) > 1:
        raise ParameterError(f"--output names one report file, got {len(args.folder)} folders "
                             "(leave it out: each folder gets its report.md)")
    failed = 0
    for folder in args.folder:
        report = make_report(folder, figures=not args.no_figures, output=args.output)
        print(f"report written to {report.path}")
        if report.warnings:
            print(f"{len(report.warnings)} folder(s) with damaged or missing trials (left out; "
                  "see the warnings)")
        if report.failed:
            print(f"{len(report.failed)} folder(s) could not be reported: "
                  + "; ".join(report.failed))
            failed += 1
    return 1 if failed else 0


def _html(args: argparse.Namespace) -> int:
    """``--html [FILE]``: the interactive report of each folder (FILE: of the one folder)."""
    if args.output is not None:
        raise ParameterError("--output names the Markdown report; --html [FILE] writes the "
                             "interactive one instead: give one of them")
    if args.html and len(args.folder) > 1:
        raise ParameterError(f"--html FILE names one page, got {len(args.folder)} folders "
                             "(give --html alone: each folder gets its report.html)")
    for folder in args.folder:
        page = report_explorer(folder, args.html or None)
        print(f"interactive report written to {page}")
    return 0


def _docs(args: argparse.Namespace) -> int:
    update = write_docs(args.folder, args.docs, figures=not args.no_figures, force=args.force)
    for page in update.pages:
        print(f"written {page}")
    replaced = ", ".join(f"{name} {kind}" for name, kind in update.replaced) or "none"
    pages = ", ".join(str(p) for p in update.block_pages) or str(Path(args.docs) / "reproducing.md")
    print(f"{pages}: blocks regenerated: {replaced}; kept as they are: {len(update.kept)}")
    if update.warnings:
        print(f"{len(update.warnings)} warning(s) (see stderr)")
    return 1 if update.warnings else 0
