"""Tables computed from a results folder, with the paper's numbers side by side.

One function per analysis name of :data:`moik.experiments.config.ANALYSES`
(the per-target ones in :mod:`moik.experiments.per_target`, the front-quality
ones of multi-objective benchmark problems in
:mod:`moik.experiments.front_quality`); each returns
:class:`~moik.experiments.tables.Table` objects that
:mod:`moik.experiments.report` prints as Markdown. Paper rows come from the
config's ``paper`` dict (keys ``summary``, ``hv``, ``joint_motion``,
``compromise``, ``signed_rank``) and are marked with its ``citation``. Only
trials with ``status="ok"`` enter a table; failed ones are counted in a note.
"""

from __future__ import annotations

import math

import numpy as np

from moik.experiments.collision_report import FUNCTIONS as COLLISION_FUNCTIONS
from moik.experiments.consistency import FUNCTIONS as CONSISTENCY_FUNCTIONS
from moik.experiments.consistency import smallest_p_values
from moik.experiments.dh_fit import FUNCTIONS as DH_FIT_FUNCTIONS
from moik.experiments.front_quality import FUNCTIONS as FRONT_FUNCTIONS
from moik.experiments.front_shares import FUNCTIONS as SHARES_FUNCTIONS
from moik.experiments.per_target import FUNCTIONS
from moik.experiments.reference_fronts import FUNCTIONS as REFERENCE_FUNCTIONS
from moik.experiments.solution_sets import FUNCTIONS as RANK_FUNCTIONS
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results, Table, fmt
from moik.metrics import (
    friedman_ranks,
    hypervolume,
    ranksum_pvalues,
    reference_point,
    signed_rank,
    success_rate,
    summarize,
)


def _paper(res: Results, key: str) -> dict:
    return res.paper.get(key, {})


def summary_table(res: Results) -> list[Table]:
    """Worst/mean/best/std/median/time/success per algorithm (EOSMA Tables 5, 7)."""
    thr = res.config.get("success_threshold", 1e-6)
    protocol = res.config.get("protocol") is not None
    header = ["algorithm", "source", "worst", "mean", "best", "std", "median", "time (s)",
              f"success (f < {thr:g})"] + (["runs per target"] if protocol else [])
    rows, paper = [], _paper(res, "summary")
    labels = res.scalar_labels()
    if not labels:
        return []  # multi-objective trials: no final objective value to summarise
    for label in labels:
        f = np.nan_to_num(res.values(label, "best_f"), posinf=np.finfo(float).max)
        with np.errstate(over="ignore"):  # a trial without a value counts as the largest
            s = summarize(f, res.values(label, "time"))
        row = [label, res.source, fmt(s.worst), fmt(s.mean), fmt(s.best), fmt(s.std), fmt(s.median),
               fmt(s.time), f"{100 * success_rate(f, thr):.0f}%"]
        if protocol:
            row.append(fmt(float(np.mean(res.values(label, "attempts")))))
        rows.append(row)
        if label in paper:
            p = paper[label]
            rows.append([label, res.citation] + [fmt(p.get(k)) for k in
                         ("worst", "mean", "best", "std", "median", "time")] + ["-"]
                        + (["-"] if protocol else []))
    n_values = {len(res.by_label[lab]) for lab in labels}
    return [Table("Final objective value over all targets and runs", header, rows,
                  [f"values per algorithm: {', '.join(map(str, sorted(n_values)))}"])]


def ranksum_table(res: Results) -> list[Table]:
    """Wilcoxon rank-sum p-values of the proposed algorithm vs each (EOSMA Figs. 11, 16)."""
    proposed = res.config["proposed"]
    if proposed not in res.labels or len(res.labels) < 2:
        return []
    samples = {lab: np.nan_to_num(res.values(lab, "best_f"), posinf=np.finfo(float).max)
               for lab in res.labels}
    p = ranksum_pvalues(samples, proposed)
    rows = []
    for lab, pv in p.items():
        a, b = np.median(samples[proposed]), np.median(samples[lab])
        verdict = "=" if pv >= 0.05 or a == b else (proposed if a < b else lab)
        rows.append([f"{proposed} vs {lab}", fmt(pv, 3), verdict])
    return [Table(f"Wilcoxon rank-sum test of {proposed} vs each algorithm (two-sided)",
                  ["pair", "p-value", "better (alpha 0.05, by median)"], rows)]


def front_hv(res: Results) -> dict[tuple[str, int], dict[str, np.ndarray]]:
    """HV of every (target, algorithm) run: ``{(target_name, ti): {label: hv per run}}``."""
    out = {}
    targets = res.meta["targets"]
    for ti, target in enumerate(targets):
        fronts = {lab: [(r["run"], res.store.load_arrays(r["trial"]).get("front_F"))
                        for r in res.by_label[lab] if r["target"] == ti] for lab in res.labels}
        if target.get("hv_ref_point") is not None:
            ref = np.asarray(target["hv_ref_point"], dtype=float)
        else:
            ref = reference_point([F for runs in fronts.values() for _, F in runs
                                   if F is not None])
        out[(target["name"], ti)] = {lab: np.array([hypervolume(F, ref) for _, F in sorted(
            runs, key=lambda x: x[0]) if F is not None]) for lab, runs in fronts.items()}
        out[(target["name"], ti)]["__ref__"] = ref
    return out


