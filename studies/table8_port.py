"""EOSMA Table 8 fidelity: the MOEOSMA.m port beside moik's MOEOSMA at P1 and P2.

Run: ``.venv/bin/python -m studies.table8_port [--seeds N] [--iterations T] [--write]``
from the repository root (``--write`` regenerates docs/results/table8-port.md).

moik's runs are eosma-table8's own ``moeosma`` trials (:func:`build_trials`: the seeds
of runs ``0 .. N-1``, N=100, archive 100, T iterations), run by the experiment's trial
function; the port (:func:`reference.eosma.moeosma_reference`, the line-by-line port of
the authors' MOEOSMA.m) runs on the same problem, N=100, archive 100, T iterations, with
``numpy.random.default_rng`` of the same trial seed (the two use their random numbers
differently, so run j of one is not run j of the other). Hypervolume with the paper's
reference points; the reference front's HV (:mod:`moik.fronts`) is the attainable one.
For P2 every moik run that misses the box volume is listed with the point of its front
nearest to the origin.
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import numpy as np

from moik.experiments import registry
from moik.experiments.kinds.ik import build_problem, experiment_robot
from moik.experiments.trials import build_trials, run_trial
from moik.metrics import hypervolume
from moik.problems import get_problem
from reference.eosma import moeosma_reference

DOC = Path(__file__).resolve().parents[1] / "docs" / "results" / "table8-port.md"
PAPER = {"P1": (5.07631, 0.02007), "P2": (4.28017, 3.17e-13)}
REGISTERED = {"P1": "eosma-p1", "P2": "eosma-p2"}


def _stats(v) -> str:
    v = np.asarray(v, dtype=float)
    return f"{v.mean():.5f} | {v.std():.3g} | {v.min():.5f} | {v.max():.5f}"


def run(seeds: int, iterations: int) -> tuple[list[str], dict]:
    """The markdown lines of the report and the raw numbers."""
    cfg = registry.get_experiment("eosma-table8")
    specs = [s for s in build_trials(cfg) if s.label == "moeosma" and s.run < seeds]
    lines, raw = [], {}
    for ti, tname in enumerate(("P1", "P2")):
        ref = np.asarray(cfg.targets[ti].hv_ref_point, dtype=float)
        moik_hv, port_hv, moik_t, port_t, misses = [], [], [], [], []
        for spec in (s for s in specs if s.target_index == ti):
            spec = spec.__class__(**{**spec.__dict__, "iterations": iterations})
            record, arrays = run_trial(spec)
            moik_hv.append(record["hv"])
            moik_t.append(record["time"])
            problem = build_problem(experiment_robot(spec.robot, spec.problem),
                                    spec.problem, spec.target)
            t0 = time.perf_counter()
            _, AF, _ = moeosma_reference(problem, 100, iterations,
                                         np.random.default_rng(spec.seed), capacity=100)
            port_t.append(time.perf_counter() - t0)
            port_hv.append(hypervolume(AF, ref))
            if tname == "P2" and record["hv"] < PAPER["P2"][0] - 1e-5:
                misses.append((spec.run, spec.seed, record))
            print(f"{tname} run {spec.run}: moik {moik_hv[-1]:.5f} ({moik_t[-1]:.2f} s), "
                  f"port {port_hv[-1]:.5f} ({port_t[-1]:.1f} s)", flush=True)
        front = get_problem(REGISTERED[tname]).pareto_front()
        ref_hv = hypervolume(front, ref)
        raw[tname] = {"moik": moik_hv, "port": port_hv, "reference": ref_hv, "misses": misses}
        lines += [f"### {tname} ({len(moik_hv)} seeds, N=100, archive 100, T={iterations})", "",
                  "| source | HV mean | HV std | HV min | HV max | time per run (s) |",
                  "|---|---|---|---|---|---|",
                  f"| moik MOEOSMA | {_stats(moik_hv)} | {np.mean(moik_t):.2f} |",
                  f"| MOEOSMA.m port (reference/eosma.py) | {_stats(port_hv)} | "
                  f"{np.mean(port_t):.1f} |",
                  f"| paper, Table 8 (20 runs) | {PAPER[tname][0]} | {PAPER[tname][1]:.3g} | - | "
                  "- | - |",
                  f"| reference front (moik.fronts, `{REGISTERED[tname]}`) | {ref_hv:.5f} | - | - "
                  "| - | - |", ""]
        if tname == "P2":
            lines += [f"moik runs below {PAPER['P2'][0]} - 1e-5: {len(misses)} of "
                      f"{len(moik_hv)}", ""]
            if misses:
                lines += ["| run | seed | HV | least position error | least orientation error "
                          "| front size |", "|---|---|---|---|---|---|"]
                lines += [f"| {r} | {s} | {rec['hv']:.5f} | {rec['min_position_error']:.3g} | "
                          f"{rec['min_orientation_error']:.3g} | {rec['n_front']} |"
                          for r, s, rec in misses]
                lines.append("")
    return lines, raw


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--iterations", type=int, default=1000)
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    lines, _ = run(args.seeds, args.iterations)
    text = "\n".join(lines)
    print(text)
    if args.write:
        DOC.write_text(
            "---\nhide: [toc]\n---\n\n"  # wide tables: no table of contents
            "# EOSMA Table 8: the MOEOSMA.m port beside moik's MOEOSMA\n\n"
            f"Generated by `python -m studies.table8_port --seeds {args.seeds} --iterations "
            f"{args.iterations} --write` (do not edit by hand; load average {load:.1f} at the "
            "start, 2 cores). See the module docstring of studies/table8_port.py for what "
            "runs.\n\n" + text + "\n")


if __name__ == "__main__":
    main()
