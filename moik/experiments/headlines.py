"""Headline numbers of an experiment: the short summary a generated docs block shows.

One function per analysis name of :data:`moik.experiments.config.ANALYSES`;
each returns Markdown lines computed from the stored trials (never typed in),
with the paper's numbers beside moik's where the config holds them. The focus
algorithm is the config's ``proposed`` one, else the first label (the configs
list the paper's method first). :func:`headline` joins those of the analyses
an experiment asks for; :mod:`moik.experiments.docs` puts them in the docs.
"""

from __future__ import annotations

import numpy as np

from moik.experiments.analysis import front_hv
from moik.experiments.collision_report import FUNCTIONS as COLLISION_FUNCTIONS
from moik.experiments.consistency import FUNCTIONS as CONSISTENCY_FUNCTIONS
from moik.experiments.dh_fit import FUNCTIONS as DH_FIT_FUNCTIONS
from moik.experiments.front_quality import HEADLINES as FRONT_HEADLINES
from moik.experiments.front_shares import HEADLINES as SHARES_HEADLINES
from moik.experiments.kinds.ik_robot import arm, experiment_robot
from moik.experiments.per_target import cluster_solutions
from moik.experiments.reference_fronts import FUNCTIONS as REFERENCE_FUNCTIONS
from moik.experiments.solution_sets import FUNCTIONS as RANK_FUNCTIONS
from moik.experiments.tables import Results, fmt
from moik.metrics import ranksum_pvalues, signed_rank, success_rate, summarize


def focus(res: Results) -> str | None:
    """The label the headline is about: ``proposed``, else the first label with results."""
    proposed = res.config.get("proposed")
    if proposed in res.labels:
        return proposed
    return res.labels[0] if res.labels else None


def _paper(res: Results, key: str) -> dict:
    return res.paper.get(key, {})


def summary_lines(res: Results) -> list[str]:
    """Mean/median/worst/success/time per algorithm, the paper's mean and worst beside."""
    thr = res.config.get("success_threshold", 1e-6)
    paper = _paper(res, "summary")
    if not res.scalar_labels():
        return ["- no final objective values to summarise (the trials store fronts: ask for "
                "a front analysis such as front-quality in the config's analyses)", ""]
    lines = [f"| algorithm | mean | median | worst | best | success (f < {thr:g}) | time (s) "
             f"| {res.citation} mean | {res.citation} worst |",
             "|---|---|---|---|---|---|---|---|---|"]
    for lab in res.scalar_labels():
        f = np.nan_to_num(res.values(lab, "best_f"), posinf=np.finfo(float).max)
        with np.errstate(over="ignore"):  # a trial without a value counts as the largest
            s = summarize(f, res.values(lab, "time"))
        p = paper.get(lab, {})
        lines.append(f"| {lab} | {fmt(s.mean, 3)} | {fmt(s.median, 3)} | {fmt(s.worst, 3)} | "
                     f"{fmt(s.best, 3)} | {100 * success_rate(f, thr):.0f}% | {fmt(s.time, 3)} | "
                     f"{fmt(p.get('mean'), 3)} | {fmt(p.get('worst'), 3)} |")
    return lines + [""]


def ranksum_lines(res: Results) -> list[str]:
    """How many algorithms the proposed one beats by the rank-sum test."""
    lab = focus(res)
    others = [o for o in res.labels if o != lab]
    if lab is None or not others:
        return []
    samples = {o: np.nan_to_num(res.values(o, "best_f"), posinf=np.finfo(float).max)
               for o in res.labels}
    pv = ranksum_pvalues(samples, lab)
    med = {o: float(np.median(v)) for o, v in samples.items()}
    better = [o for o in others if pv[o] < 0.05 and med[lab] < med[o]]
    worse = [o for o in others if pv[o] < 0.05 and med[lab] > med[o]]
    return [f"- rank-sum test (two-sided, alpha 0.05, by median): {lab} better than "
            f"{len(better)} of {len(others)}; worse than {', '.join(worse) or 'none'}"]


