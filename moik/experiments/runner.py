"""``run_experiment``: plan the trials, skip the finished ones, run and store the rest."""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path

from moik._validate import flag, integer, optional_integer
from moik.experiments.config import ExperimentConfig, check_requirements
from moik.experiments.executors import Progress, connect_dask, execute, sigterm_as_interrupt
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
        rerun_damaged: Of ``ran``, stored trials run again because their arrays were
            damaged or missing.
        notes: What preparing the folder did or found (a stale lock taken over, stale
            temporary files removed, damaged trials run again), one sentence each.
    """

    folder: Path
    total: int
    skipped: int
    ran: int
    failed: int
    wall_time: float
    rerun_damaged: int = 0
    notes: tuple[str, ...] = ()


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
                   limit: int | None = None, by_run: bool = False) -> RunSummary:
    """Run ``config`` (or its quick size) and store every trial as it finishes.

    A Dask scheduler is connected before the folder is made; the folder's run
    lock is held from the start to the end of the run (a second live run into it
    is refused). On resume every stored trial's arrays are read back; a trial
    whose arrays are damaged or missing runs again (said in the summary's notes).

    Args:
        config: The experiment.
        out: Results folder (default :func:`default_out`).
        quick: Run the ``quick`` size.
        workers: Processes (1 = serial in this process; None = the number of cores).
        resume: Continue the results in ``out``, skipping finished trials.
        dask_scheduler: Address of a Dask scheduler (overrides ``workers``).
        progress: Show a progress bar on stderr.
        limit: Run at most this many of the pending trials (to split long runs).
        by_run: Run the pending trials run by run (run 0 of every algorithm and target,
            then run 1, ...) instead of algorithm by algorithm, so that a partial run
            (``limit``, an interruption) has every algorithm on every target for the
            runs it finished. The trials and their results are the same either way.

    Returns:
        A :class:`RunSummary`.

    Raises:
        ResultsError: If ``out`` holds other results, or another live run holds it
            (see :meth:`ResultStore.create`).
        ConfigError: If an optional extra the experiment ``requires`` is missing.
        ParameterError: For bad ``workers``/``limit`` or an unreachable scheduler.
    """
    t0 = time.perf_counter()
    cfg = config.quick() if quick else config
    workers = check_workers(workers)
    limit = optional_integer("limit", limit, minimum=0)
    by_run = flag("by_run", by_run)
    check_requirements(cfg)
    targets = list(cfg.targets)
    specs = build_trials(cfg, targets)
    folder = Path(out) if out is not None else default_out(cfg)
    executor = f"dask:{dask_scheduler}" if dask_scheduler else (
        f"pool:{workers}" if workers > 1 else "serial")
    client = connect_dask(dask_scheduler) if dask_scheduler else None
    try:
        return _run(cfg, specs, targets, folder, executor, client=client, workers=workers,
                    dask_scheduler=dask_scheduler, resume=resume, progress=progress,
                    limit=limit, by_run=by_run, t0=t0)
    finally:
        if client is not None:
            client.close()


def _run(cfg: ExperimentConfig, specs, targets, folder: Path, executor: str, *, client,
         workers: int, dask_scheduler: str | None, resume: bool, progress: bool,
         limit: int | None, by_run: bool, t0: float) -> RunSummary:
    """The run under the folder's lock (see :func:`run_experiment`)."""
    store = ResultStore.create(folder, config=cfg, targets=[t.as_dict() for t in targets],
                               trials=[spec_summary(s) for s in specs], resume=resume,
                               session={"executor": executor})
    failed = ran = 0
    try:
        records = store.records()
        damaged = store.check_arrays(records)
        ok = {r["trial"] for r in records if r.get("status") == "ok"}
        done = ok - set(damaged)
        notes = list(store.notes)
        if damaged:
            notes.append(f"{len(damaged)} stored trial(s) have damaged or missing arrays, so "
                         "they count as not finished and run again: "
                         + "; ".join(damaged.values()))
        pending = [s for s in specs if s.trial_id not in done]
        skipped = len(specs) - len(pending)
        if by_run:
            pending.sort(key=lambda s: s.run)  # stable: algorithm-major within a run
        if limit is not None:
            pending = pending[:limit]
        bar = Progress(total=len(pending), done=skipped, label=cfg.name, enabled=progress)
        try:
            with sigterm_as_interrupt():
                for record, arrays in execute(pending, workers=workers,
                                              dask_scheduler=dask_scheduler,
                                              dask_client=client):
                    store.append(record, arrays)
                    ran += 1
                    failed += record.get("status") != "ok"
                    bar.update(record.get("status") == "ok")
        finally:
            bar.close()
            store.end_session(wall_time=time.perf_counter() - t0, ran=ran)
    finally:
        store.close()
    return RunSummary(folder=folder, total=len(specs), skipped=skipped, ran=len(pending),
                      failed=failed, wall_time=time.perf_counter() - t0,
                      rerun_damaged=sum(s.trial_id in damaged for s in pending),
                      notes=tuple(notes))