def friedman_hv_table(res: Results) -> list[Table]:
    """HV mean/std, Friedman mean rank, time and uncovered box share per target (EOSMA Table 8).

    The reference box is ``[0, ref]`` (the objectives are non-negative errors): its
    volume less the HV is what the front leaves uncovered, given also as a share of it.
    """
    tables, paper = [], _paper(res, "hv")
    for (name, ti), hv in front_hv(res).items():
        ref = hv.pop("__ref__")
        box = float(np.prod(ref))

        def uncovered(mean, box=box):
            return [fmt(box - mean, 4), f"{100 * (box - mean) / box:.2f} %"] if box > 0 and \
                mean is not None else ["-", "-"]

        labels = [lab for lab in res.labels if hv[lab].size]
        n_common = min((hv[lab].size for lab in labels), default=0)
        fr = friedman_ranks({lab: hv[lab][:n_common] for lab in labels},
                            higher_is_better=True) if len(labels) >= 2 and n_common else None
        rows = []
        for lab in labels:
            times = [r["time"] for r in res.by_label[lab] if r["target"] == ti]
            sizes = [r["n_front"] for r in res.by_label[lab] if r["target"] == ti]
            rank = (f"{fr.mean_ranks[lab]:.2f} ({fr.order[lab]})" if fr else "-")
            rows.append([lab, res.source, fmt(float(hv[lab].mean()), 6),
                         fmt(float(np.std(hv[lab], ddof=1)) if hv[lab].size > 1 else 0.0, 3),
                         rank, fmt(float(np.mean(times))), fmt(float(np.mean(sizes))),
                         *uncovered(float(hv[lab].mean()))])
            p = paper.get(name, {}).get(lab)
            if p:
                rows.append([lab, res.citation, fmt(p.get("mean"), 6), fmt(p.get("std"), 3),
                             f"{p['fr']:.2f} ({p.get('rank', '-')})" if "fr" in p else "-",
                             fmt(p.get("time")),
                             "-", *uncovered(p.get("mean"))])
        notes = [f"reference point {np.round(ref, 6).tolist()}; runs per algorithm: {n_common}",
                 f"uncovered: volume of the reference box [0, ref] ({fmt(box, 5)}) less the mean "
                 "HV, and its share of the box"]
        if fr is not None and np.isfinite(fr.p_value):
            notes.append(f"Friedman test p-value: {fr.p_value:.3g}")
        tables.append(Table(f"Hypervolume at {name}", ["algorithm", "source", "HV mean", "HV std",
                                                       "Friedman rank", "time (s)",
                                                       "front size", "uncovered (box - HV)",
                                                       "uncovered share"], rows, notes))
    return tables


def joint_motion_table(res: Results) -> list[Table]:
    """Best solution per algorithm, its joint angles and distance (EOSMA Table 9)."""
    q0 = res.config["problem"].get("q_start_deg")
    paper = _paper(res, "joint_motion")
    rows, dof = [], len(q0) if q0 else 0
    for lab in res.labels:
        recs = [r for r in res.by_label[lab] if r.get("best_x") is not None]
        if not recs:
            continue
        best = min(recs, key=lambda r: r["best_f"])
        q = np.degrees(best["best_x"])
        dist = [r["joint_distance_deg"] for r in recs]
        rows.append([lab, res.source] + [f"{v:.6f}" for v in q] + [
            fmt(best.get("joint_distance_deg"), 7), fmt(best["best_f"], 3),
            f"{np.mean(dist):.4g} +- {np.std(dist):.2g}"])
        p = paper.get(lab)
        if p:
            rows.append([lab, res.citation] + [f"{v:g}" for v in p["q_deg"]]
                        + [fmt(p.get("distance"), 7), "-", "-"])
    header = (["algorithm", "source"] + [f"q{i + 1} (deg)" for i in range(dof)]
              + ["distance (deg)", "objective", "distance over runs (mean +- std)"])
    return [Table(f"Best solution from the start {q0} deg (lowest objective over runs)",
                  header, rows)]