def compromise_lines(res: Results) -> list[str]:
    """Mean (median) position and orientation error of the selected solutions."""
    unit = arm(res.robot).unit
    paper = _paper(res, "compromise")
    lines = []
    for lab in res.labels:
        parts, cited = [], []
        for key, name, u in (("position_error", "position", unit),
                             ("orientation_error", "orientation", "rad")):
            v = res.values(lab, key)
            if v.size and np.all(np.isfinite(v)):
                parts.append(f"{name} mean {fmt(float(np.mean(v)), 3)} {u} "
                             f"(median {fmt(float(np.median(v)), 3)})")
            p = paper.get(lab, {}).get(name, {})
            if p.get("mean") is not None:
                cited.append(f"{name} mean {fmt(p['mean'], 3)} {u}")
        if parts:
            lines.append(f"- {lab}: " + ", ".join(parts)
                         + (f"; {res.citation}: {', '.join(cited)}" if cited else ""))
    return lines


def signed_rank_lines(res: Results) -> list[str]:
    """R+/R- and p of the proposed algorithm vs each, paired by (target, run)."""
    lab = focus(res)
    key = "best_f" if res.config["problem"]["kind"] != "bi-objective" else "position_error"
    paper = _paper(res, "signed_rank")
    if lab is None:
        return []
    base = {(r["target"], r["run"]): r[key] for r in res.by_label[lab]}
    lines = []
    for other in res.labels:
        if other == lab:
            continue
        pairs = {(r["target"], r["run"]): r[key] for r in res.by_label[other]}
        common = sorted(set(base) & set(pairs))
        if not common:
            continue
        t = signed_rank([base[k] for k in common], [pairs[k] for k in common])
        p = paper.get(other, {})
        cited = (f" ({res.citation} {fmt(p.get('r_plus'))}/{fmt(p.get('r_minus'))})"
                 if p.get("r_plus") is not None else "")
        lines.append(f"- {lab} vs {other}: R+/R- = {fmt(t.r_plus)}/{fmt(t.r_minus)}{cited}, "
                     f"p = {fmt(t.p_value, 2)}, better: {t.better(lab, other)} "
                     f"({len(common)} pairs)")
    return lines


def friedman_hv_lines(res: Results) -> list[str]:
    """Per target: the focus algorithm's HV, rank, uncovered share of the box; the best HV."""
    lab = focus(res)
    paper = _paper(res, "hv")
    lines = []
    for (name, _ti), hv in front_hv(res).items():
        ref = hv.pop("__ref__")
        means = {o: float(v.mean()) for o, v in hv.items() if v.size}
        if lab not in means:
            continue
        order = sorted(means, key=lambda o: -means[o])
        box = float(np.prod(ref))
        p = paper.get(name, {}).get(lab, {})
        cited = ""
        if p.get("mean") is not None:
            cited = (f" ({res.citation} {fmt(p['mean'], 6)}, rank {p.get('rank', '-')}; uncovered "
                     f"{fmt(box - p['mean'], 3)}, {100 * (box - p['mean']) / box:.2f} %)")
        lines.append(f"- {name}: {lab} HV {fmt(means[lab], 6)}, rank by mean HV "
                     f"{order.index(lab) + 1} of {len(order)}; uncovered box - HV = "
                     f"{fmt(box - means[lab], 3)} of the box {fmt(box, 5)} "
                     f"({100 * (box - means[lab]) / box:.2f} %){cited}; highest mean HV: "
                     f"{order[0]} {fmt(means[order[0]], 6)}")
    return lines


def joint_motion_lines(res: Results) -> list[str]:
    """Per algorithm: runs reaching the pose, best joint distance (paper's beside)."""
    thr = res.config.get("success_threshold", 1e-6)
    paper = _paper(res, "joint_motion")
    lines = []
    for lab in res.labels:
        recs = [r for r in res.by_label[lab] if r.get("best_f") is not None]
        if not recs:
            continue
        solved = [r for r in recs if r.get("position_error", r["best_f"]) < thr
                  and r.get("orientation_error", 0.0) < thr]
        best = min(recs, key=lambda r: r["best_f"])
        p = paper.get(lab, {})
        cited = f" ({res.citation} {fmt(p['distance'], 7)} deg)" if p.get("distance") else ""
        lines.append(f"- {lab}: pose reached (errors < {thr:g}) in {len(solved)} of {len(recs)} "
                     f"runs; lowest objective {fmt(best['best_f'], 3)} at joint distance "
                     f"{fmt(best.get('joint_distance_deg'), 7)} deg{cited}")
    return lines


