"""MOEA/D on constrained problems: which ideal point the decomposition of feasible points uses.

Run: ``.venv/bin/python -m studies.moead_constraints [--problems osy tnk] [--seeds 3] [--write]``
(``--write`` regenerates docs/results/moead-constraints.md from the printed table).

moik's :class:`~moik.algorithms.moo.moead_pymoo.PymooMOEAD` decomposes feasible points from the
best feasible value per objective seen so far (``feasible_ideal``). ``all-points``
below is the earlier rule, pymoo's ideal point of every evaluated point, infeasible
ones included (a subclass that restores it); ``normalized`` additionally scales each
objective by the feasible population's range before the Tchebycheff decomposition
(Zhang & Li 2007 discuss such a normalization for disparately scaled objectives; it is
not in pymoo's MOEA/D and not an option of moik's). Budget 25,000 evaluations,
population 100; the share of reported members that are feasible when re-evaluated;
HV of the feasible ones with the reference point of the ``moo-constrained`` experiment
(the analytic front's nadir + 0.1 x its magnitude), as a share of NSGA-II's.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import get_algorithm
from moik.algorithms.moo.moead_pymoo import PymooMOEAD
from moik.experiments.kinds.moo_fronts import analytic_front, hv_reference
from moik.metrics import hypervolume


class AllPointsIdeal(PymooMOEAD):
    """The earlier rule: feasible points decomposed from pymoo's ideal of every point."""

    def _replace(self, k, off) -> None:
        pop, N = self.pop, self.neighbors[k]
        FV = self.decomposition.do(pop[N].get("F"), weights=self.ref_dirs[N, :],
                                   ideal_point=self.ideal)
        off_FV = self.decomposition.do(off.F[None, :], weights=self.ref_dirs[N, :],
                                       ideal_point=self.ideal)
        CV, off_CV = pop[N].get("CV")[:, 0], float(off.CV[0])
        better = np.where(CV <= 0.0, (off_CV <= 0.0) & (off_FV < FV),
                          (off_CV <= 0.0) | (off_CV < CV))
        pop[N[np.flatnonzero(better)]] = off


class Normalized(PymooMOEAD):
    """Feasible ideal, objectives scaled by the feasible population's range."""

    def _replace(self, k, off) -> None:
        pop, N = self.pop, self.neighbors[k]
        CV, off_CV = pop[N].get("CV")[:, 0], float(off.CV[0])
        if off_CV > 0.0:
            better = (CV > 0.0) & (off_CV < CV)
        else:
            self.feasible_ideal = np.minimum(self.feasible_ideal, off.F)
            z = self.feasible_ideal
            feasible = pop.get("F")[pop.get("CV")[:, 0] <= 0.0]
            nadir = np.max(np.vstack([feasible, off.F[None, :]]), axis=0)
            scale = np.where(nadir - z > 1e-12, nadir - z, 1.0)
            zero = np.zeros(len(z))
            FV = self.decomposition.do((pop[N].get("F") - z) / scale,
                                       weights=self.ref_dirs[N, :], ideal_point=zero)
            off_FV = self.decomposition.do(((off.F - z) / scale)[None, :],
                                           weights=self.ref_dirs[N, :], ideal_point=zero)
            better = np.where(CV <= 0.0, off_FV < FV, True)
        pop[N[np.flatnonzero(better)]] = off


VARIANTS = {"nsga2": lambda: get_algorithm("nsga2", pop_size=100),
            "moead": lambda: PymooMOEAD(pop_size=100),
            "all-points": lambda: AllPointsIdeal(pop_size=100),
            "normalized": lambda: Normalized(pop_size=100)}


def feasible_front(name: str, make, seed: int, budget: int) -> tuple[np.ndarray, int]:
    """Feasible members of the reported set (re-evaluated), and how many were reported."""
    problem = get_problem(name)
    res = minimize(problem, make(), ("n_eval", budget), seed=seed)
    if res.X is None:
        return np.zeros((0, problem.n_obj)), 0
    F, G = problem.evaluate(np.atleast_2d(res.X), return_values_of=["F", "G"])
    ok = np.all(G <= 0.0, axis=1)
    return F[ok], len(ok)


DOC = Path(__file__).resolve().parents[1] / "docs" / "results" / "moead-constraints.md"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--problems", nargs="*", default=["osy"])
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--budget", type=int, default=25_000)
    parser.add_argument("--write", action="store_true", help=f"write {DOC.name}")
    args = parser.parse_args()
    lines = [f"| problem | variant | feasible / reported | HV / NSGA-II ({args.seeds} seeds, "
             f"{args.budget} evaluations) |", "|---|---|---|---|"]
    print("\n".join(lines), flush=True)
    for name in args.problems:
        runs = {v: [feasible_front(name, make, s, args.budget) for s in range(args.seeds)]
                for v, make in VARIANTS.items()}
        ref = hv_reference(analytic_front(get_problem(name), name))
        base = np.mean([hypervolume(F, ref) for F, _ in runs["nsga2"]])
        for v, rs in runs.items():
            hv = np.mean([hypervolume(F, ref) for F, _ in rs])
            lines.append(f"| {name.upper()} | {v} | {sum(len(F) for F, _ in rs)} / "
                         f"{sum(n for _, n in rs)} | {100 * hv / base:.1f}% |")
            print(lines[-1], flush=True)
    if args.write:
        intro = " ".join(__doc__.split("\n\n")[2].split())
        DOC.write_text("---\nhide: [toc]\n---\n\n"  # wide tables: no table of contents
                       "# MOEA/D on constrained problems (generated by "
                       "studies/moead_constraints.py)\n\n" + intro + "\n\n"
                       + "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
