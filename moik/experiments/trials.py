"""Trials (algorithm x target x run): their seeds, and running one trial.

Seeds: ``SeedSequence(config seed).spawn(n_targets * runs)``; child
``k = target * runs + run`` seeds trial (target, run) of *every* algorithm, so
all algorithms see the same random streams. A trial records the child's
``entropy`` and ``spawn_key`` (it is rebuilt as
``SeedSequence(entropy, spawn_key=spawn_key)``, identical to the spawned
child wherever the trial runs) and the integer ``seed`` given to pymoo.

:func:`run_trial` is a pure function of its :class:`TrialSpec` (a picklable
bundle of plain data): it returns a JSON-ready record and a dict of arrays, and
never raises for a failing algorithm (the record then has ``status="error"``).
"""

from __future__ import annotations

import os
import socket
import time
import traceback
from dataclasses import asdict, dataclass

import numpy as np
from pymoo.core.callback import Callback
from pymoo.optimize import minimize

from moik.experiments.targets import NamedTarget, build_problem, build_targets, experiment_robot


@dataclass(frozen=True)
class TrialSpec:
    """Everything one trial needs, as plain data.

    Attributes:
        trial_id: ``"<label>/<target index>/<run>"``, unique in the experiment.
        label: Algorithm label; ``algorithm``/``params`` its registry name and keywords.
        target_index: Index into the experiment's targets; ``target`` the target itself.
        run: Run index per (algorithm, target).
        entropy: Root entropy (the config seed); ``spawn_key`` the child's key.
        seed: Integer seed handed to pymoo (first word of the child's state).
        robot: Robot name; ``problem`` the problem dict; ``n_gen`` generations.
        protocol: ``{"threshold", "max_failures"}`` or None.
        record_history: Store the best-so-far x of every generation as the
            array ``best_x_history`` (experiments with the ``joint-motion``
            analysis: EOSMA Fig. 19a).
    """

    trial_id: str
    label: str
    algorithm: str
    params: dict
    target_index: int
    target: NamedTarget
    run: int
    entropy: int
    spawn_key: tuple[int, ...]
    seed: int
    robot: str
    problem: dict
    n_gen: int
    protocol: dict | None
    record_history: bool = False

    @property
    def seed_sequence(self) -> np.random.SeedSequence:
        """The trial's ``SeedSequence`` (equal to the spawned child)."""
        return np.random.SeedSequence(self.entropy, spawn_key=self.spawn_key)


def trial_seeds(seed: int, n_targets: int, runs: int) -> list[np.random.SeedSequence]:
    """Children ``k = target * runs + run`` of ``SeedSequence(seed)``, shared by all algorithms."""
    return np.random.SeedSequence(seed).spawn(n_targets * runs)


def build_trials(config, targets: list[NamedTarget] | None = None) -> list[TrialSpec]:
    """All trials of ``config``, algorithm-major (the report order)."""
    targets = build_targets(config) if targets is None else targets
    runs = config["runs"]
    children = trial_seeds(config["seed"], len(targets), runs)
    specs = []
    for alg in config.algorithms:
        for ti, target in enumerate(targets):
            for r in range(runs):
                child = children[ti * runs + r]
                specs.append(TrialSpec(
                    trial_id=f"{alg.label}/{ti}/{r}", label=alg.label, algorithm=alg.name,
                    params=dict(alg.params), target_index=ti, target=target, run=r,
                    entropy=int(child.entropy), spawn_key=tuple(child.spawn_key),
                    seed=int(child.generate_state(1, dtype=np.uint32)[0]),
                    robot=getattr(target, "robot", None) or config["robot"],
                    problem=dict(config["problem"]),
                    n_gen=config["n_gen"], protocol=config["protocol"],
                    record_history="joint-motion" in (config["analyses"] or [])))
    return specs


class _BestF(Callback):
    """Best f per generation, for pymoo algorithms without ``convergence``."""

    def notify(self, algorithm) -> None:
        opt = algorithm.opt
        F = None if opt is None else opt.get("F")
        self.data.setdefault("best", []).append(float(np.min(F)) if F is not None and len(F)
                                                else np.inf)


def _make_algorithm(spec: TrialSpec, created: list):
    from moik.algorithms import get_algorithm
    from moik.algorithms.base import ArrayAlgorithm

    def factory():
        algorithm = get_algorithm(spec.algorithm, **spec.params)
        if not isinstance(algorithm, ArrayAlgorithm) and ".soo." in type(algorithm).__module__:
            algorithm.callback = _BestF()
        created.append(algorithm)
        return algorithm

    return factory


def _convergence(algorithm) -> np.ndarray:
    if hasattr(algorithm, "convergence"):
        return np.asarray(algorithm.convergence, dtype=float)
    cb = getattr(algorithm, "callback", None)
    return np.asarray(cb.data.get("best", []) if isinstance(cb, _BestF) else [], dtype=float)