def per_target_lines(res: Results) -> list[str]:
    """Per target: the focus algorithm's median and mean, the best median and who has it."""
    lab = focus(res)
    paper = res.paper.get("per_target", {})
    lines = [f"| target | {lab} median | {lab} mean | {res.citation} {lab} mean | best median |",
             "|---|---|---|---|---|"]
    for ti, target in enumerate(res.meta["targets"]):
        med = {}
        for o in res.labels:
            f = np.array([r["best_f"] for r in res.by_label[o]
                          if r["target"] == ti and r.get("best_f") is not None], dtype=float)
            if f.size:
                med[o] = (float(np.median(f)), float(np.mean(f)))
        if lab not in med:
            continue
        top = min(med, key=lambda o: med[o][0])
        p = paper.get(target["name"], {}).get(lab, {})
        lines.append(f"| {target['name']} | {fmt(med[lab][0], 3)} | {fmt(med[lab][1], 3)} | "
                     f"{fmt(p.get('mean'), 3)} | {top} {fmt(med[top][0], 3)} |")
    return lines + [""]


def per_target_ranksum_lines(res: Results) -> list[str]:
    """Count of +/=/- of the proposed algorithm against each other one over the targets."""
    lab = focus(res)
    others = [o for o in res.labels if o != lab]
    if lab is None or not others:
        return []
    big = np.finfo(float).max
    count = {"+": 0, "=": 0, "-": 0}
    for ti in range(len(res.meta["targets"])):
        samples = {o: np.array([big if r.get("best_f") is None else r["best_f"]
                                for r in res.by_label[o] if r["target"] == ti])
                   for o in res.labels}
        if any(v.size == 0 for v in samples.values()):
            continue
        pv = ranksum_pvalues(samples, lab)
        for o in others:
            a, b = float(np.median(samples[lab])), float(np.median(samples[o]))
            sign = "=" if not np.isfinite(pv[o]) or pv[o] >= 0.05 or a == b else (
                "+" if a < b else "-")
            count[sign] += 1
    return [f"- rank-sum per target, {lab} vs each other algorithm: {count['+']} better (+), "
            f"{count['=']} no difference (=), {count['-']} worse (-) of {sum(count.values())}"]


def branches_lines(res: Results) -> list[str]:
    """Per target: runs solved and distinct branches found by the first algorithm."""
    if not res.labels:
        return []
    lab, thr = res.labels[0], res.config.get("success_threshold", 1e-6)
    robot = experiment_robot(res.robot, res.config.get("problem", {}))
    parts = []
    for ti, target in enumerate(res.meta["targets"]):
        recs = [r for r in res.by_label[lab] if r["target"] == ti]
        solved = [r for r in recs if r.get("best_f") is not None and r["best_f"] < thr
                  and r.get("best_x") is not None]
        parts.append(f"{target['name']} {len(cluster_solutions(robot, solved))} branches "
                     f"({len(solved)}/{len(recs)} runs solved)")
    return [f"- {lab}, distinct solutions (f < {thr:g}): " + "; ".join(parts)]


def notes_of(tables_of):
    """Headline of an analysis whose tables carry their own verdict in their notes."""
    def lines(res: Results) -> list[str]:
        return [f"- {note}" for table in tables_of(res) for note in table.notes]
    lines.__doc__ = f"The notes of :func:`{tables_of.__name__}`'s tables, one line each."
    return lines


HEADLINES = {"summary": summary_lines, "ranksum": ranksum_lines,
             "friedman-hv": friedman_hv_lines, "joint-motion": joint_motion_lines,
             "compromise": compromise_lines, "signed-rank": signed_rank_lines,
             "per-target": per_target_lines, "per-target-ranksum": per_target_ranksum_lines,
             "branches": branches_lines,
             "dh-fit": notes_of(DH_FIT_FUNCTIONS["dh-fit"]),
             "solution-rank": notes_of(RANK_FUNCTIONS["solution-rank"]),
             "paper-consistency": notes_of(CONSISTENCY_FUNCTIONS["paper-consistency"]),
             "reference-front": notes_of(REFERENCE_FUNCTIONS["reference-front"]),
             "collision": notes_of(COLLISION_FUNCTIONS["collision"]),
             **FRONT_HEADLINES, **SHARES_HEADLINES}
"""Analysis name -> headline function (every name of ``ANALYSES`` has one)."""


def headline(res: Results) -> list[str]:
    """The headline lines of every analysis the experiment asks for, in its order."""
    if not res.ok:
        return ["- no finished trials"]
    lines: list[str] = []
    for name in res.config.get("analyses", ["summary"]):
        part = HEADLINES[name](res)
        if part and lines and lines[-1]:
            lines.append("")  # a list and a table stay apart in Markdown
        lines += part
    return lines
