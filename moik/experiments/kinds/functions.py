"""Benchmark-function experiments: classical and CEC test functions, engineering design problems.

Such an experiment has no robot and no targets; its problem is::

    {"kind": "benchmark", "names": ["F1", {"name": "pressure_vessel",
                                           "label": "vessel-discrete",
                                           "params": {"discrete": True}}, ...],
     "params": {...}}

Each entry of ``names`` is a name of :func:`moik.problems.benchmarks.get_benchmark`
or a dict with that ``name``, an optional display ``label`` and ``params`` (the
problem's keywords); the top-level ``params`` go to every problem that accepts
them (``n_var`` to the scalable functions, not to the fixed-dimension ones).
The problems take the place of the targets: trials are (algorithm x problem x
run), with the same seeds for every algorithm. Validation builds every problem
(except those of an extra, built only when run).

The experiment key ``requires`` lists optional extras (``"cec"``: minionpy for
the CEC2017 functions); a run checks them first and fails with one clear line.

A trial records ``best_f`` (the objective of the best design, or None when that
design violates a constraint: an infeasible best is never reported as a
feasible value), ``objective`` (its objective value in any case), ``cv`` (its
constraint violation, ``sum(max(G, 0))``, 0 for unconstrained problems),
``feasible``, ``f_opt`` and ``error = best_f - f_opt``, ``best_x``, ``time``,
``n_eval``; and the best-so-far curve as the array ``convergence``.
"""

from __future__ import annotations

import inspect
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pymoo.core.problem import Problem
from pymoo.optimize import minimize

from moik.exceptions import ConfigError, MoikError
from moik.experiments.checks import check_keys
from moik.experiments.convergence import algorithm_factory, convergence_curve
from moik.experiments.spec import TrialSpec
from moik.problems.benchmarks import _REGISTRY, available_benchmarks, get_benchmark

PROBLEM_KINDS = ("benchmark",)
EXTRAS = {"cec": ("minionpy", "the CEC2017 functions")}
"""Optional extras an experiment may require: name -> (module, what needs it)."""

_KEYS = {"kind", "names", "params"}
_ENTRY_KEYS = {"name", "label", "params"}


@dataclass(frozen=True)
class BenchmarkTarget:
    """One problem of a benchmark experiment, in the place of a target."""

    name: str
    benchmark: str
    params: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        """JSON-ready form."""
        return {"name": self.name, "benchmark": self.benchmark, "params": dict(self.params)}


def _factory_parameters(name: str) -> set[str]:
    return set(inspect.signature(_REGISTRY[name]).parameters)


def _entry(where: str, raw: Any, common: Mapping) -> dict:
    entry = {"name": raw} if isinstance(raw, str) else dict(
        check_keys(where, raw, _ENTRY_KEYS, ("name",)))
    name = entry["name"]
    if name not in available_benchmarks():
        raise ConfigError(f"{where}: unknown benchmark {name!r}; expected one of: "
                          f"{', '.join(available_benchmarks())}")
    accepted = _factory_parameters(name)
    own = check_keys(f"{where}.params", entry.get("params", {}), accepted)
    params = {k: v for k, v in common.items() if k in accepted} | dict(own)
    label = entry.get("label", name)
    if not isinstance(label, str) or not label:
        raise ConfigError(f"{where}.label must be a non-empty string, got {label!r}")
    return {"name": name, "label": label, "params": params}


