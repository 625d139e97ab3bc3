"""Speed and hypervolume of the multi-objective algorithms at the EOSMA paper's Table 8 budget.

Run: ``.venv/bin/python benchmarks/moo.py [--quick] [--seeds K]``

Setting (EOSMA paper, Yin et al. 2022, Table 8, as ``experiments/eosma_table8.toml``
configures it): the ``eosma7-m`` arm, objectives (position error, Eq. 26 Euler
orientation error, ``BiObjectiveIK(orientation="eosma-euler")``), N = 100, T = 1000,
archive 100. MOEOSMA evaluates ``N + T 2N = 200,100`` points in that budget; MO-m-PSO
and pymoo's NSGA2 (pop 100) get the same number of evaluations.

(0) MOEOSMA on P2 alone: the best wall and process-CPU seconds of 7 runs (seeds 0-6),
    goal <= 0.15 s (the paper's MATLAB time: 0.82 s). The generation is compiled
    (:mod:`moik.algorithms.moo.moeosma_kernels`), the archive merge too.
(a) Seconds per run on P2 = (0.50, -0.25, 0.75) m and P1 = (-0.25, 1.00, 0.50) m,
    Euler angles (0, 0, 0), printed side by side with the ratio NSGA2 / algorithm.
    Goals: MOEOSMA >= 5x faster than NSGA2. The paper's MATLAB times: MOEOSMA
    0.82 s (P2), 5.88 s (P1).
(b) Hypervolume with the paper's reference points
    (``moik.metrics.EOSMA_TABLE8_REF_POINTS``), mean and std over the seeds,
    against the paper's MOEOSMA means 5.07631 (P1) and 4.28017 (P2).
(c) ZDT1 (30 variables), 25,000 evaluations, reference (1.1, 1.1): HV of
    MOEOSMA and NSGA2, mean of 5 seeds (the sanity check of the test suite).
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOEOSMA, MOMPSO
from moik.metrics import EOSMA_TABLE8_REF_POINTS, hypervolume
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots import get_robot

POSES = {"P2": (0.50, -0.25, 0.75), "P1": (-0.25, 1.00, 0.50)}
PAPER_HV = {"P1": 5.07631, "P2": 4.28017}
PAPER_TIME = {"P1": 5.87559, "P2": 0.81779}
N, T = 100, 1000
BUDGET = N + T * 2 * N  # MOEOSMA's evaluations at N=100, T=1000, q=1

ALGORITHMS = {
    "MOEOSMA": lambda: MOEOSMA(pop_size=N, archive_size=N),
    "MO-m-PSO": lambda: MOMPSO(pop_size=N, archive_size=N),
    "NSGA2": lambda: NSGA2(pop_size=N),
}


def pose_problem(name: str) -> BiObjectiveIK:
    """The Table 8 problem for pose P1 or P2."""
    target = Target.from_euler(POSES[name], (0, 0, 0), convention="eosma-euler", degrees=True)
    return BiObjectiveIK(get_robot("eosma7-m"), target, orientation="eosma-euler")


def moeosma_p2_time(repeats: int = 7) -> None:
    """(0): MOEOSMA's Table 8 P2 run, best of ``repeats`` seeds, wall and CPU seconds."""
    problem = pose_problem("P2")
    minimize(problem, MOEOSMA(pop_size=N, archive_size=N), ("n_gen", 3), seed=0)  # compile
    wall, cpu = [], []
    for seed in range(repeats):
        w, c = time.perf_counter(), time.process_time()
        res = minimize(problem, MOEOSMA(pop_size=N, archive_size=N), ("n_gen", T + 1), seed=seed)
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
        assert res.algorithm.evaluator.n_eval == BUDGET
    print(f"MOEOSMA P2 (eosma7-m, eosma-euler, N={N}, T={T}, {BUDGET} evaluations): "
          f"best {min(wall):.3f} s wall, {min(cpu):.3f} s CPU, median {np.median(wall):.3f} s "
          f"wall over {repeats} seeds (goal <= 0.15 s; paper {PAPER_TIME['P2']:.2f} s MATLAB)")


def run(make, problem, budget: int, seed: int) -> tuple[float, np.ndarray, int]:
    """Seconds, front and evaluations of one run."""
    start = time.perf_counter()
    res = minimize(problem, make(), ("n_eval", budget), seed=seed)
    return time.perf_counter() - start, res.F, res.algorithm.evaluator.n_eval


def table8(seeds: list[int], budget: int) -> None:
    """(a) and (b): times, ratios and hypervolumes on P1 and P2."""
    print(f"Table 8 setting: eosma7-m, N={N}, archive {N}, {budget} evaluations per run, "
          f"seeds {seeds}")
    for pose in POSES:
        problem, ref = pose_problem(pose), EOSMA_TABLE8_REF_POINTS[pose]
        times, hvs = {}, {}
        for name, make in ALGORITHMS.items():
            runs = [run(make, problem, budget, seed) for seed in seeds]
            assert all(r[2] == budget for r in runs), "evaluation budgets differ"
            times[name] = np.median([r[0] for r in runs])
            hvs[name] = [hypervolume(r[1], ref) for r in runs]
        print(f"\n{pose}  ref {ref}  (paper: MOEOSMA HV {PAPER_HV[pose]}, "
              f"{PAPER_TIME[pose]:.2f} s MATLAB)")
        print(f"  {'algorithm':10s} {'s/run':>8s} {'NSGA2/alg':>10s} {'HV mean':>9s} "
              f"{'HV std':>9s}  HV per seed")
        for name in ALGORITHMS:
            hv = np.array(hvs[name])
            print(f"  {name:10s} {times[name]:8.3f} {times['NSGA2'] / times[name]:9.1f}x "
                  f"{hv.mean():9.5f} {hv.std():9.2e}  {np.round(hv, 5).tolist()}")


def zdt1_check(seeds: list[int]) -> None:
    """(c): the ZDT1 sanity check of the test suite."""
    problem, ref = get_problem("zdt1"), [1.1, 1.1]
    hv = {name: [] for name in ("MOEOSMA", "NSGA2")}
    for seed in seeds:
        hv["MOEOSMA"].append(hypervolume(run(ALGORITHMS["MOEOSMA"], problem, 25_000, seed)[1],
                                         ref))
        hv["NSGA2"].append(hypervolume(run(ALGORITHMS["NSGA2"], problem, 25_000, seed)[1], ref))
    a, b = np.mean(hv["MOEOSMA"]), np.mean(hv["NSGA2"])
    print(f"\nZDT1 (30 vars), 25,000 evaluations, ref (1.1, 1.1), seeds {seeds}: "
          f"HV MOEOSMA {a:.5f}, NSGA2 {b:.5f}, ratio {a / b:.4f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1 seed, 1/10 of the budget")
    parser.add_argument("--seeds", type=int, default=3, help="seeds per pose (default 3)")
    args = parser.parse_args()
    seeds = [0] if args.quick else list(range(args.seeds))
    moeosma_p2_time(2 if args.quick else 7)
    table8(seeds, N + T // 10 * 2 * N if args.quick else BUDGET)
    zdt1_check(seeds if args.quick else list(range(5)))


if __name__ == "__main__":
    main()
