"""Trials (algorithm x target x run): planning them, and running one.

:func:`build_trials` gives every trial its seeds (see :mod:`moik.experiments.spec`).
:func:`run_trial` is a pure function of its :class:`~moik.experiments.spec.TrialSpec`:
it returns a JSON-ready record and a dict of arrays, and never raises for a
failing algorithm (the record then has ``status="error"``); the trial function
of the experiment's kind (:mod:`moik.experiments.kinds`) fills in the results.
"""

from __future__ import annotations

import os
import socket
import traceback

import numpy as np

from moik.experiments.kinds import KINDS
from moik.experiments.spec import TrialSpec, TrialTarget, trial_seeds


def build_trials(config, targets: list[TrialTarget] | None = None) -> list[TrialSpec]:
    """All trials of ``config``, algorithm-major (the report order).

    Args:
        config: An :class:`~moik.experiments.config.ExperimentConfig`.
        targets: The targets (default: the config's, built when it was validated).
    """
    targets = list(config.targets) if targets is None else targets
    runs = config["runs"]
    children = trial_seeds(config["seed"], len(targets), runs)
    specs = []
    for alg in config.algorithms:
        for ti, target in enumerate(targets):
            for r in range(runs):
                child = children[ti * runs + r]
                specs.append(TrialSpec(
                    trial_id=f"{alg.label}/{ti}/{r}", kind=config.kind, label=alg.label,
                    algorithm=alg.name, params=dict(alg.params), target_index=ti, target=target,
                    run=r, entropy=int(child.entropy), spawn_key=tuple(child.spawn_key),
                    seed=int(child.generate_state(1, dtype=np.uint32)[0]),
                    robot=getattr(target, "robot", None) or config.robot,
                    problem=dict(config["problem"]),
                    iterations=config["iterations"], protocol=config["protocol"],
                    record_history="joint-motion" in (config["analyses"] or [])))
    return specs


def run_trial(spec: TrialSpec) -> tuple[dict, dict]:
    """Run one trial; returns ``(record, arrays)``, never raises for algorithm failures.

    The record holds the trial's identity and seeds, ``status`` (``"ok"`` or
    ``"error"`` with ``error``), ``time`` (s), ``n_eval``, and the results that
    the kind's trial function records (:mod:`moik.experiments.kinds.ik`,
    :mod:`moik.experiments.kinds.functions`).
    """
    record = {"trial": spec.trial_id, "algorithm": spec.label, "algorithm_name": spec.algorithm,
              "target": spec.target_index, "target_name": spec.target.name, "run": spec.run,
              "seed": spec.seed, "seed_entropy": spec.entropy, "spawn_key": list(spec.spawn_key),
              "worker": f"{socket.gethostname()}:{os.getpid()}", "status": "ok"}
    arrays: dict = {}
    try:
        KINDS[spec.kind].run_trial(spec, record, arrays)
    except Exception as exc:  # a failing trial is recorded, the experiment goes on
        record.update(status="error", error=f"{type(exc).__name__}: {exc}",
                      traceback=traceback.format_exc(limit=8))
        arrays = {}
    return record, arrays