def _single_objective(spec: TrialSpec, problem, record: dict, arrays: dict) -> None:
    from moik.experiments.protocol import solve_until_success

    created: list = []
    factory = _make_algorithm(spec, created)
    termination = ("n_gen", spec.n_gen)
    t0 = time.perf_counter()
    if spec.protocol is not None:
        out = solve_until_success(problem, factory, termination, seed=spec.seed_sequence,
                                  threshold=spec.protocol["threshold"],
                                  max_failures=spec.protocol["max_failures"])
        res, elapsed = out.best, out.total_time
        record.update(attempts=out.attempts, solved=bool(out.solved), run_f=out.run_f,
                      run_seeds=out.seeds)
    else:
        res = minimize(problem, factory(), termination, seed=spec.seed, copy_algorithm=False)
        elapsed = time.perf_counter() - t0
    x = np.asarray(res.X, dtype=float).reshape(-1) if res.X is not None else None
    record.update(time=elapsed, n_eval=int(sum(a.evaluator.n_eval for a in created)),
                  best_f=float(np.min(res.F)) if res.F is not None else float("inf"))
    if x is not None:
        record["best_x"] = x.tolist()
        if hasattr(problem, "errors"):
            pos, ori = problem.errors(x[None])
            record.update(position_error=float(pos[0]), orientation_error=float(ori[0]))
        else:
            record["position_error"] = float(problem.position_error(x[None])[0])
        if problem.q_start is not None:
            record["joint_distance_deg"] = float(np.linalg.norm(np.degrees(x - problem.q_start)))
        arrays["best_x"] = x
    arrays["convergence"] = _convergence(res.algorithm)
    if spec.record_history and hasattr(res.algorithm, "best_x_history"):
        arrays["best_x_history"] = res.algorithm.best_x_history


def _multi_objective(spec: TrialSpec, problem, record: dict, arrays: dict) -> None:
    from moik.algorithms import get_algorithm
    from moik.metrics import closest_to_utopia, hypervolume

    algorithm = get_algorithm(spec.algorithm, **spec.params)
    t0 = time.perf_counter()
    res = minimize(problem, algorithm, ("n_gen", spec.n_gen), seed=spec.seed,
                   copy_algorithm=False)
    elapsed = time.perf_counter() - t0
    F = np.atleast_2d(np.asarray(res.F, dtype=float))
    X = np.atleast_2d(np.asarray(res.X, dtype=float))
    i = closest_to_utopia(F)
    record.update(time=elapsed, n_eval=int(algorithm.evaluator.n_eval), n_front=int(len(F)),
                  position_error=float(F[i, 0]), orientation_error=float(F[i, 1]),
                  min_position_error=float(F[:, 0].min()),
                  min_orientation_error=float(F[:, 1].min()), best_x=X[i].tolist())
    if spec.target.hv_ref_point is not None:
        record["hv"] = hypervolume(F, spec.target.hv_ref_point)
    arrays.update(front_F=F, front_X=X, best_x=X[i])


def run_trial(spec: TrialSpec) -> tuple[dict, dict]:
    """Run one trial; returns ``(record, arrays)``, never raises for algorithm failures.

    The record holds the trial's identity and seeds, ``status`` (``"ok"`` or
    ``"error"`` with ``error``), ``time`` (s), ``n_eval``, and the results:
    ``best_f``/``position_error``/``orientation_error``/``best_x`` (and
    ``attempts``/``solved`` under the protocol, ``joint_distance_deg`` with a
    start configuration) for single-objective problems; the compromise's errors,
    ``n_front`` and ``hv`` for multi-objective ones; for benchmark problems
    see :mod:`moik.experiments.benchmark`. ``arrays`` holds ``convergence`` or
    ``front_F``/``front_X``, and ``best_x``.
    """
    from moik.experiments.benchmark import is_benchmark, run_benchmark_trial

    record = {"trial": spec.trial_id, "algorithm": spec.label, "algorithm_name": spec.algorithm,
              "target": spec.target_index, "target_name": spec.target.name, "run": spec.run,
              "seed": spec.seed, "seed_entropy": spec.entropy, "spawn_key": list(spec.spawn_key),
              "worker": f"{socket.gethostname()}:{os.getpid()}", "status": "ok"}
    arrays: dict = {}
    try:
        if is_benchmark(spec.problem):
            run_benchmark_trial(spec, record, arrays, _make_algorithm, _convergence)
            return record, arrays
        robot = experiment_robot(spec.robot, spec.problem)
        problem = build_problem(robot, spec.problem, spec.target)
        if problem.n_obj == 1:
            _single_objective(spec, problem, record, arrays)
        else:
            _multi_objective(spec, problem, record, arrays)
    except Exception as exc:  # a failing trial is recorded, the experiment goes on
        record.update(status="error", error=f"{type(exc).__name__}: {exc}",
                      traceback=traceback.format_exc(limit=8))
        arrays = {}
    return record, arrays


def spec_summary(spec: TrialSpec) -> dict:
    """The seeds and identity of a trial, for the metadata (no target geometry)."""
    d = asdict(spec)
    return {k: d[k] for k in ("trial_id", "label", "target_index", "run", "seed", "entropy",
                              "spawn_key")}