def check_config(where: str, cfg: Mapping, folder: Path
                 ) -> tuple[dict, tuple[BenchmarkTarget, ...]]:
    """Validate a benchmark experiment's ``problem`` (and absence of robot/targets).

    Returns:
        The problem dict with every entry of ``names`` in the dict form, and the
        problems as targets.

    Raises:
        ConfigError: For a robot or targets given, an unknown problem name or
            keyword, a bad value (problems are built to check them, except those
            of an extra, built only when run), duplicate labels, unknown extras.
    """
    for key in ("robot", "targets", "protocol"):
        if key in cfg:
            raise ConfigError(f"{where}: problem kind 'benchmark' takes no {key!r} (the "
                              "problems listed in problem.names replace the targets)")
    p = check_keys(f"{where}: problem", cfg["problem"], _KEYS, ("kind", "names"))
    common = check_keys(f"{where}: problem.params", p.get("params", {}),
                        set().union(*(_factory_parameters(n) for n in available_benchmarks())))
    names = p["names"]
    if not isinstance(names, list) or not names:
        raise ConfigError(f"{where}: problem.names must be a non-empty list of benchmark names")
    entries = [_entry(f"{where}: problem.names[{i}]", raw, common) for i, raw in enumerate(names)]
    labels = [e["label"] for e in entries]
    if len(set(labels)) != len(labels):
        raise ConfigError(f"{where}: problem.names: labels must be unique, got {labels}")
    requires = cfg.get("requires", [])
    if not isinstance(requires, list) or any(r not in EXTRAS for r in requires):
        raise ConfigError(f"{where}: requires must be a list of: {', '.join(EXTRAS)}; "
                          f"got {requires!r}")
    for i, e in enumerate(entries):
        if not e["name"].startswith("cec2017_"):
            try:
                build_benchmark(e)
            except MoikError as exc:
                raise ConfigError(f"{where}: problem.names[{i}]: {exc}") from None
        elif "cec" not in requires:
            raise ConfigError(f"{where}: {e['name']} needs requires: ['cec'] (minionpy)")
    problem = {"kind": "benchmark", "names": entries, **({"params": common} if common else {})}
    targets = tuple(BenchmarkTarget(e["label"], e["name"], dict(e["params"])) for e in entries)
    return problem, targets


def build_benchmark(entry: Mapping) -> Problem:
    """The pymoo problem of an entry (``name`` and ``params``)."""
    return get_benchmark(entry["name"] if "name" in entry else entry["benchmark"],
                         **entry.get("params", {}))


def constraint_violation(problem: Problem, x: np.ndarray) -> tuple[float, float]:
    """``(objective, violation)`` of one design, evaluated afresh on ``problem``."""
    if problem.n_ieq_constr or problem.n_eq_constr:
        F, G, H = problem.evaluate(x[None], return_values_of=["F", "G", "H"])
        g = np.zeros(0) if G is None else np.maximum(np.asarray(G, dtype=float).ravel(), 0.0)
        h = np.zeros(0) if H is None else np.abs(np.asarray(H, dtype=float).ravel())
        cv = float(np.sum(g) + np.sum(h))
        return float(np.asarray(F).ravel()[0]), (cv if np.isfinite(cv) else float("inf"))
    F = problem.evaluate(x[None], return_values_of=["F"])
    return float(np.asarray(F).ravel()[0]), 0.0


def run_trial(spec: TrialSpec, record: dict, arrays: dict) -> None:
    """Run one (algorithm, problem, run) trial; fills ``record`` and ``arrays``."""
    problem = build_benchmark(spec.target.as_dict())
    created: list = []
    algorithm = algorithm_factory(spec, created)()
    algorithm.return_least_infeasible = True  # so res.X exists; feasibility is checked below
    t0 = time.perf_counter()
    res = minimize(problem, algorithm, ("n_gen", spec.iterations + 1), seed=spec.seed,
                   copy_algorithm=False)
    elapsed = time.perf_counter() - t0
    record.update(time=elapsed, n_eval=int(algorithm.evaluator.n_eval),
                  f_opt=float(getattr(problem, "f_opt", np.nan)))
    if res.X is None:
        record.update(best_f=None, objective=None, cv=None, feasible=False)
    else:
        x = np.asarray(res.X, dtype=float).reshape(-1)
        f, cv = constraint_violation(problem, x)
        feasible = cv <= 0.0
        record.update(best_f=f if feasible else None, objective=f, cv=cv, feasible=feasible,
                      error=(f - record["f_opt"]) if feasible else None, best_x=x.tolist())
        arrays["best_x"] = x
    arrays["convergence"] = convergence_curve(res.algorithm)
