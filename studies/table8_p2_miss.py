"""Which of eosma-table8's 20 moik MOEOSMA runs at P2 miss the exact pose, and why.

Run: ``.venv/bin/python -m studies.table8_p2_miss [--write]`` from the repository root
(``--write`` regenerates docs/results/table8-p2-miss.md).

P2 is reachable: a run that finds the pose has a front point at (0, 0) to rounding and
the HV of the whole reference box, 4.28017. This study reruns the experiment's 20
``moeosma`` trials at P2 (:func:`build_trials`: the experiment's seeds, N=100, archive
100, T=1000) and, for each run below the box volume, records: the archive's least
position and orientation errors every 100 iterations (does the archive lose points it
had?), the joints of its final members that sit within 0.01 rad of a limit, and the best
pose error a local solver reaches from each final member (:func:`moik.fronts.scalarised.
solve_sum`, SLSQP on ``f1^2 / reach^2 + f2^2`` within the limits): when no member's
basin contains the pose, the population has converged to a local front.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from pymoo.optimize import minimize

from moik.algorithms import get_algorithm
from moik.experiments import registry
from moik.experiments.kinds.ik import build_problem, experiment_robot
from moik.experiments.trials import build_trials
from moik.fronts.scalarised import ErrorModel, solve_sum
from moik.metrics import hypervolume

DOC = Path(__file__).resolve().parents[1] / "docs" / "results" / "table8-p2-miss.md"
BOX = 4.28017
CHECKPOINTS = (1, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1000)


def _run(spec):
    problem = build_problem(experiment_robot(spec.robot, spec.problem), spec.problem,
                            spec.target)
    history: dict[int, np.ndarray] = {}

    def callback(algorithm):
        it = algorithm.n_gen - 1
        if it in CHECKPOINTS and algorithm.opt is not None:
            history[it] = algorithm.opt.get("F").min(axis=0)

    res = minimize(problem, get_algorithm(spec.algorithm, **spec.params),
                   ("n_gen", spec.iterations + 1), seed=spec.seed, callback=callback,
                   copy_algorithm=False)
    return problem, res, history


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args(argv)
    cfg = registry.get_experiment("eosma-table8")
    ref = np.asarray(cfg.targets[1].hv_ref_point, dtype=float)
    specs = [s for s in build_trials(cfg) if s.label == "moeosma" and s.target_index == 1]
    lines = ["| run | seed | HV | front size | least position error | least orientation error |",
             "|---|---|---|---|---|---|"]
    misses = []
    for spec in specs:
        problem, res, history = _run(spec)
        F = np.atleast_2d(res.F)
        hv = hypervolume(F, ref)
        lines.append(f"| {spec.run} | {spec.seed} | {hv:.6f} | {len(F)} | {F[:, 0].min():.3g} | "
                     f"{F[:, 1].min():.3g} |")
        print(lines[-1], flush=True)
        if hv < BOX - 1e-5:
            misses.append((spec, problem, res, history))
    hvs = [float(row.split("|")[3]) for row in lines[2:]]
    text = [f"HV over the 20 runs: mean {np.mean(hvs):.5f}, std (ddof=1) "
            f"{np.std(hvs, ddof=1):.4g}; runs below {BOX} - 1e-5: {len(misses)}", "",
            *lines, ""]
    for spec, problem, res, history in misses:
        robot = problem.robot
        X = np.atleast_2d(res.X)
        near = [j + 1 for j in range(robot.dof)
                if np.all(np.minimum(X[:, j] - robot.lower[j], robot.upper[j] - X[:, j]) < 0.01)]
        model = ErrorModel(robot, problem.target.position, problem.target.rotation,
                           problem.orientation)
        local = np.array([solve_sum(model, x).errors for x in X])
        best = local[np.argmin(local.max(axis=1))]
        text += [f"### Run {spec.run} (seed {spec.seed})", "",
                 "Archive's least errors by iteration (a rise means the archive dropped its "
                 "best member):", "", "| iteration | least position error | least orientation "
                 "error |", "|---|---|---|"]
        text += [f"| {it} | {v[0]:.3g} | {v[1]:.3g} |" for it, v in sorted(history.items())]
        text += ["", f"- joints at a limit (within 0.01 rad) in every final member: {near} "
                 f"(limits lower {np.round(robot.lower, 3).tolist()}, upper "
                 f"{np.round(robot.upper, 3).tolist()})",
                 f"- final members' joint ranges: min {np.round(X.min(axis=0), 3).tolist()}, "
                 f"max {np.round(X.max(axis=0), 3).tolist()}",
                 f"- local solver (SLSQP on f1^2/reach^2 + f2^2 within the limits) from each of "
                 f"the {len(X)} final members: best pose errors reached ({best[0]:.3g}, "
                 f"{best[1]:.3g}); "
                 + ("the pose is in none of their basins: the population converged to a local "
                    "front bounded by the joint limits" if best.max() > 1e-6 else
                    "the pose is in a member's basin: the run stopped short of it"), ""]
    out = "\n".join(text)
    print(out)
    if args.write:
        DOC.write_text("---\nhide: [toc]\n---\n\n"  # wide tables: no table of contents
                       "# EOSMA Table 8, P2: the moik MOEOSMA runs that miss the exact pose\n\n"
                       "Generated by `python -m studies.table8_p2_miss --write` (do not edit by "
                       "hand); see studies/table8_p2_miss.py for what runs.\n\n" + out + "\n")


if __name__ == "__main__":
    main()
