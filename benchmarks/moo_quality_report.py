"""Tables and goals of ``benchmarks/moo_quality.py``: printed, and written into the docs.

``write_reports(results, quick, write=...)`` prints every table; with ``write`` it
writes docs/results/moo-quality.md in full and replaces the part of
docs/algorithms.md between ``<!-- moo-quality:begin -->`` and ``<!-- moo-quality:end -->``.
``results[section][(algorithm, problem, budget, seed)]`` is one run's measurements.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import numpy as np

from moik.algorithms import MOArrayAlgorithm, available, entry
from moik.metrics import friedman_ranks, hypervolume, signed_rank

DOCS = Path(__file__).resolve().parent.parent / "docs"
BEGIN, END = "<!-- moo-quality:begin -->", "<!-- moo-quality:end -->"
SECTIONS_DOC = {
    "suite": "every algorithm on every problem",
    "reference": "moik's implementation beside the port of its reference code",
    "variants": "options beside the defaults",
    "small": "the Mirjalili family at its codes' setting",
    "moeosma": "MOEOSMA and its option on the EOSMA paper's Table 8 poses",
    "constrained": "pymoo's constrained problems",
}
GUIDED = ("moeosma", "mogwo", "moalo", "moda", "momvo", "mssa", "mopso")
"""The archive-guided moik algorithms (leaders drawn from the archive)."""
PAPER_TABLE8 = {"P1": 5.07631, "P2": 4.28017}


def _moik_names() -> list[str]:
    return [n for n in available("multi-objective") if issubclass(entry(n).cls, MOArrayAlgorithm)]


def _by(results: dict, key: str, budget: int | None = None):
    """(algorithm, problem) -> list of values over the seeds (seed order)."""
    out = defaultdict(list)
    for (alg, prob, b, _seed), r in sorted(results.items(), key=lambda kv: kv[0][3]):
        if budget is None or b == budget:
            out[alg, prob].append(r[key])
    return out


def _fmt(x: float) -> str:
    return f"{x:.4f}" if abs(x) < 100 else f"{x:.1f}"


def suite_tables(res: dict, budget: int) -> tuple[list[str], dict]:
    igd, hv = _by(res, "igd", budget), _by(res, "hv", budget)
    problems = sorted({p for _, p in igd}, key=lambda p: (p.rstrip("0123456789"), int(p[-1])))
    algs = sorted({a for a, _ in igd})
    lines, summary = [], {"beats_random": {}, "hv_share": {}, "ranks": {}}
    for prob in problems:
        n_seeds = len(igd["nsga2", prob])
        lines += [f"\n#### {prob.upper()} ({budget:,} evaluations, {n_seeds} seeds)\n",
                  "| algorithm | IGD mean | IGD std | HV mean | HV / NSGA-II | IGD vs NSGA-II "
                  "(Wilcoxon) | beats random |", "|---|---|---|---|---|---|---|"]
        rnd, ref = np.mean(igd["random", prob]), np.mean(hv["nsga2", prob])
        for alg in sorted(algs, key=lambda a: np.mean(igd[a, prob])):
            i, h = np.array(igd[alg, prob]), np.array(hv[alg, prob])
            if alg in ("nsga2", "random"):
                test = "-"
            else:
                sr = signed_rank(i, igd["nsga2", prob])
                test = f"{sr.better(alg, 'nsga2')} better (p={sr.p_value:.3f})".replace(
                    "= better", "no difference")
            share = h.mean() / ref if ref > 0 else float("nan")
            beats = i.mean() < rnd
            summary["beats_random"][alg, prob] = beats
            summary["hv_share"][alg, prob] = share
            shown = f"{share:.1%}" if np.isfinite(share) else "- (NSGA-II HV 0)"
            lines.append(f"| {alg} | {_fmt(i.mean())} | {_fmt(i.std())} | {_fmt(h.mean())} | "
                         f"{shown} | {test} | {'yes' if beats else '**no**'} |")
    ranks = {}
    for prob in problems:
        fr = friedman_ranks({a: igd[a, prob] for a in algs})
        for a in algs:
            ranks.setdefault(a, []).append(fr.mean_ranks[a])
    lines += [f"\n#### Mean ranks ({budget:,} evaluations; Friedman ranks of the IGD per problem, "
              "averaged over the problems; 1 = best)\n",
              "| algorithm | mean rank | " + " | ".join(p.upper() for p in problems) + " |",
              "|---|---|" + "---|" * len(problems)]
    for a in sorted(algs, key=lambda a: np.mean(ranks[a])):
        summary["ranks"][a] = float(np.mean(ranks[a]))
        lines.append(f"| {a} | {np.mean(ranks[a]):.2f} | "
                     + " | ".join(f"{r:.1f}" for r in ranks[a]) + " |")
    return lines, summary


def reference_table(res: dict, suite: dict) -> list[str]:
    igd, hv = _by(res, "igd"), _by(res, "hv")
    rnd = _by(suite, "igd", 25_000) if suite else {}
    lines = ["| algorithm | problem | moik IGD | port IGD | moik HV | port HV | random IGD |"
             " collapsed seeds moik / port |", "|---|---|---|---|---|---|---|---|"]
    for (alg, prob) in sorted({k for k in igd if not k[0].startswith("port:")}):
        port = f"port:{alg}"
        r = np.mean(rnd["random", prob]) if ("random", prob) in rnd else float("nan")
        hm, hp = np.array(hv[alg, prob]), np.array(hv[port, prob])
        collapsed = f"{int((hm < 0.25 * max(hm.max(), hp.max())).sum())} / " \
                    f"{int((hp < 0.25 * max(hm.max(), hp.max())).sum())} of {hm.size}"
        lines.append(f"| {alg} | {prob.upper()} | {_fmt(np.mean(igd[alg, prob]))} | "
                     f"{_fmt(np.mean(igd[port, prob]))} | {_fmt(hm.mean())} | {_fmt(hp.mean())} | "
                     f"{_fmt(r)} | {collapsed} |")
    return lines


def variants_table(res: dict) -> list[str]:
    igd, hv = _by(res, "igd"), _by(res, "hv")
    lines = ["| algorithm | problem | IGD mean | HV mean |", "|---|---|---|---|"]
    for alg, prob in sorted(igd):
        lines.append(f"| {alg} | {prob.upper()} | {_fmt(np.mean(igd[alg, prob]))} | "
                     f"{_fmt(np.mean(hv[alg, prob]))} |")
    return lines


def small_table(res: dict) -> list[str]:
    igd, hv = _by(res, "igd"), _by(res, "hv")
    probs = ("zdt1", "zdt2", "zdt3")
    lines = ["| algorithm (N) | " + " | ".join(f"{p.upper()} HV / NSGA-II" for p in probs)
             + " | " + " | ".join(f"{p.upper()} IGD" for p in probs) + " |",
             "|---|" + "---|" * 6]
    for alg in sorted({a for a, _ in hv}):
        shares = [np.mean(hv[alg, p]) / np.mean(hv["nsga2", p]) for p in probs]
        lines.append(f"| {alg} | " + " | ".join(f"{s:.1%}" for s in shares) + " | "
                     + " | ".join(_fmt(np.mean(igd[alg, p])) for p in probs) + " |")
    return lines


def moeosma_table(res: dict) -> list[str]:
    hv, f1, f2 = _by(res, "hv"), _by(res, "min_f1"), _by(res, "min_f2")
    lines = ["| pose | algorithm | HV mean | HV std | paper (MOEOSMA, 20 runs) | smallest position "
             "error | smallest orientation error |", "|---|---|---|---|---|---|---|"]
    for pose in ("P1", "P2"):
        for alg in ("moeosma", "moeosma-nsga2-gaussian", "nsga2"):
            if (alg, pose) in hv:
                h = np.array(hv[alg, pose])
                lines.append(f"| {pose} | {alg} | {h.mean():.5f} | {h.std():.5f} | "
                             f"{PAPER_TABLE8[pose]:.5f} | {np.mean(f1[alg, pose]):.2e} | "
                             f"{np.mean(f2[alg, pose]):.2e} |")
    return lines


def constrained_table(res: dict) -> tuple[list[str], dict]:
    runs = defaultdict(list)
    for (alg, prob, _, _seed), r in sorted(res.items(), key=lambda kv: kv[0][3]):
        runs[alg, prob].append(r)
    probs = sorted({p for _, p in runs})
    refs = {p: 1.1 * np.max([np.max(np.array(r["F"]), axis=0) for r in runs["nsga2", p]
                             if r["F"]], axis=0) for p in probs}

    def hv(alg, p):
        return np.mean([hypervolume(np.array(r["F"]).reshape(-1, 2)[
            np.all(np.array(r["F"]).reshape(-1, 2) < refs[p], axis=1)], refs[p])
            for r in runs[alg, p]])

    lines = ["| algorithm | " + " | ".join(f"{p.upper()} feasible | {p.upper()} HV / NSGA-II"
                                          for p in probs) + " |", "|---|" + "---|---|" * len(probs)]
    ok = {}
    for alg in sorted({a for a, _ in runs}):
        cells = []
        for p in probs:
            feas = sum(r["feasible"] for r in runs[alg, p])
            members = sum(r["members"] for r in runs[alg, p])
            share = hv(alg, p) / hv("nsga2", p)
            ok[alg, p] = (feas == members and members > 0, share)
            cells.append(f"{feas}/{members} | {share:.1%}")
        lines.append(f"| {alg} | " + " | ".join(cells) + " |")
    return lines, ok


def summary_table(res: dict, summary: dict, budget: int = 25_000) -> list[str]:
    """Compact table for docs/algorithms.md: HV share of NSGA-II and IGD per problem."""
    igd = _by(res, "igd", budget)
    problems = sorted({p for _, p in igd}, key=lambda p: (p.rstrip("0123456789"), int(p[-1])))
    lines = ["| algorithm | mean rank | " + " | ".join(p.upper() for p in problems) + " |",
             "|---|---|" + "---|" * len(problems)]
    for alg in sorted(summary["ranks"], key=summary["ranks"].get):
        cells = []
        for p in problems:
            share = summary["hv_share"].get((alg, p), float("nan"))
            mark = "" if alg == "random" or summary["beats_random"].get((alg, p), True) else " (<)"
            hv_txt = f"{share:.0%}" if np.isfinite(share) else "-"
            cells.append(f"{hv_txt} / {np.mean(igd[alg, p]):.3g}{mark}")
        lines.append(f"| {alg} | {summary['ranks'][alg]:.1f} | " + " | ".join(cells) + " |")
    return lines


def goals(summaries: dict, constrained: dict | None) -> list[str]:
    lines = []
    moik = _moik_names()
    zdt = ("zdt1", "zdt2", "zdt3", "zdt4", "zdt6")
    for budget, s in sorted(summaries.items()):
        br = s["beats_random"]
        fails = [f"{a} on {p.upper()}" for a in moik for p in zdt if not br.get((a, p), True)]
        fails += [f"{a} on DTLZ2" for a in GUIDED if not br.get((a, "dtlz2"), True)]
        lines.append(f"- Every moik MO algorithm beats random search (IGD) on ZDT1/2/3/4/6 at "
                     f"{budget:,} evaluations, the archive-guided ones ({', '.join(GUIDED)}) also "
                     f"on DTLZ2: " + ("**met**" if not fails else "not met for "
                                      + ", ".join(fails)))
    if 25_000 in summaries:
        hs = summaries[25_000]["hv_share"]
        for alg in ("moeosma", "moeosma-nsga2-gaussian"):
            vals = {p: hs.get((alg, p), float("nan")) for p in ("zdt1", "zdt2", "zdt3", "zdt6")}
            met = all(v >= 0.95 for v in vals.values())
            lines.append(f"- {alg} >= 95 % of NSGA-II's HV on ZDT1/2/3/6 (25,000 evaluations): "
                         + ("**met**" if met else "not met") + " ("
                         + ", ".join(f"{p.upper()} {v:.1%}" for p, v in vals.items()) + ")")
    if constrained:
        bad = [f"{a} on {p.upper()} ({'infeasible members' if not f else f'HV {s:.1%}'})"
               for (a, p), (f, s) in sorted(constrained.items())
               if p in ("bnh", "tnk", "osy") and not (f and s >= 0.9)]
        lines.append("- Constrained problems: every MO algorithm returns only feasible members on "
                     "BNH/TNK/OSY with HV within 10 % of NSGA-II's: "
                     + ("**met**" if not bad else "not met for " + ", ".join(bad)))
    return lines


def write_reports(results: dict, quick: bool, *, write: bool) -> None:
    out, summaries, constrained = ["# Multi-objective quality (generated by "
                                   "benchmarks/moo_quality.py)\n"], {}, None
    if "suite" in results:
        for budget in sorted({k[2] for k in results["suite"]}, reverse=True):
            lines, summaries[budget] = suite_tables(results["suite"], budget)
            out += [f"\n## Suite, {budget:,} evaluations"] + lines
    if "reference" in results:
        out += ["\n## Reference codes side by side (25,000 evaluations, 5 seeds; a seed "
                "'collapsed' below a quarter of the best HV)\n"]
        out += reference_table(results["reference"], results.get("suite"))
    if "variants" in results:
        out += ["\n## Options beside the defaults (25,000 evaluations, 5 seeds)\n"]
        out += variants_table(results["variants"])
    if "small" in results:
        out += ["\n## The Mirjalili codes' setting: ZDT1-3 with 5 variables, 100 iterations "
                "(N x 100 evaluations), 5 seeds\n"] + small_table(results["small"])
    if "moeosma" in results:
        out += ["\n## MOEOSMA on the EOSMA paper's Table 8 poses (eosma7-m, eosma-euler, N = 100,"
                " T = 1000, 200,100 evaluations, 5 seeds)\n"] + moeosma_table(results["moeosma"])
    if "constrained" in results:
        lines, constrained = constrained_table(results["constrained"])
        out += ["\n## Constrained problems (25,000 evaluations, 5 seeds; members re-evaluated; "
                "HV reference 1.1 x NSGA-II's nadir)\n"] + lines
    out += ["\n## Goals\n"] + goals(summaries, constrained)
    text = "\n".join(out) + "\n"
    print(text)
    if write and not quick:
        (DOCS / "results" / "moo-quality.md").write_text(text)
        doc = (DOCS / "algorithms.md").read_text()
        if BEGIN in doc and END in doc:
            head, rest = doc.split(BEGIN, 1)
            _, tail = rest.split(END, 1)
            table = (summary_table(results["suite"], summaries[25_000])
                     if 25_000 in summaries else [])
            block = "\n".join([
                "", "Measured by `benchmarks/moo_quality.py` (25,000 evaluations, population "
                "100, 10 seeds; each cell: HV as a share of NSGA-II's / mean IGD, \"(<)\" where "
                "the IGD is worse than uniform random sampling of the same budget; mean rank: "
                "Friedman ranks of the IGD averaged over the problems):", "", *table, "",
                "Goals:", "", *goals(summaries, constrained), "",
                "Every table (10,000 evaluations, Wilcoxon tests against NSGA-II, the reference "
                "codes side by side, the codes' own setting, Table 8, constrained problems): "
                "[results/moo-quality.md](results/moo-quality.md).", ""])
            (DOCS / "algorithms.md").write_text(head + BEGIN + block + END + tail)