def compromise_table(res: Results) -> list[Table]:
    """Position/orientation errors of the selected solutions (MO-m-PSO Tables 2-4)."""
    paper = _paper(res, "compromise")
    rows = []
    for lab in res.labels:
        for key, name in (("position_error", "position"), ("orientation_error", "orientation")):
            v = res.values(lab, key)
            if not np.all(np.isfinite(v)):
                continue
            s = summarize(v)
            rows.append([lab, name, res.source, fmt(s.best), fmt(s.worst), fmt(s.mean), fmt(s.std),
                         fmt(s.median)])
            p = paper.get(lab, {}).get(name)
            if p:
                rows.append([lab, name, res.citation] + [fmt(p.get(k)) for k in
                                                         ("best", "worst", "mean", "std",
                                                          "median")])
    return [Table("Errors of the selected solution (compromise closest to the utopia point)",
                  ["algorithm", "error", "source", "best", "worst", "mean", "std", "median"],
                  rows, ["orientation error in the metric of the problem "
                         f"({res.config['problem'].get('orientation')}), rad"])]


def signed_rank_table(res: Results) -> list[Table]:
    """Wilcoxon signed-rank R+, R-, p and the rank-sum p of the proposed vs each (MO-m-PSO Table 5).

    The paper's R+/R- are signed-rank sums while its p-values are rank-sum ones
    (3.01e-11 is below the smallest signed-rank p of 30 pairs): both tests are
    printed, the paper's p under the test whose range it fits (a note says which).
    """
    proposed = res.config["proposed"]
    key = "best_f" if res.config["problem"]["kind"] != "bi-objective" else "position_error"
    paper = _paper(res, "signed_rank")
    rows, papers = [], []
    if proposed not in res.labels:
        return []
    base = {(r["target"], r["run"]): r[key] for r in res.by_label[proposed]}
    for lab in res.labels:
        if lab == proposed:
            continue
        other = {(r["target"], r["run"]): r[key] for r in res.by_label[lab]}
        pairs = sorted(set(base) & set(other))
        if not pairs:
            continue
        a, b = [base[k] for k in pairs], [other[k] for k in pairs]
        t = signed_rank(a, b)
        p_ranksum = ranksum_pvalues({proposed: a, lab: b}, proposed)[lab]
        rows.append([proposed, lab, res.source, fmt(t.r_plus), fmt(t.r_minus), fmt(t.p_value, 3),
                     fmt(p_ranksum, 3), t.better(proposed, lab), str(len(pairs))])
        p = paper.get(lab)
        if p:
            n_paper = int(p.get("r_plus", 0) + p.get("r_minus", 0))
            n_paper = int(round((math.sqrt(8 * n_paper + 1) - 1) / 2))  # R+ + R- = n (n + 1) / 2
            as_ranksum = (n_paper >= 2 and p.get("p") is not None
                          and p["p"] < smallest_p_values(n_paper)[0])
            cells = ["-", fmt(p.get("p"), 3)] if as_ranksum else [fmt(p.get("p"), 3), "-"]
            rows.append([proposed, lab, res.citation, fmt(p.get("r_plus")),
                         fmt(p.get("r_minus"))] + cells + [p.get("best", "-"), "-"])
            if n_paper >= 2 and p.get("p") is not None:
                papers.append((lab, n_paper, p["p"], as_ranksum))
    notes = ["R+: rank sum where data 1 has the larger error; p (signed-rank): two-sided "
             "Wilcoxon signed-rank of the pairs; p (rank-sum): two-sided Wilcoxon rank-sum "
             "(Mann-Whitney) of the two samples"]
    for lab, n_paper, p_value, as_ranksum in papers:
        low_signed, low_ranksum = smallest_p_values(n_paper)
        notes.append(f"paper's p vs {lab} = {p_value:.3g}; with {n_paper} runs the smallest "
                     f"two-sided p is {low_signed:.3g} (signed-rank) and {low_ranksum:.3g} "
                     f"(rank-sum): printed as "
                     f"{'rank-sum' if as_ranksum else 'signed-rank (it fits either range)'}")
    return [Table(f"Wilcoxon signed-rank and rank-sum tests, paired by (target, run), on {key}",
                  ["data 1", "data 2", "source", "R+", "R-", "p (signed-rank)", "p (rank-sum)",
                   "best", "pairs"], rows, notes)]


ANALYSIS_FUNCTIONS = {"summary": summary_table, "ranksum": ranksum_table,
                      "friedman-hv": friedman_hv_table, "joint-motion": joint_motion_table,
                      "compromise": compromise_table, "signed-rank": signed_rank_table}


def analyze(store: ResultStore) -> tuple[Results, list[Table]]:
    """All tables the experiment's config asks for."""
    res = Results(store)
    tables: list[Table] = []
    if res.ok:
        for name in res.config.get("analyses", ["summary"]):
            tables += {**ANALYSIS_FUNCTIONS, **FUNCTIONS, **DH_FIT_FUNCTIONS,
                       **RANK_FUNCTIONS, **CONSISTENCY_FUNCTIONS,
                       **FRONT_FUNCTIONS, **SHARES_FUNCTIONS, **REFERENCE_FUNCTIONS,
                       **COLLISION_FUNCTIONS}[name](res)
    for table in tables:
        if res.paper_note and any("paper" in row for row in table.rows):
            table.notes.append(res.paper_note)
    return res, tables
