"""Quality of the multi-objective algorithms on pymoo's analytic test problems.

Run: ``.venv/bin/python benchmarks/moo_quality.py [--quick] [--jobs J] [--sections ...]``

Every number in the multi-objective part of docs/algorithms.md and in
docs/results/moo-quality.md comes from this script (``--write`` regenerates both).

Problems: ZDT1/2/3 (30 variables), ZDT4/6 (10), DTLZ1 (7) and DTLZ2 (10, pymoo's
default: k = 8) with three objectives; only problems whose ``pareto_front()`` is
analytic (nothing is downloaded: DTLZ5-7 and the WFG fronts are not). IGD against the
front (ZDT: 1,000 points; DTLZ: 496 Das-Dennis points), hypervolume with the reference
point 1.1 x the front's nadir per objective. "random" is uniform sampling of the same
budget, non-dominated filtered. Algorithms: every multi-objective name of the registry
with its defaults (population 100), MOEOSMA's ``diversity="nsga2-gaussian"`` option,
and the line-by-line ports of the reference codes (``benchmarks/moo_reference.py``).

Sections:

- ``suite``: every algorithm on every problem, 25,000 evaluations (10 seeds) and
  10,000 (5 seeds); IGD and HV, HV as a share of NSGA-II's, Wilcoxon signed-rank
  test of the IGD against NSGA-II's (paired seeds), Friedman mean ranks; the goals.
- ``reference``: moik's implementation and the port of its reference code side by
  side, same problem and budget, 5 seeds (bug or method?).
- ``variants``: options beside the defaults (MOALO's ``antlion="first"``, MALO.m's rule),
  25,000 evaluations, 5 seeds.
- ``small``: the Mirjalili family at its codes' setting (5 variables, 100 iterations,
  N = 100; MSSA.m's N = 200), ZDT1-3, with MO-CSA beside them (scale or bug?).
- ``moeosma``: MOEOSMA as in the paper and with ``diversity="nsga2-gaussian"`` on the
  EOSMA paper's Table 8 poses P1/P2 (N = 100, T = 1000, 5 seeds).
- ``constrained``: BNH, TNK, OSY, SRN, 25,000 evaluations, 5 seeds: the share of
  reported members that are feasible when re-evaluated, HV against NSGA-II's.
"""

from __future__ import annotations

import argparse
import json
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
from moo_quality_report import SECTIONS_DOC, write_reports
from moo_reference import REFERENCES
from pymoo.indicators.igd import IGD
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting
from pymoo.util.ref_dirs import get_reference_directions

from moik.algorithms import MOEOSMA, available, get_algorithm
from moik.metrics import EOSMA_TABLE8_REF_POINTS, hypervolume
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots import get_robot

PROBLEMS = {"zdt1": {}, "zdt2": {}, "zdt3": {}, "zdt4": {}, "zdt6": {},
            "dtlz1": {"n_obj": 3}, "dtlz2": {"n_obj": 3}}
CONSTRAINED = ("bnh", "tnk", "osy", "srn")
OPTION = "moeosma-nsga2-gaussian"
REFERENCE_CASES = [("moeosma", "zdt2"), ("moeosma", "zdt6"), ("mogwo", "dtlz2"),
                   ("mogwo", "zdt2"), ("moalo", "dtlz2"), ("mssa", "dtlz2"), ("mssa", "zdt1"),
                   ("moda", "zdt1"), ("moda", "dtlz2"),
                   ("momvo", "dtlz2"), ("momvo", "zdt1")]
SMALL = {"mssa": 200, "moalo": 100, "moda": 100, "momvo": 100, "mogwo": 100, "mo-csa": 100,
         "nsga2": 100}
TABLE8_POSES = {"P1": (-0.25, 1.00, 0.50), "P2": (0.50, -0.25, 0.75)}


def problem_and_front(name: str, n_var: int | None = None):
    """The pymoo problem and its analytic front (never a downloaded one)."""
    kw = dict(PROBLEMS.get(name, {}))
    if n_var is not None:
        kw["n_var"] = n_var
    problem = get_problem(name, **kw)
    if name.startswith("dtlz"):
        front = problem.pareto_front(get_reference_directions("das-dennis", 3, n_partitions=30))
    else:
        front = problem.pareto_front(1000)
    return problem, front


VARIANTS = {"moalo-first": ("moalo", {"antlion": "first"})}
"""Label -> (registry name, options) of the ``variants`` section."""


def build(name: str, pop_size: int = 100):
    if name == OPTION:
        return MOEOSMA(pop_size=pop_size, diversity="nsga2-gaussian")
    if name in VARIANTS:
        base, options = VARIANTS[name]
        return get_algorithm(base, pop_size=pop_size, **options)
    return get_algorithm(name, pop_size=pop_size)


