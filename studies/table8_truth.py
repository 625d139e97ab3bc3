"""EOSMA Table 8 measured against the reference fronts of P1 and P2.

Run: ``.venv/bin/python -m studies.table8_truth [--results DIR | --runs R] [--write]``
from the repository root (``--write`` regenerates docs/results/table8-truth.md and its
figures).

With ``--results DIR`` (the folder of a finished ``moik experiment run eosma-table8``) it
reads every stored trial's final front; otherwise (results folders are not in git) it
reruns the experiment's own trials (:func:`build_trials`, the same seeds, full budget:
N=100, archive 100, T=1000) for runs ``0 .. R-1`` of every algorithm. Each final front
is measured against the reference front (:mod:`moik.fronts`,
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
from moik.experiments.store import ResultStore
from moik.experiments.trials import build_trials, run_trial
from moik.fronts import dominating_points
from moik.metrics import hypervolume
from moik.plotting._common import LOG_FLOOR
from moik.problems import get_problem

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "results" / "table8-truth.md"
FIGURES = ROOT / "docs" / "results" / "figures" / "table8-truth"
TARGETS = (("P1", "eosma-p1"), ("P2", "eosma-p2"))
TOL = 1e-6


def _stored(folder: Path, skip: list[str]):
    """``(target index, label, run, record, arrays)`` of every finished trial in ``folder``."""
    store = ResultStore.open(folder)
    for rec in store.records():
        if rec["algorithm"] not in skip:
            arrays = store.load_arrays(rec["trial"]) if rec["status"] == "ok" else {}
            yield rec["target"], rec["algorithm"], rec["run"], rec, arrays


def _rerun(runs: int, skip: list[str]):
    """The same tuples from the experiment's trials ``0 .. runs - 1``, run here."""
    cfg = registry.get_experiment("eosma-table8")
    for spec in build_trials(cfg):
        if spec.run < runs and spec.label not in skip:
            record, arrays = run_trial(spec)
            yield spec.target_index, spec.label, spec.run, record, arrays


def measure(runs: int, skip: list[str], results: Path | None = None) -> dict:
    """Per target: the reference front and, per algorithm, its runs' numbers and run-0 front."""
    cfg = registry.get_experiment("eosma-table8")
    trials = list(_stored(results, skip) if results is not None else _rerun(runs, skip))
    out = {}
    for ti, (tname, pname) in enumerate(TARGETS):
        ref_point = np.asarray(cfg.targets[ti].hv_ref_point, dtype=float)
        front = get_problem(pname).pareto_front()
        igd = IGDPlus(front)
        per: dict[str, dict] = {}
        for target, label, run, record, arrays in trials:
            if target != ti:
                continue
            if record["status"] != "ok":
                print(f"{tname} {label} run {run}: {record.get('error')}")
                continue
            F = np.atleast_2d(arrays["front_F"])
            row = per.setdefault(label, {"hv": [], "igd": [], "beat": [], "time": []})
            row["hv"].append(hypervolume(F, ref_point))
            row["igd"].append(float(igd(F)))
            row["beat"].append(len(dominating_points(front, F, TOL)))
            row["time"].append(record["time"])
            if run == 0:
                row["front"] = F
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
                ax.plot(*np.maximum(F[0], LOG_FLOOR), "k*", ms=16, zorder=20,
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
    parser.add_argument("--results", type=Path, help="a finished eosma-table8 results folder")
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    data = measure(args.runs, args.skip, args.results)
    text = "\n".join(tables(data, args.runs))
    print(text)
    if args.write:
        figures(data)
        if args.results is not None:
            meta = ResultStore.open(args.results).meta
            how = (f"--results RESULTS --write` (do not edit by hand): every stored trial of "
                   f"eosma-table8 (config fingerprint {meta['config_fingerprint'][:12]}), read "
                   "from its results folder")
        else:
            how = (f"--runs {args.runs} --write` (do not edit by hand; load average {load:.1f} "
                   f"at the start, 2 cores): runs 0 .. {args.runs - 1} of every algorithm of "
                   "eosma-table8 (the experiment's seeds, full budget), rerun here")
        DOC.write_text(
            "---\nhide: [toc]\n---\n\n"  # wide tables: no table of contents
            "# EOSMA Table 8 against the reference fronts\n\n"
            "Generated by `python -m studies.table8_truth "
            + (f"--skip {' '.join(args.skip)} " if args.skip else "") + how + ". Left out: "
            f"{', '.join(args.skip) or 'none'}. See studies/table8_truth.py.\n\n" + text + "\n")


if __name__ == "__main__":
    main()
