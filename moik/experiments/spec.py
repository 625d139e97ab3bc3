"""The trial spec: everything one trial (algorithm x target x run) needs, as plain data.

Seeds: ``SeedSequence(config seed).spawn(n_targets * runs)``; child
``k = target * runs + run`` seeds trial (target, run) of *every* algorithm, so
all algorithms see the same random streams. A trial records the child's
``entropy`` and ``spawn_key`` (it is rebuilt as
``SeedSequence(entropy, spawn_key=spawn_key)``, identical to the spawned
child wherever the trial runs) and the integer ``seed`` given to pymoo.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np


class TrialTarget(Protocol):
    """What a trial's target is to the runner: a display name and a JSON-ready form.

    IK experiments have :class:`~moik.experiments.kinds.ik_targets.NamedTarget`,
    benchmark-function experiments
    :class:`~moik.experiments.kinds.functions.BenchmarkTarget`.
    """

    name: str

    def as_dict(self) -> dict:
        """JSON-ready form, stored in the results' metadata."""


@dataclass(frozen=True)
class TrialSpec:
    """Everything one trial needs, as picklable data.

    Attributes:
        trial_id: ``"<label>/<target index>/<run>"``, unique in the experiment.
        kind: The experiment kind (a key of :data:`moik.experiments.kinds.KINDS`)
            whose trial function runs it.
        label: Algorithm label; ``algorithm``/``params`` its registry name and keywords.
        target_index: Index into the experiment's targets; ``target`` the target itself.
        run: Run index per (algorithm, target).
        entropy: Root entropy (the config seed); ``spawn_key`` the child's key.
        seed: Integer seed handed to pymoo (first word of the child's state).
        robot: Robot name, or a URDF arm resolved
            (:func:`moik.experiments.kinds.ik_robot.resolve`; None for benchmark
            functions); ``problem`` the problem
            dict; ``iterations`` the update iterations after the initial population
            (the papers' Max_t; pymoo's termination is ``("n_gen", iterations + 1)``).
        protocol: ``{"threshold", "max_failures"}`` or None.
        record_history: Store the best-so-far x of every generation as the
            array ``best_x_history`` (experiments with the ``joint-motion``
            analysis: EOSMA Fig. 19a).
    """

    trial_id: str
    kind: str
    label: str
    algorithm: str
    params: dict
    target_index: int
    target: TrialTarget
    run: int
    entropy: int
    spawn_key: tuple[int, ...]
    seed: int
    robot: str | dict | None
    problem: dict
    iterations: int
    protocol: dict | None
    record_history: bool = False

    @property
    def seed_sequence(self) -> np.random.SeedSequence:
        """The trial's ``SeedSequence`` (equal to the spawned child)."""
        return np.random.SeedSequence(self.entropy, spawn_key=self.spawn_key)


def trial_seeds(seed: int, n_targets: int, runs: int) -> list[np.random.SeedSequence]:
    """Children ``k = target * runs + run`` of ``SeedSequence(seed)``, shared by all algorithms."""
    return np.random.SeedSequence(seed).spawn(n_targets * runs)


def spec_summary(spec: TrialSpec) -> dict:
    """The seeds and identity of a trial, for the metadata (no target geometry)."""
    return {"trial_id": spec.trial_id, "label": spec.label, "target_index": spec.target_index,
            "run": spec.run, "seed": spec.seed, "entropy": spec.entropy,
            "spawn_key": tuple(spec.spawn_key)}
