"""Multi-objective benchmark experiments: problems with analytic fronts (ZDT, DTLZ, BNH, OSY ...).

Such an experiment has no robot and no targets; its problem is::

    {"kind": "moo-benchmark",
     "names": ["zdt1", {"name": "zdt4", "label": "zdt4", "params": {"n_var": 10}},
               {"name": "dtlz2", "params": {"n_obj": 3}}, ...],
     "evaluations": 25000}

Each entry of ``names`` is a problem of :data:`ANALYTIC_FRONTS` (pymoo's
``get_problem`` name) or a dict with that ``name``, an optional display
``label`` and ``params`` (``n_var``; ``n_obj`` for DTLZ, 2 or 3; none for the
constrained BNH, OSY, SRN, TNK and for the bi-objective IK problems of
:func:`moik.problems.available`, e.g. ``eosma-p1``, whose fronts are moik's reference
fronts). Trials are (algorithm x problem x run), with
the same seeds for every algorithm.

Budget: with ``evaluations`` every algorithm runs until that many evaluations
(pymoo's ``("n_eval", evaluations)``; an algorithm may finish the generation it
is in; the config's ``iterations`` are then unused); without it, the config's
``iterations`` (update iterations after the initial population, pymoo's
``("n_gen", iterations + 1)``), as for the other kinds.

Only problems whose Pareto front is analytic are accepted (pymoo downloads
some fronts at run time; nothing here touches the network): the fronts are
those of :mod:`moik.experiments.kinds.moo_fronts`.

Baselines beside the registry's algorithms (:data:`BASELINES`):
``random-search`` samples the same budget uniformly in the box (the
``evaluations``, or without them ``pop_size x (iterations + 1)``, the budget of
an algorithm that evaluates its population once per iteration) with the
trial's seed and keeps the non-dominated points (constrained problems: the
feasible non-dominated ones).

Every returned member is re-evaluated for its constraints: ``n_front`` counts
the feasible members, ``n_infeasible`` the infeasible ones reported (0 for a
correct algorithm), and ``igd``, ``hv`` score the feasible members only (no
feasible member: IGD inf, HV 0). A trial records ``igd`` (pymoo's IGD of the
feasible members against the analytic front), ``hv``
(:func:`moik.metrics.hypervolume` with the reference point
:func:`~moik.experiments.kinds.moo_fronts.hv_reference`: the front's nadir plus
a tenth of its magnitude per objective; points outside that box add nothing),
``n_front``, ``n_infeasible``, ``time``, ``n_eval``; the arrays ``front_F`` and
``front_X`` (every returned member).
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pymoo.core.problem import Problem
from pymoo.indicators.igd import IGD
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik import _validate
from moik.algorithms import get_algorithm
from moik.algorithms.archive import constrained_nondominated_mask
from moik.algorithms.mechanics import constraint_violation
from moik.exceptions import ConfigError
from moik.experiments.checks import check_keys, integer
from moik.experiments.kinds.moo_fronts import (
    ANALYTIC_FRONTS,
    CONSTRAINED,
    IK_FRONTS,
    analytic_front,
    hv_reference,
)
from moik.experiments.spec import TrialSpec
from moik.metrics import hypervolume
from moik.problems import get_problem as get_ik_problem

PROBLEM_KINDS = ("moo-benchmark",)
MULTI_OBJECTIVE = PROBLEM_KINDS
"""The problem kinds of this module whose algorithms are multi-objective."""

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
    """The pymoo problem ``name`` with ``params`` (``n_var``, ``n_obj``), or the IK problem
    ``name`` of :func:`moik.problems.get_problem` (no params)."""
    if name in IK_FRONTS:
        return get_ik_problem(name)
    return get_problem(name, **dict(params))


def front_scores(F: np.ndarray, front: np.ndarray) -> tuple[float, float]:
    """``(IGD, HV)`` of the front ``F`` against the analytic ``front``; no rows: (inf, 0)."""
    F = np.asarray(F, dtype=float).reshape(-1, front.shape[1])
    if not len(F):
        return float("inf"), 0.0
    return float(IGD(front).do(F)), hypervolume(F, hv_reference(front))


def _violation(problem: Problem, G, H, n: int) -> np.ndarray:
    """pymoo's default total violation of ``n`` rows from their ``G``, ``H`` (0 if feasible):
    :func:`moik.algorithms.mechanics.constraint_violation`, the algorithms' own rule."""
    if problem.n_ieq_constr + problem.n_eq_constr == 0 or not n:
        return np.zeros(n)
    cv = constraint_violation(None if G is None else np.reshape(G, (n, -1)),
                              None if H is None else np.reshape(H, (n, -1)))
    return np.broadcast_to(cv, (n,)).astype(float)


def violation(problem: Problem, X: np.ndarray) -> np.ndarray:
    """Total constraint violation of the rows of ``X`` (re-evaluated), 0 if feasible."""
    X = np.asarray(X, dtype=float).reshape(-1, problem.n_var)
    if problem.n_ieq_constr + problem.n_eq_constr == 0 or not len(X):
        return np.zeros(len(X))
    G, H = problem.evaluate(X, return_values_of=["G", "H"])
    return _violation(problem, G, H, len(X))


def random_search(problem: Problem, budget: int, rng: np.random.Generator
                  ) -> tuple[np.ndarray, np.ndarray]:
    """``budget`` uniform samples of the box, non-dominated filtered: ``(X, F)``.

    Constrained problems: constraint-domination, as the archives
    (:func:`moik.algorithms.archive.constrained_nondominated_mask`): the feasible
    samples compete; with none feasible, those of the smallest violation.
    """
    X = problem.xl + rng.random((budget, problem.n_var)) * (problem.xu - problem.xl)
    F, G, H = problem.evaluate(X, return_values_of=["F", "G", "H"])
    F = np.asarray(F, dtype=float)
    keep = constrained_nondominated_mask(F, _violation(problem, G, H, len(X)))
    return X[keep], F[keep]


def _entry(where: str, raw: Any) -> dict:
    entry = {"name": raw} if isinstance(raw, str) else dict(
        check_keys(where, raw, _ENTRY_KEYS, ("name",)))
    name = entry["name"]
    if name not in ANALYTIC_FRONTS:
        raise ConfigError(f"{where}: unknown problem {name!r}; expected one with an analytic "
                          f"front: {', '.join(ANALYTIC_FRONTS)}")
    dtlz = name.startswith("dtlz")
    fixed = name in CONSTRAINED or name in IK_FRONTS
    allowed = {"n_var", "n_obj"} if dtlz else set() if fixed else {"n_var"}
    params = dict(check_keys(f"{where}.params", entry.get("params", {}), allowed))
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


def check_config(where: str, cfg: Mapping, folder: Path
                 ) -> tuple[dict, tuple[MooTarget, ...]]:
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
        empty = res.X is None  # pymoo: nothing to report
        X = np.zeros((0, problem.n_var)) if empty else np.asarray(res.X, dtype=float)
        F = np.zeros((0, problem.n_obj)) if empty else np.asarray(res.F, dtype=float)
        X, F = X.reshape(-1, problem.n_var), F.reshape(-1, problem.n_obj)
        n_eval = int(algorithm.evaluator.n_eval)
    elapsed = time.perf_counter() - t0
    feasible = violation(problem, X) <= 0.0
    igd, hv = front_scores(F[feasible], front)
    record.update(time=elapsed, n_eval=n_eval, n_front=int(feasible.sum()),
                  n_infeasible=int((~feasible).sum()), igd=igd, hv=hv,
                  hv_ref_point=hv_reference(front).tolist())
    arrays.update(front_F=F, front_X=X)
