"""``moik experiment list`` and ``moik experiment run NAME | --config FILE``."""

from __future__ import annotations

import argparse
import sys

from moik.cli import output
from moik.exceptions import MoikError
from moik.experiments.config import load_config
from moik.experiments.registry import ENV_VAR, experiment_files, get_experiment
from moik.experiments.runner import default_out, run_experiment


def cmd_list(args: argparse.Namespace) -> int:
    """Print every experiment with its trial counts (full / quick) and title."""
    files = experiment_files()
    if not files:
        print(f"no experiments found (see {ENV_VAR})")
        return 0
    rows = []
    for name in files:
        try:
            cfg = get_experiment(name)
            counts = [len(c.algorithms) * len(c.targets) * c["runs"] for c in (cfg, cfg.quick())]
            rows.append([name, str(counts[0]), str(counts[1]), cfg["title"]])
        except MoikError as exc:
            rows.append([name, "-", "-", f"INVALID: {exc}"])
    print(output.table(["name", "trials", "quick", "title"], rows, right={1, 2}))
    return 0


def cmd_run(args: argparse.Namespace) -> int:
    """Run one experiment (by name or ``--config FILE``); Ctrl-C keeps the stored trials."""
    config = (load_config(args.config, experiment_files()) if args.config
              else get_experiment(args.name))
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
