"""Multi-objective quality checks beside the runner's experiments: reference codes, settings.

Run: ``.venv/bin/python -m studies.moo_quality [--quick] [--jobs J] [--sections ...]``

The suite itself (every algorithm on ZDT1-4/6 and DTLZ1-2 at 25,000 and 10,000
evaluations, random search, rank-sum tests, mean ranks) and the constrained problems
(BNH, OSY, SRN, TNK) run on the experiment runner: ``moik experiment run moo-suite``,
``moo-suite-10k``, ``moo-constrained`` (docs/results/moo-suite.md, ...). This script
measures what the runner does not: moik's implementations beside line-by-line ports of
their reference codes (``reference/__init__.py``), the Mirjalili codes' own setting,
and MOEOSMA on the EOSMA paper's Table 8 poses. ``--write`` regenerates
docs/results/moo-quality.md and the block of docs/algorithms.md between
``<!-- moo-quality:begin -->`` and ``<!-- moo-quality:end -->``.

Problems and scores as on the runner (:mod:`moik.experiments.kinds.moo_fronts`): analytic
fronts only (nothing is downloaded), IGD against the front, HV with the reference point
nadir + 0.1 x |nadir| per objective (1.1 x the nadir on ZDT/DTLZ); on constrained
problems the returned members are re-evaluated and only the feasible ones scored.
"random" is uniform sampling of the same budget, (feasible) non-dominated filtered.

Sections:

- ``reference``: moik's implementation and the port of its reference code side by
  side, same problem and budget (25,000 evaluations), 5 seeds, with random search
  (bug or method?);
- ``small``: the Mirjalili family at its codes' setting (5 variables, 100 iterations,
  N = 100; MSSA.m's N = 200), ZDT1-3, with MO-CSA beside them (scale or bug?);
- ``moeosma``: MOEOSMA as in the paper and with ``diversity="nsga2-gaussian"`` on the
  EOSMA paper's Table 8 poses P1/P2 (N = 100, T = 1000, 5 seeds).
"""

from __future__ import annotations

import argparse
import json
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOEOSMA, get_algorithm
from moik.experiments.kinds.moo_fronts import analytic_front
from moik.experiments.kinds.moo_functions import front_scores, random_search, violation
from moik.metrics import EOSMA_TABLE8_REF_POINTS, hypervolume
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots import get_robot
from reference import REFERENCES
from studies.moo_quality_report import CODE_READINGS, SECTIONS_DOC, port_of, write_reports

PROBLEMS = {"dtlz2": {"n_obj": 3}}
"""Problem options (pymoo's defaults otherwise: ZDT1-3 30 variables, DTLZ2 10)."""
OPTION = "moeosma-nsga2-gaussian"
REFERENCE_CASES = [("moeosma", "zdt2"), ("moeosma", "zdt6"), ("mogwo", "dtlz2"),
                   ("mogwo", "zdt2"), ("moalo", "dtlz2"), ("mssa", "dtlz2"), ("mssa", "zdt1"),
                   ("moda", "zdt1"), ("moda", "dtlz2"), ("momvo", "dtlz2"), ("momvo", "zdt1"),
                   ("moalo", "osy"), ("moalo", "tnk"), ("moda", "osy"), ("moda", "tnk"),
                   ("mssa", "osy"), ("momvo", "osy"), ("mogwo", "osy"),
                   ("moda-w-end-0.2", "osy"), ("moda-w-end-0.2", "tnk"), ("mo-csa", "zdt1"),
                   ("mo-csa", "zdt3")]

SMALL = {"mssa": 200, "moalo": 100, "moda": 100, "momvo": 100, "mogwo": 100, "mo-csa": 100,
         "nsga2": 100}
TABLE8_POSES = {"P1": (-0.25, 1.00, 0.50), "P2": (0.50, -0.25, 0.75)}


def problem_and_front(name: str, n_var: int | None = None):
    """The pymoo problem and its analytic front (never a downloaded one)."""
    kw = dict(PROBLEMS.get(name, {}))
    if n_var is not None:
        kw["n_var"] = n_var
    problem = get_problem(name, **kw)
    return problem, analytic_front(problem, name)


def build(name: str, pop_size: int = 100):
    if name == OPTION:
        return MOEOSMA(pop_size=pop_size, diversity="nsga2-gaussian")
    if name in CODE_READINGS:
        base, options = CODE_READINGS[name]
        return get_algorithm(base, pop_size=pop_size, **options)
    return get_algorithm(name, pop_size=pop_size)


def scores(problem, X: np.ndarray, F: np.ndarray, front: np.ndarray) -> tuple[float, float]:
    """IGD and HV of the feasible rows (all rows on an unconstrained problem)."""
    X = np.asarray(X, dtype=float).reshape(-1, problem.n_var)
    F = np.asarray(F, dtype=float).reshape(-1, problem.n_obj)
    return front_scores(F[violation(problem, X) <= 0.0], front)


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
    problem, front = problem_and_front(pname, extra.get("n_var"))
    if alg == "random":
        X, F = random_search(problem, budget, np.random.default_rng(seed))
    elif alg.startswith("port:"):
        name, N, M = alg[5:], 100, problem.n_obj
        # iterations of the budget: (initial evaluations, per iteration) where the code
        # evaluates before its loop; the Mirjalili codes evaluate N at the top of each
        init, per = {"moeosma": (N, 2 * N), "mogwo": (N, N),
                     "mo-csa": (M * N, M * N)}.get(name, (0, N))
        T = (budget - init) // per
        with np.errstate(all="ignore"):
            X, F, _ = REFERENCES[name](problem, N, T, np.random.default_rng(seed))
    else:
        res = minimize(problem, build(alg, extra.get("pop_size", 100)), ("n_eval", budget),
                       seed=seed)
        X, F = res.X, res.F
    igd, hv = scores(problem, X, F, front)
    return {"igd": igd, "hv": hv, "cpu": time.process_time() - start}


def tasks(section: str, quick: bool) -> list[tuple]:
    if section == "reference":
        budget, k = (2500, 2) if quick else (25_000, 5)
        pairs = dict.fromkeys((a, p) for name, p in REFERENCE_CASES
                              for a in (name, port_of(name)))
        cases = [(section, a, p, budget, s, {}) for a, p in pairs for s in range(k)]
        return cases + [(section, "random", p, budget, s, {})
                        for p in dict.fromkeys(p for _, p in REFERENCE_CASES) for s in range(k)]
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
    raise ValueError(section)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="tiny budgets, 2 seeds")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--sections", nargs="*", default=list(SECTIONS_DOC))
    parser.add_argument("--cache", type=Path, default=Path("/tmp/moik-moo-quality.json"),
                        help="results of earlier runs (reused; delete to measure afresh)")
    parser.add_argument("--write", action="store_true",
                        help="regenerate docs/results/moo-quality.md and docs/algorithms.md")
    args = parser.parse_args()
    cache = json.loads(args.cache.read_text()) if args.cache.exists() else {}
    todo = [t for s in args.sections for t in tasks(s, args.quick)
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
    results = {s: {t[1:5]: cache[json.dumps(t)] for t in tasks(s, args.quick)}
               for s in args.sections}
    write_reports(results, args.quick, write=args.write)


if __name__ == "__main__":
    main()
