"""The ``moik experiment list|run`` and ``moik report [--docs]`` subcommands."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from moik._validate import integer
from moik.exceptions import MoikError, ParameterError
from moik.experiments.config import load_config
from moik.experiments.docs import write_docs
from moik.experiments.registry import ENV_VAR, experiment_files, get_experiment
from moik.experiments.report import make_report
from moik.experiments.runner import default_out, run_experiment


def cmd_list(args: argparse.Namespace) -> int:
    """Print every experiment with its trial counts (full / quick) and title."""
    files = experiment_files()
    if not files:
        print(f"no experiments found (see {ENV_VAR})")
        return 0
    print(f"{'name':<16}{'trials':>8}{'quick':>7}  title")
    for name in files:
        try:
            cfg = get_experiment(name)
            counts = [len(c.algorithms) * len(c.targets) * c["runs"] for c in (cfg, cfg.quick())]
            print(f"{name:<16}{counts[0]:>8}{counts[1]:>7}  {cfg['title']}")
        except MoikError as exc:
            print(f"{name:<16}{'-':>8}{'-':>7}  INVALID: {exc}")
    return 0


def cmd_run(args: argparse.Namespace) -> int:
    """Run one experiment (by name or ``--config FILE``); Ctrl-C keeps the stored trials."""
    config = load_config(args.config) if args.config else get_experiment(args.name)
    what = f"--config {args.config}" if args.config else args.name
    out = args.out or default_out(config.quick() if args.quick else config)
    try:
        summary = run_experiment(config, out=out, quick=args.quick, workers=args.workers,
                                 resume=args.resume, dask_scheduler=args.dask_scheduler,
                                 progress=not args.no_progress, limit=args.limit,
                                 by_run=args.by_run)
    except KeyboardInterrupt:
        print(f"\nmoik: interrupted; finished trials are stored in {out}; continue with "
              f"`moik experiment run {what}{' --quick' if args.quick else ''} --out {out} "
              "--resume`", file=sys.stderr)
        return 130
    for note in summary.notes:
        print(f"moik: note: {note}", file=sys.stderr)
    print(f"{config.name}: ran {summary.ran} trial(s) ({summary.failed} failed), "
          f"{summary.skipped} already finished, {summary.total} in all, "
          f"{summary.wall_time:.1f} s; results in {summary.folder}")
    left = summary.total - summary.skipped - summary.ran + summary.failed
    if left:
        print(f"{left} trial(s) not finished: rerun with --resume to run them")
    print(f"report: moik report {summary.folder}")
    return 0 if summary.failed == 0 else 1


def cmd_report(args: argparse.Namespace) -> int:
    """Write the report of each results folder, or with ``--docs`` the docs (1 if one failed)."""
    if args.docs is not None:
        if args.output is not None:
            raise ParameterError("--output names the report file of one folder; --docs writes "
                                 "the docs folder instead: give one of them")
        return _docs(args)
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


def _docs(args: argparse.Namespace) -> int:
    update = write_docs(args.folder, args.docs, figures=not args.no_figures)
    for page in update.pages:
        print(f"written {page}")
    replaced = ", ".join(f"{name} {kind}" for name, kind in update.replaced) or "none"
    pages = ", ".join(str(p) for p in update.block_pages) or str(Path(args.docs) / "reproducing.md")
    print(f"{pages}: blocks regenerated: {replaced}; kept as they are: {len(update.kept)}")
    if update.warnings:
        print(f"{len(update.warnings)} warning(s) (see stderr)")
    return 1 if update.warnings else 0


def _positive_int(text: str) -> int:
    """An argparse type: ``text`` as an integer >= 1 (the rule of :mod:`moik._validate`)."""
    try:
        return integer("value", int(text), minimum=1)
    except ValueError:  # int() failed, or ParameterError (a ValueError): below 1
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}") from None


def add_subcommands(sub) -> None:
    """Register ``experiment`` and ``report`` on the ``moik`` subparsers."""
    p = sub.add_parser("experiment", help="list or run the papers' experiments",
                       description="List or run the experiments that regenerate the papers' "
                                   "tables and figures.")
    esub = p.add_subparsers(dest="experiment_command", required=True)
    q = esub.add_parser("list", help="list the experiments (trials full / quick size)")
    q.set_defaults(func=cmd_list)
    q = esub.add_parser("run", help="run an experiment; results are stored trial by trial",
                        description="Run an experiment. Each finished trial is stored at once; "
                                    "Ctrl-C loses only the trials in flight; --resume continues.")
    which = q.add_mutually_exclusive_group(required=True)
    which.add_argument("name", nargs="?",
                       help="experiment name (see `moik experiment list`) or config file")
    which.add_argument("--config", metavar="FILE",
                       help="run the experiment defined by this config file (your own; the "
                            f"folders in {ENV_VAR} are listed by name too)")
    q.add_argument("--quick", action="store_true", help="the seconds-long smoke-test size")
    q.add_argument("--workers", type=_positive_int, default=None,
                   help="worker processes (default: the number of cores; 1 = serial)")
    q.add_argument("--resume", action="store_true",
                   help="continue the results in --out, skipping finished trials")
    q.add_argument("--out", metavar="DIR",
                   help="results folder (default results/NAME or results/NAME-quick)")
    q.add_argument("--dask-scheduler", metavar="ADDRESS",
                   help="run on a Dask distributed scheduler (needs moik[dask])")
    q.add_argument("--limit", type=_positive_int, default=None,
                   help="run at most this many pending trials, then stop")
    q.add_argument("--by-run", action="store_true",
                   help="run trials run by run (run 0 of every algorithm and target first), so "
                        "a partial run compares every algorithm")
    q.add_argument("--no-progress", action="store_true", help="no progress bar")
    q.set_defaults(func=cmd_run)
    p = sub.add_parser("report", help="write a Markdown report of results folders, or the docs",
                       description="Write DIR/report.md: tables beside the paper's numbers, "
                                   "and figures. DIR is a results folder or a folder of them. "
                                   "With --docs DOCS: write DOCS/results/NAME.md per experiment "
                                   "and regenerate its blocks in DOCS/reproducing.md.")
    p.add_argument("folder", metavar="DIR", nargs="+",
                   help="results folder (or a folder of them)")
    p.add_argument("--no-figures", action="store_true", help="tables only")
    p.add_argument("--output", metavar="FILE", help="report file (default DIR/report.md)")
    p.add_argument("--docs", metavar="DOCS",
                   help="docs folder to regenerate from the results (e.g. docs/)")
    p.set_defaults(func=cmd_report)
