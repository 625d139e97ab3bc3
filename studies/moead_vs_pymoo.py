"""moik's MOEA/D against pymoo's: equal quality by rank-sum on ZDT1-3 and DTLZ2.

Run: ``.venv/bin/python -m studies.moead_vs_pymoo [--seeds 10] [--budget 10000]``.

moik's :class:`~moik.algorithms.moo.moead.MOEAD` (registry ``moead``) and pymoo's
(``moead-pymoo``, :class:`~moik.algorithms.moo.moead_pymoo.PymooMOEAD`), both with their
defaults except that pymoo's is given the Tchebycheff decomposition on DTLZ2 too (pymoo
picks PBI for three objectives; moik's MOEA/D is Tchebycheff only), so the two differ
only in the implementation (moik: one batch per generation, see its module doc). Same
seeds 0..n-1 for both; hypervolume of ``res.F`` (reference point 1.1 per objective);
two-sided Wilcoxon rank-sum test (``scipy.stats.ranksums``) of the per-seed values.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from pymoo.decomposition.tchebicheff import Tchebicheff
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from scipy.stats import ranksums

from moik.algorithms import get_algorithm
from moik.metrics import hypervolume

PROBLEMS = {"zdt1": {}, "zdt2": {}, "zdt3": {}, "dtlz2": {"n_obj": 3}}


def run(name: str, problem: str, seed: int, budget: int) -> tuple[float, float]:
    """Hypervolume of one run's ``res.F`` and its seconds."""
    p = get_problem(problem, **PROBLEMS[problem])
    algorithm = get_algorithm(name) if name == "moead" else \
        get_algorithm(name, decomposition=Tchebicheff())
    start = time.perf_counter()
    res = minimize(p, algorithm, ("n_eval", budget), seed=seed)
    return hypervolume(res.F, np.full(p.n_obj, 1.1)), time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--budget", type=int, default=10_000)
    args = parser.parse_args()
    print(f"| problem | moead HV (mean +- std) | moead-pymoo HV | rank-sum p | "
          f"s per run (moik / pymoo) |  ({args.seeds} seeds, {args.budget} evaluations)")
    print("|---|---|---|---|---|")
    for problem in PROBLEMS:
        runs = {n: [run(n, problem, s, args.budget) for s in range(args.seeds)]
                for n in ("moead", "moead-pymoo")}
        hv = {n: np.array([h for h, _ in r]) for n, r in runs.items()}
        sec = {n: np.median([t for _, t in r]) for n, r in runs.items()}
        p = ranksums(hv["moead"], hv["moead-pymoo"]).pvalue
        print(f"| {problem.upper()} | {hv['moead'].mean():.4f} +- {hv['moead'].std():.4f} | "
              f"{hv['moead-pymoo'].mean():.4f} +- {hv['moead-pymoo'].std():.4f} | {p:.3f} | "
              f"{sec['moead']:.2f} / {sec['moead-pymoo']:.2f} |", flush=True)


if __name__ == "__main__":
    main()
