"""Constrained multi-objective problems: the method, the archive or the feasibility search?

Run: ``.venv/bin/python -m studies.constrained_moo [--algorithms ...] [--problems ...]
[--seeds 1 2] [--write]`` (``--write`` regenerates docs/results/constrained-moo.md from the
printed tables).

pymoo's NSGA-II returns feasible points on MW1, MW2, MW3 and CTP1-CTP3 (50,000 evaluations,
population 100; its row is printed first). For every moik multi-objective algorithm, the
same runs three ways:

- ``archive only``: moik's constraint handling without the feasibility search
  (feasibility first everywhere, Deb's rules; while nothing is feasible the archive keeps
  the ``capacity`` least infeasible rows, as NSGA-II's constrained survival fills its
  population), the search switched off by replacing
  :func:`moik.algorithms.moo.feasibility_search.start_search` where the algorithms call it;
- ``moik``: the same with the feasibility search
  (:mod:`moik.algorithms.moo.feasibility_search`: while nothing feasible was found, a
  companion DE population minimises the violation and offers its trials to the archive);
- ``objectives only`` (run where ``archive only`` misses the feasible region in some run):
  the same objectives without the constraints (the method as its authors coded it: their
  reference codes have no constraint handling), and whether the returned front lies in the
  constrained problem's feasible region at all.

A run "returns feasible points" when ``res.X`` is not None (pymoo's ``Result``: moik reports
only feasible members). Where ``objectives only`` never reaches the feasible region, the
method does not converge far enough on that problem within the budget, with or without
constraint handling (MW1-MW3: the feasible region is a narrow band along the front, reached
only when the 14 distance variables converge); where it does and ``archive only`` fails,
the failure was the handling.
"""

from __future__ import annotations

import argparse
import contextlib
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

import moik.algorithms.moo.base as mo_base
import moik.algorithms.moo.mopso_cd as mopso_cd
from moik.algorithms import get_algorithm

ALGORITHMS = ["nsga2", "moeosma", "mo-m-pso", "mssa", "moalo", "moda", "momvo", "mogwo", "mosma",
              "mopso", "mompa", "mo-pso", "mo-jaya", "mo-csa", "moead", "mopso-cd"]
PROBLEMS = ["mw1", "mw2", "mw3", "ctp1", "ctp2", "ctp3"]
BUDGET, POP_SIZE = 50_000, 100
OUT = Path(__file__).resolve().parents[1] / "docs" / "results" / "constrained-moo.md"


class ObjectivesOnly(Problem):
    """A constrained problem's objectives, without its constraints."""

    def __init__(self, problem: Problem) -> None:
        super().__init__(n_var=problem.n_var, n_obj=problem.n_obj, xl=problem.xl,
                         xu=problem.xu)
        self.constrained = problem

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = self.constrained.evaluate(X, return_values_of=["F"])


@contextlib.contextmanager
def archive_only() -> Iterator[None]:
    """Inside the block, no algorithm starts the feasibility search (module doc)."""
    originals = mo_base.start_search, mopso_cd.start_search
    mo_base.start_search = mopso_cd.start_search = lambda *args: None  # type: ignore
    try:
        yield
    finally:
        mo_base.start_search, mopso_cd.start_search = originals


def _run(problem: Problem, name: str, seed: int):
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return minimize(problem, get_algorithm(name, pop_size=POP_SIZE), ("n_eval", BUDGET),
                        seed=seed)


def _max_violation(problem: Problem, X) -> np.ndarray:
    G = problem.evaluate(np.atleast_2d(X), return_values_of=["G"])
    return np.max(np.asarray(G, dtype=float).reshape(len(np.atleast_2d(X)), -1), axis=1)


def measure(name: str, problem_name: str, seeds) -> dict:
    """Feasible runs of the three variants (module doc) and the smallest violation that
    ``objectives only`` reached with its returned front."""
    problem = get_problem(problem_name)
    row = {"archive": 0, "moik": 0, "objectives": 0, "objectives_min_g": np.inf}
    for seed in seeds:
        row["moik"] += _run(problem, name, seed).X is not None
        if name == "nsga2":
            continue
        with archive_only():
            row["archive"] += _run(problem, name, seed).X is not None
    if name != "nsga2" and row["archive"] < len(seeds):  # where the archive alone fails
        for seed in seeds:
            free = _run(ObjectivesOnly(problem), name, seed)
            g = _max_violation(problem, free.X)
            row["objectives"] += bool(np.any(g <= 0.0))
            row["objectives_min_g"] = min(row["objectives_min_g"], float(np.min(g)))
    return row


def verdict(rows: dict, n_runs: int) -> str:
    """Whose the infeasible output is, per problem of one algorithm (module doc)."""
    parts = []
    for p, r in rows.items():
        if r["archive"] == n_runs and r["moik"] == n_runs:
            continue
        if r["objectives"] == 0:
            cause = "method: its front misses the feasible region with the constraints ignored too"
        else:
            cause = (f"handling: the objectives-only front reaches the feasible region in "
                     f"{r['objectives']} of {n_runs}")
        reached = ("the feasibility search reaches it in every run" if r["moik"] == n_runs
                   else f"feasible in {r['moik']} of {n_runs} with the feasibility search")
        parts.append(f"{p}: {cause}; {reached}")
    return "; ".join(parts) or "feasible in every run without the feasibility search"


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--algorithms", nargs="+", default=ALGORITHMS,
                        help="nsga2 is the reference row (about 25 s a run)")
    parser.add_argument("--problems", nargs="+", default=PROBLEMS)
    parser.add_argument("--seeds", nargs="+", type=int, default=[1, 2])
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args(argv)
    n = len(args.seeds)
    lines = [f"Runs returning feasible points, of {n} (seeds {', '.join(map(str, args.seeds))}; "
             f"{BUDGET:,} evaluations, population {POP_SIZE}): archive only / moik (with the "
             f"feasibility search) / objectives only (its front inside the feasible region; "
             f"run only where the archive alone misses it), smallest max(G) of the "
             f"objectives-only fronts in brackets. pymoo's NSGA-II: moik's column. Front "
             f"quality on MW1-MW3: the moo-constrained-mw experiment.", "",
             "| algorithm | " + " | ".join(args.problems) + " | verdict |",
             "|---|" + "---|" * len(args.problems) + "---|"]
    print("\n".join(lines), flush=True)
    for name in args.algorithms:
        rows = {p: measure(name, p, args.seeds) for p in args.problems}
        if name == "nsga2":
            cells = [f"- / {r['moik']} / -" for r in rows.values()]
            text = "pymoo's, the reference"
        else:
            cells = [f"{r['archive']} / {r['moik']} / " + (
                f"{r['objectives']} ({r['objectives_min_g']:.2g})"
                if np.isfinite(r["objectives_min_g"]) else "-") for r in rows.values()]
            text = verdict(rows, n)
        line = f"| {name} | " + " | ".join(cells) + f" | {text} |"
        print(line, flush=True)
        lines.append(line)
    if args.write:
        header = ["# Constrained multi-objective problems: method, archive or feasibility search",
                  "", "Generated by `python -m studies.constrained_moo --write` (do not edit "
                  "by hand); what the variants are: the study's module docstring.", ""]
        OUT.write_text("---\nhide: [toc]\n---\n\n"  # wide tables: no table of contents
                       + "\n".join(header + lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