def random_front(problem, budget: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    X = problem.xl + rng.random((budget, problem.n_var)) * (problem.xu - problem.xl)
    F = problem.evaluate(X, return_values_of=["F"])
    return F[NonDominatedSorting().do(F, only_non_dominated_front=True)]


def scores(F: np.ndarray, front: np.ndarray) -> tuple[float, float]:
    ref = 1.1 * front.max(axis=0)
    inside = F[np.all(ref > F, axis=1)]
    return float(IGD(front).do(F)), hypervolume(inside, ref) if len(inside) else 0.0


def run_task(task: tuple) -> dict:
    """One run: ``(section, algorithm, problem, budget, seed, extra)`` -> its measurements."""
    section, alg, pname, budget, seed, extra = task
    start = time.process_time()
    if section == "moeosma":
        target = Target.from_euler(TABLE8_POSES[pname], (0, 0, 0), convention="eosma-euler",
                                   degrees=True)
        problem = BiObjectiveIK(get_robot("eosma7-m"), target, orientation="eosma-euler")
        res = minimize(problem, build(alg), ("n_eval", budget), seed=seed)
        return {"hv": hypervolume(res.F, EOSMA_TABLE8_REF_POINTS[pname]),
                "min_f1": float(res.F[:, 0].min()), "min_f2": float(res.F[:, 1].min()),
                "cpu": time.process_time() - start}
    if section == "constrained":
        problem = get_problem(pname)
        res = minimize(problem, build(alg), ("n_eval", budget), seed=seed)
        if res.X is None:
            return {"F": [], "feasible": 0, "members": 0}
        F, G = problem.evaluate(np.atleast_2d(res.X), return_values_of=["F", "G"])
        ok = np.all(G <= 0.0, axis=1)
        return {"F": F[ok].tolist(), "feasible": int(ok.sum()), "members": len(ok)}
    problem, front = problem_and_front(pname, extra.get("n_var"))
    if alg == "random":
        F = random_front(problem, budget, seed)
    elif alg.startswith("port:"):
        name = alg[5:]
        N, per = 100, (200 if name == "moeosma" else 100)
        T = (budget - N) // per if name in ("moeosma", "mogwo") else budget // N
        with np.errstate(all="ignore"):
            _, F, _ = REFERENCES[name](problem, N, T, np.random.default_rng(seed))
    else:
        res = minimize(problem, build(alg, extra.get("pop_size", 100)), ("n_eval", budget),
                       seed=seed)
        F = res.F
    igd, hv = scores(F, front)
    return {"igd": igd, "hv": hv, "cpu": time.process_time() - start}


def tasks(section: str, seeds: int, quick: bool) -> list[tuple]:
    mo = available("multi-objective")
    if section == "suite":
        budgets = [(2500, 2)] if quick else [(25_000, seeds), (10_000, max(seeds // 2, 2))]
        return [(section, a, p, b, s, {}) for b, k in budgets for p in PROBLEMS
                for a in [*mo, OPTION, "random"] for s in range(k)]
    if section == "reference":
        budget = 2500 if quick else 25_000
        return [(section, a, p, budget, s, {}) for name, p in REFERENCE_CASES
                for a in (name, f"port:{name}") for s in range(2 if quick else 5)]
    if section == "variants":
        return [(section, a, p, 2500 if quick else 25_000, s, {})
                for label, (base, _) in VARIANTS.items() for a in (label, base)
                for p in ("zdt1", "dtlz2") for s in range(2 if quick else 5)]
    if section == "small":
        return [(section, a, p, 100 * n, s, {"n_var": 5, "pop_size": n})
                for p in ("zdt1", "zdt2", "zdt3") for a, n in SMALL.items()
                for s in range(2 if quick else 5)] + [
            (section, "random", p, 10_000, s, {"n_var": 5}) for p in ("zdt1", "zdt2", "zdt3")
            for s in range(2 if quick else 5)]
    if section == "moeosma":
        budget = 100 + (10 if quick else 1000) * 200
        return [(section, a, p, budget, s, {}) for p in TABLE8_POSES
                for a in ("moeosma", OPTION, "nsga2") for s in range(2 if quick else 5)]
    if section == "constrained":
        return [(section, a, p, 2500 if quick else 25_000, s, {}) for p in CONSTRAINED
                for a in mo for s in range(2 if quick else 5)]
    raise ValueError(section)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="tiny budgets, 2 seeds")
    parser.add_argument("--seeds", type=int, default=10, help="seeds of the 25,000 budget")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--sections", nargs="*", default=list(SECTIONS_DOC))
    parser.add_argument("--cache", type=Path, default=Path("/tmp/moik-moo-quality.json"),
                        help="results of earlier runs (reused; delete to measure afresh)")
    parser.add_argument("--write", action="store_true",
                        help="regenerate docs/results/moo-quality.md and docs/algorithms.md")
    args = parser.parse_args()
    cache = json.loads(args.cache.read_text()) if args.cache.exists() else {}
    todo = [t for s in args.sections for t in tasks(s, args.seeds, args.quick)
            if json.dumps(t) not in cache]
    print(f"{len(todo)} runs to do ({len(cache)} cached in {args.cache})", flush=True)
    with ProcessPoolExecutor(args.jobs) as pool:
        for k, (task, out) in enumerate(zip(todo, pool.map(run_task, todo, chunksize=4),
                                            strict=True)):
            cache[json.dumps(task)] = out
            if k % 50 == 49:
                args.cache.write_text(json.dumps(cache))
                print(f"  {k + 1}/{len(todo)}", flush=True)
    args.cache.write_text(json.dumps(cache))
    results = {s: {t[1:5]: cache[json.dumps(t)] for t in tasks(s, args.seeds, args.quick)}
               for s in args.sections}
    write_reports(results, args.quick, write=args.write)


if __name__ == "__main__":
    main()
