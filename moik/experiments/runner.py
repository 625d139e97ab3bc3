"""``run_experiment``: plan the trials, skip the finished ones, run and store the rest."""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path

from moik._validate import integer, optional_integer
from moik.experiments.config import ExperimentConfig
from moik.experiments.executors import Progress, execute
from moik.experiments.kinds.functions import check_requirements
from moik.experiments.spec import spec_summary
from moik.experiments.store import ResultStore
from moik.experiments.trials import build_trials


@dataclass(frozen=True)
class RunSummary:
    """What a call of :func:`run_experiment` did.

    Attributes:
        folder: The results folder.
        total: Trials of the experiment.
        skipped: Trials already finished (resume) and not run again.
        ran: Trials run in this call.
        failed: Of those, trials that ended with ``status="error"``.
        wall_time: Seconds this call took.
    """

    folder: Path
    total: int
    skipped: int
    ran: int
    failed: int
    wall_time: float


def default_out(config: ExperimentConfig) -> Path:
    """``results/NAME`` (``results/NAME-quick`` for the quick size)."""
    return Path("results") / (config.name + ("-quick" if config.is_quick else ""))


def check_workers(workers: int | None) -> int:
    """``workers`` validated; None means the number of cores."""
    if workers is None:
        return os.cpu_count() or 1
    return integer("workers", workers, minimum=1)


def run_experiment(config: ExperimentConfig, *, out: str | Path | None = None,
                   quick: bool = False, workers: int | None = 1, resume: bool = False,
                   dask_scheduler: str | None = None, progress: bool = False,
                   limit: int | None = None) -> RunSummary:
    """Run ``config`` (or its quick size) and store every trial as it finishes.

    Args:
        config: The experiment.
        out: Results folder (default :func:`default_out`).
        quick: Run the ``quick`` size.
        workers: Processes (1 = serial in this process; None = the number of cores).
        resume: Continue the results in ``out``, skipping finished trials.
        dask_scheduler: Address of a Dask scheduler (overrides ``workers``).
        progress: Show a progress bar on stderr.
        limit: Run at most this many of the pending trials (to split long runs).

    Returns:
        A :class:`RunSummary`.

    Raises:
        ResultsError: If ``out`` holds other results (see :meth:`ResultStore.create`).
        ConfigError: If an optional extra the experiment ``requires`` is missing.
        ParameterError: For bad ``workers``/``limit`` or an unreachable scheduler.
    """
    t0 = time.perf_counter()
    cfg = config.quick() if quick else config
    workers = check_workers(workers)
    limit = optional_integer("limit", limit, minimum=0)
    check_requirements(cfg)
    targets = list(cfg.targets)
    specs = build_trials(cfg, targets)
    folder = Path(out) if out is not None else default_out(cfg)
    executor = f"dask:{dask_scheduler}" if dask_scheduler else (
        f"pool:{workers}" if workers > 1 else "serial")
    store = ResultStore.create(folder, config=cfg, targets=[t.as_dict() for t in targets],
                               trials=[spec_summary(s) for s in specs], resume=resume,
                               session={"executor": executor})
    done = store.finished_ids()
    pending = [s for s in specs if s.trial_id not in done]
    skipped = len(specs) - len(pending)
    if limit is not None:
        pending = pending[:limit]
    bar = Progress(total=len(pending), done=skipped, label=cfg.name,
                   enabled=progress)
    failed = 0
    try:
        for record, arrays in execute(pending, workers=workers, dask_scheduler=dask_scheduler):
            store.append(record, arrays)
            ok = record.get("status") == "ok"
            failed += not ok
            bar.update(ok)
    finally:
        bar.close()
        store.close()
    return RunSummary(folder=folder, total=len(specs), skipped=skipped, ran=len(pending),
                      failed=failed, wall_time=time.perf_counter() - t0)
