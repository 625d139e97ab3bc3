"""Multi-objective benchmark-function experiments: ZDT and DTLZ problems with analytic fronts.

Such an experiment has no robot and no targets; its problem is::

    {"kind": "moo-benchmark",
     "names": ["zdt1", {"name": "zdt4", "label": "zdt4", "params": {"n_var": 10}},
               {"name": "dtlz2", "params": {"n_obj": 3}}, ...],
     "evaluations": 25000}

Each entry of ``names`` is a problem of :data:`ANALYTIC_FRONTS` (pymoo's
``get_problem`` name) or a dict with that ``name``, an optional display
``label`` and ``params`` (``n_var``; ``n_obj`` for DTLZ, 2 or 3). Trials are
(algorithm x problem x run), with the same seeds for every algorithm.

Budget: with ``evaluations`` every algorithm runs until that many evaluations
(pymoo's ``("n_eval", evaluations)``; an algorithm may finish the generation it
is in; the config's ``iterations`` are then unused); without it, the config's
``iterations`` (update iterations after the initial population, pymoo's
``("n_gen", iterations + 1)``), as for the other kinds.

Only problems whose Pareto front is analytic are accepted: pymoo's
``pareto_front()`` downloads some fronts (DTLZ7's with three objectives, the
WFG ones) at run time, and nothing here touches the network. The fronts
(:func:`analytic_front`): ZDT, :data:`ZDT_FRONT_POINTS` points of pymoo's
closed-form front; DTLZ1-4, pymoo's closed-form front at Das-Dennis reference
directions (:data:`DTLZ_PARTITIONS` partitions per objective count: 496 points
with three objectives).

Baselines beside the registry's algorithms (:data:`BASELINES`):
``random-search`` samples the same budget uniformly in the box (the
``evaluations``, or without them ``pop_size x (iterations + 1)``, the budget of
an algorithm that evaluates its population once per iteration) with the
trial's seed and keeps the non-dominated points.

A trial records ``igd`` (pymoo's IGD of the returned front against the analytic
one), ``hv`` (:func:`moik.metrics.hypervolume` with the reference point
:func:`hv_reference`: 1.1 x the analytic front's nadir per objective; points
outside that box add nothing), ``n_front``, ``time``, ``n_eval``; the arrays
``front_F`` and ``front_X``.
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from pymoo.core.problem import Problem
from pymoo.indicators.igd import IGD
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting
from pymoo.util.ref_dirs import get_reference_directions

from moik import _validate
from moik.algorithms import get_algorithm
from moik.exceptions import ConfigError
from moik.experiments.checks import check_keys, integer
from moik.experiments.spec import TrialSpec
from moik.metrics import hypervolume

PROBLEM_KINDS = ("moo-benchmark",)
MULTI_OBJECTIVE = PROBLEM_KINDS
"""The problem kinds of this module whose algorithms are multi-objective."""

ANALYTIC_FRONTS = ("zdt1", "zdt2", "zdt3", "zdt4", "zdt6", "dtlz1", "dtlz2", "dtlz3", "dtlz4")
"""pymoo problems whose ``_calc_pareto_front`` is closed-form (never downloaded)."""

ZDT_FRONT_POINTS = 1000
"""Points of a ZDT front (pymoo's ``pareto_front(n)``)."""

DTLZ_PARTITIONS = {2: 999, 3: 30}
"""Das-Dennis partitions of the DTLZ fronts per objective count (1000 and 496 points)."""

HV_FACTOR = 1.1
"""The HV reference point is this factor times the analytic front's nadir, per objective."""

BASELINES = {"random-search": ("pop_size",)}
"""Baseline name -> the keywords it takes (run here, not through the registry)."""

_KEYS = {"kind", "names", "evaluations"}
_ENTRY_KEYS = {"name", "label", "params"}


@dataclass(frozen=True)
class MooTarget:
    """One problem of a multi-objective benchmark experiment, in the place of a target."""

    name: str
    benchmark: str
    params: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        """JSON-ready form."""
        return {"name": self.name, "benchmark": self.benchmark, "params": dict(self.params)}


def build_problem(name: str, params: Mapping) -> Problem:
    """The pymoo problem ``name`` with ``params`` (``n_var``, ``n_obj``)."""
    return get_problem(name, **dict(params))


def analytic_front(problem: Problem, name: str) -> np.ndarray:
    """The closed-form Pareto front of the problem ``name`` (see the module docstring)."""
    if name.startswith("dtlz"):
        dirs = get_reference_directions("das-dennis", problem.n_obj,
                                        n_partitions=DTLZ_PARTITIONS[problem.n_obj])
        return np.asarray(problem.pareto_front(dirs), dtype=float)
    return np.asarray(problem.pareto_front(ZDT_FRONT_POINTS), dtype=float)


def hv_reference(front: np.ndarray) -> np.ndarray:
    """The HV reference point: :data:`HV_FACTOR` x the front's nadir, per objective."""
    return HV_FACTOR * np.max(front, axis=0)


def front_scores(F: np.ndarray, front: np.ndarray) -> tuple[float, float]:
    """``(IGD, HV)`` of the front ``F`` against the analytic ``front``."""
    F = np.atleast_2d(np.asarray(F, dtype=float))
    return float(IGD(front).do(F)), hypervolume(F, hv_reference(front))


def random_search(problem: Problem, budget: int, rng: np.random.Generator
                  ) -> tuple[np.ndarray, np.ndarray]:
    """``budget`` uniform samples of the box, non-dominated filtered: ``(X, F)``."""
    X = problem.xl + rng.random((budget, problem.n_var)) * (problem.xu - problem.xl)
    F = np.asarray(problem.evaluate(X, return_values_of=["F"]), dtype=float)
    keep = NonDominatedSorting().do(F, only_non_dominated_front=True)
    return X[keep], F[keep]


def _entry(where: str, raw: Any) -> dict:
    entry = {"name": raw} if isinstance(raw, str) else dict(
        check_keys(where, raw, _ENTRY_KEYS, ("name",)))
    name = entry["name"]
    if name not in ANALYTIC_FRONTS:
        raise ConfigError(f"{where}: unknown problem {name!r}; expected one with an analytic "
                          f"front: {', '.join(ANALYTIC_FRONTS)}")
    dtlz = name.startswith("dtlz")
    params = dict(check_keys(f"{where}.params", entry.get("params", {}),
                             {"n_var", "n_obj"} if dtlz else {"n_var"}))
    n_obj = params.get("n_obj", 3) if dtlz else 2
    if dtlz:
        _validate.integer(f"{where}.params.n_obj", n_obj, minimum=2, maximum=3,
                          error=ConfigError)
    if "n_var" in params:
        integer(f"{where}.params.n_var", params["n_var"], n_obj if dtlz else 2)
    label = entry.get("label", name)
    if not isinstance(label, str) or not label:
        raise ConfigError(f"{where}.label must be a non-empty string, got {label!r}")
    return {"name": name, "label": label, "params": params}


def check_config(where: str, cfg: Mapping) -> tuple[dict, tuple[MooTarget, ...]]:
    """Validate a multi-objective benchmark experiment's ``problem``.

    Returns:
        The problem dict with every entry of ``names`` in the dict form, and the
        problems as targets.

    Raises:
        ConfigError: For a robot, targets, protocol or requires given, an unknown
            problem or keyword, a bad value, duplicate labels.
    """
    for key in ("robot", "targets", "protocol", "requires"):
        if key in cfg:
            raise ConfigError(f"{where}: problem kind 'moo-benchmark' takes no {key!r} (the "
                              "problems listed in problem.names replace the targets)")
    p = check_keys(f"{where}: problem", cfg["problem"], _KEYS, ("kind", "names"))
    names = p["names"]
    if not isinstance(names, list) or not names:
        raise ConfigError(f"{where}: problem.names must be a non-empty list of problem names")
    entries = [_entry(f"{where}: problem.names[{i}]", raw) for i, raw in enumerate(names)]
    labels = [e["label"] for e in entries]
    if len(set(labels)) != len(labels):
        raise ConfigError(f"{where}: problem.names: labels must be unique, got {labels}")
    problem: dict[str, Any] = {"kind": "moo-benchmark", "names": entries}
    if "evaluations" in p:
        problem["evaluations"] = integer(f"{where}: problem.evaluations", p["evaluations"], 1)
    for e in entries:
        build_problem(e["name"], e["params"])
    targets = tuple(MooTarget(e["label"], e["name"], dict(e["params"])) for e in entries)
    return problem, targets


def _budget(spec: TrialSpec) -> int:
    """Evaluations of the random-search baseline (see the module docstring)."""
    return spec.problem.get("evaluations") or spec.params["pop_size"] * (spec.iterations + 1)


def run_trial(spec: TrialSpec, record: dict, arrays: dict) -> None:
    """Run one (algorithm, problem, run) trial; fills ``record`` and ``arrays``."""
    target = spec.target
    assert isinstance(target, MooTarget)  # this kind's targets
    problem = build_problem(target.benchmark, target.params)
    front = analytic_front(problem, target.benchmark)
    t0 = time.perf_counter()
    if spec.algorithm in BASELINES:
        X, F = random_search(problem, _budget(spec), np.random.default_rng(spec.seed_sequence))
        n_eval = _budget(spec)
    else:
        algorithm = get_algorithm(spec.algorithm, **spec.params)
        evaluations = spec.problem.get("evaluations")
        termination = (("n_eval", evaluations) if evaluations
                       else ("n_gen", spec.iterations + 1))  # initialization is generation 1
        res = minimize(problem, algorithm, termination, seed=spec.seed, copy_algorithm=False)
        X = np.atleast_2d(np.asarray(res.X, dtype=float))
        F = np.atleast_2d(np.asarray(res.F, dtype=float))
        n_eval = int(algorithm.evaluator.n_eval)
    elapsed = time.perf_counter() - t0
    igd, hv = front_scores(F, front)
    record.update(time=elapsed, n_eval=n_eval, n_front=int(len(F)), igd=igd, hv=hv,
                  hv_ref_point=hv_reference(front).tolist())
    arrays.update(front_F=F, front_X=X)
