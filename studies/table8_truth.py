"""EOSMA Table 8 measured against the reference fronts of P1 and P2.

Run: ``.venv/bin/python -m studies.table8_truth [--runs R] [--write]`` from the
repository root (``--write`` regenerates docs/results/table8-truth.md and its figures).

The stored 560 trials of eosma-table8 are not in this checkout (results folders are not
in git), so this study reruns the experiment's own trials (:func:`build_trials`, the same
seeds, full budget: N=100, archive 100, T=1000) for runs ``0 .. R-1`` of every algorithm
and measures each final front against the reference front (:mod:`moik.fronts`,
``moik.problems.get_problem("eosma-p1")``): HV with the paper's reference point, that HV
as a share of the reference front's, IGD+ to the reference front (pymoo), and the
points that beat the reference front in both errors by more than 1e-6 of its range
(:func:`moik.fronts.dominating_points`; none expected). The figure
draws every algorithm's run-0 front over the reference front.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import numpy as np
from pymoo.indicators.igd_plus import IGDPlus

from moik.experiments import registry
from moik.experiments.trials import build_trials, run_trial
from moik.fronts import dominating_points
from moik.metrics import hypervolume
from moik.problems import get_problem

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "results" / "table8-truth.md"
FIGURES = ROOT / "docs" / "results" / "figures" / "table8-truth"
TARGETS = (("P1", "eosma-p1"), ("P2", "eosma-p2"))
TOL = 1e-6


def measure(runs: int, skip: list[str]) -> dict:
    """Per target: the reference front and, per algorithm, its runs' numbers and run-0 front."""
    cfg = registry.get_experiment("eosma-table8")
    specs = [s for s in build_trials(cfg) if s.run < runs and s.label not in skip]
    out = {}
    for ti, (tname, pname) in enumerate(TARGETS):
        ref_point = np.asarray(cfg.targets[ti].hv_ref_point, dtype=float)
        front = get_problem(pname).pareto_front()
        igd = IGDPlus(front)
        per: dict[str, dict] = {}
        for spec in (s for s in specs if s.target_index == ti):
            record, arrays = run_trial(spec)
            if record["status"] != "ok":
                print(f"{tname} {spec.label} run {spec.run}: {record.get('error')}")
                continue
            F = np.atleast_2d(arrays["front_F"])
            row = per.setdefault(spec.label, {"hv": [], "igd": [], "beat": [], "time": []})
            row["hv"].append(hypervolume(F, ref_point))
            row["igd"].append(float(igd(F)))
            row["beat"].append(len(dominating_points(front, F, TOL)))
            row["time"].append(record["time"])
            if spec.run == 0:
                row["front"] = F
            print(f"{tname} {spec.label} run {spec.run}: HV {row['hv'][-1]:.5f} IGD+ "
                  f"{row['igd'][-1]:.3g}", flush=True)
        out[tname] = {"front": front, "ref_point": ref_point, "ref_hv":
                      hypervolume(front, ref_point), "per": per}
    return out


def tables(data: dict, runs: int) -> list[str]:
    lines = []
    for tname, d in data.items():
        best = max((max(r["hv"]), a) for a, r in d["per"].items())
        lines += [f"### {tname}", "",
                  f"Reference front: {len(d['front'])} points, HV {d['ref_hv']:.5f} (reference "
                  f"point {d['ref_point'].tolist()}); best run of any algorithm: HV "
                  f"{best[0]:.5f} ({best[1]}), {100 * best[0] / d['ref_hv']:.3f} % of it.", "",
                  f"| algorithm | runs | HV mean | HV share of the reference front | IGD+ mean | "
                  f"IGD+ std | IGD+ min | points beating the front (> {TOL:g} of its range) |",
                  "|---|---|---|---|---|---|---|---|"]
        order = sorted(d["per"].items(), key=lambda kv: np.mean(kv[1]["igd"]))
        for alg, r in order:
            hv, igd = np.array(r["hv"]), np.array(r["igd"])
            lines.append(f"| {alg} | {len(hv)} | {hv.mean():.5f} | "
                         f"{100 * hv.mean() / d['ref_hv']:.3f} % | {igd.mean():.4g} | "
                         f"{igd.std():.3g} | {igd.min():.4g} | {sum(r['beat'])} |")
        lines += ["", f"![Run-0 fronts at {tname} over the reference front]"
                  f"(figures/table8-truth/front-{tname}.png)", ""]
    return lines


def figures(data: dict) -> None:
    """Per target: every run-0 front and the reference front (thick black line), the whole
    range on the left, zoomed on the reference front on the right."""
    import matplotlib.pyplot as plt  # matplotlib only when drawing

    from moik.plotting import plot_pareto_fronts

    FIGURES.mkdir(parents=True, exist_ok=True)
    for tname, d in data.items():
        fronts = {a: r["front"] for a, r in d["per"].items() if "front" in r}
        fig, axes = plt.subplots(1, 2, figsize=(13, 5))
        F = d["front"]
        for ax, zoom in zip(axes, (False, True), strict=True):
            plot_pareto_fronts(fronts, proposed="moeosma", ax=ax, log=tname == "P2",
                               title=f"Run-0 fronts at {tname}" + (", zoomed" if zoom else ""))
            if len(F) > 1:
                ax.plot(F[:, 0], F[:, 1], "-", color="black", lw=3, zorder=20,
                        label="reference front")
                if zoom:
                    ax.set_xlim(-0.02 * F[:, 0].max(), 1.6 * F[:, 0].max())
                    ax.set_ylim(-0.02 * F[:, 1].max(), 1.15 * F[:, 1].max())
            else:
                ax.plot(*np.maximum(F[0], 1e-16), "k*", ms=16, zorder=20,
                        label="reference front (0, 0)")
            if zoom:
                ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=7)
            elif ax.get_legend() is not None:
                ax.get_legend().remove()
        fig.savefig(FIGURES / f"front-{tname}.png", dpi=110, bbox_inches="tight")
        plt.close(fig)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--skip", nargs="*", default=[], help="algorithm labels left out")
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    data = measure(args.runs, args.skip)
    text = "\n".join(tables(data, args.runs))
    print(text)
    if args.write:
        figures(data)
        DOC.write_text(
            "# EOSMA Table 8 against the reference fronts\n\n"
            f"Generated by `python -m studies.table8_truth --runs {args.runs}"
            + (" --skip " + " ".join(args.skip) if args.skip else "") + " --write` (do not "
            f"edit by hand; load average {load:.1f} at the start, 2 cores). Runs 0 .. "
            f"{args.runs - 1} of every algorithm of eosma-table8 (the experiment's seeds, full "
            "budget), rerun here: the stored 560 trials are not in this checkout. Left out: "
            f"{', '.join(args.skip) or 'none'}. See studies/table8_truth.py.\n\n" + text + "\n")


if __name__ == "__main__":
    main()
