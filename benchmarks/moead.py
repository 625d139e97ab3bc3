"""Cost per evaluation of moik's MOEA/D beside pymoo's on the EOSMA paper's Table 8 problem.

Run: ``.venv/bin/python benchmarks/moead.py [--repeats 3] [--evals 20000]``

Setting (``experiments/eosma_table8.toml``): the ``eosma7-m`` arm, objectives (position
error, Eq. 26 Euler orientation error), poses P1 = (-0.25, 1.00, 0.50) m and
P2 = (0.50, -0.25, 0.75) m with Euler angles (0, 0, 0); N = 100 (Das-Dennis, two
objectives: 100 directions), archive 100. Runs of ``--evals`` evaluations, moik's and
pymoo's interleaved (seeds 0..repeats-1, after one warm-up run of each), process CPU
seconds per run divided by the evaluations (CPU time: the machine may be shared), medians.
Goal: moik's <= 10 us per evaluation (issue 26; pymoo's was measured at ~300 us).
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from pymoo.optimize import minimize

from moik.algorithms import get_algorithm
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots import get_robot

POSES = {"P1": (-0.25, 1.00, 0.50), "P2": (0.50, -0.25, 0.75)}
NAMES = ("moead", "moead-pymoo")


def pose_problem(name: str) -> BiObjectiveIK:
    """The Table 8 problem for pose P1 or P2."""
    target = Target.from_euler(POSES[name], (0, 0, 0), convention="eosma-euler", degrees=True)
    return BiObjectiveIK(get_robot("eosma7-m"), target, orientation="eosma-euler")


def us_per_eval(name: str, problem, evals: int, seed: int) -> float:
    algorithm = get_algorithm(name, pop_size=100, **({"archive_size": 100}
                                                     if name == "moead" else {}))
    start = time.process_time()
    res = minimize(problem, algorithm, ("n_eval", evals), seed=seed)
    elapsed = time.process_time() - start
    return 1e6 * elapsed / res.algorithm.evaluator.n_eval


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--evals", type=int, default=20_000)
    args = parser.parse_args()
    print(f"| pose | moead us/eval | moead-pymoo us/eval | pymoo / moik |  (medians of "
          f"{args.repeats} runs of {args.evals} evaluations)")
    print("|---|---|---|---|")
    for pose in POSES:
        problem = pose_problem(pose)
        for name in NAMES:  # warm-up (compilation, caches)
            us_per_eval(name, problem, 1000, 0)
        times: dict[str, list[float]] = {n: [] for n in NAMES}
        for seed in range(args.repeats):
            for name in NAMES:
                times[name].append(us_per_eval(name, problem, args.evals, seed))
        ours, theirs = (float(np.median(times[n])) for n in NAMES)
        print(f"| {pose} | {ours:.2f} | {theirs:.1f} | {theirs / ours:.0f}x |", flush=True)


if __name__ == "__main__":
    main()
