"""Tables per target (or per benchmark problem), and the solution branches of I-BES Table 9.

- ``per-target``: best/worst/mean/median/std of ``best_f`` over the runs of
  each (target, algorithm), with the paper's numbers (``paper["per_target"]
  [target name][label]``) on the next row (I-BES Tables 8, 12, 15, 17; MChOA
  Table 3). Runs whose best design is infeasible (``best_f`` None) are left out
  of the statistics and counted in the ``feasible runs`` column.
- ``per-target-ranksum``: two-sided Wilcoxon rank-sum p-value of the proposed
  algorithm vs each other one per target, with ``+``/``-``/``=`` (proposed
  better / worse by median at alpha 0.05 / no significant difference); an
  infeasible run ranks last. Paper cells: ``paper["ranksum"][target][label] =
  {"p", "R"}`` (I-BES Table 13).
- ``branches``: the distinct joint solutions found at each target by the runs
  of the first algorithm (runs below ``success_threshold`` only, joint angles
  compared modulo 2 pi, distinct beyond 0.1 rad), matched to the paper's branches
  ``paper["branches"][target] = [{"geometric": q, "paper": q}, ...]`` (rad;
  I-BES Table 9).
"""

from __future__ import annotations

import numpy as np

from moik.experiments.kinds.ik_robot import experiment_robot
from moik.experiments.tables import Results, Table, fmt
from moik.kinematics.criteria import joint_distance
from moik.metrics import ranksum_pvalues, summarize
from moik.robots.chain import Robot

DISTINCT = 0.1
"""Joint-space distance (rad) beyond which two solutions are different branches."""


def _runs(res: Results, label: str, ti: int) -> list[dict]:
    return [r for r in res.by_label[label] if r["target"] == ti]


def _finite(records: list[dict], key: str = "best_f") -> np.ndarray:
    return np.array([r[key] for r in records if r.get(key) is not None], dtype=float)


def per_target_table(res: Results) -> list[Table]:
    """Statistics of ``best_f`` per target and algorithm, paper rows beside them."""
    paper = res.paper.get("per_target", {})
    header = ["target", "algorithm", "source", "best", "worst", "mean", "median", "std",
              "time (s)", "feasible runs"]
    rows = []
    for ti, target in enumerate(res.meta["targets"]):
        name = target["name"]
        for lab in res.labels:
            recs = _runs(res, lab, ti)
            if not recs:
                continue
            f = _finite(recs)
            t = float(np.mean([r["time"] for r in recs]))
            if f.size:
                s = summarize(f)
                stats = [fmt(s.best), fmt(s.worst), fmt(s.mean), fmt(s.median), fmt(s.std)]
            else:
                stats = ["-"] * 5
            rows.append([name, lab, res.source, *stats, fmt(t), f"{f.size}/{len(recs)}"])
            p = paper.get(name, {}).get(lab)
            if p:
                rows.append([name, lab, res.citation] + [fmt(p.get(k)) for k in
                            ("best", "worst", "mean", "median", "std", "time")] + ["-"])
    notes = ["statistics over the runs whose best design is feasible (all runs for "
             "unconstrained problems); std with ddof=1"]
    return [Table("Final objective value per target / problem", header, rows, notes)]


def _verdict(p: float, a: float, b: float) -> str:
    if not np.isfinite(p) or p >= 0.05 or a == b:
        return "="
    return "+" if a < b else "-"


def _paper_verdicts(res: Results, name: str, proposed: str, others: list[str]) -> list[str]:
    """``+``/``-``/``=`` of the paper's rank-sum row, else of its means, per other algorithm."""
    ranks = res.paper.get("ranksum", {}).get(name)
    if ranks:
        return [ranks[lab].get("R", "") if lab in ranks else "" for lab in others]
    means = res.paper.get("per_target", {}).get(name, {})
    if "mean" not in means.get(proposed, {}):
        return []
    a = means[proposed]["mean"]
    return [("=" if a == means[lab]["mean"] else "+" if a < means[lab]["mean"] else "-")
            if "mean" in means.get(lab, {}) else "" for lab in others]


def per_target_ranksum_table(res: Results) -> list[Table]:
    """Rank-sum p-values and +/-/= of the proposed algorithm vs each, per target.

    Beside moik's row: the paper's rank-sum row when the config has one, else
    the paper's verdict by mean; a note lists where moik's verdict differs.
    """
    proposed = res.config["proposed"]
    others = [lab for lab in res.labels if lab != proposed]
    if proposed not in res.labels or not others:
        return []
    paper = res.paper.get("ranksum", {})
    big = np.finfo(float).max
    rows, compared, differ = [], 0, []
    for ti, target in enumerate(res.meta["targets"]):
        name = target["name"]
        samples = {lab: np.array([big if r.get("best_f") is None else r["best_f"]
                                  for r in _runs(res, lab, ti)]) for lab in res.labels}
        if any(v.size == 0 for v in samples.values()):
            continue
        pv = ranksum_pvalues(samples, proposed)
        med = {lab: float(np.median(v)) for lab, v in samples.items()}
        ours = [_verdict(pv[lab], med[proposed], med[lab]) for lab in others]
        rows.append([name, res.source] + [f"{fmt(pv[lab], 3)} {v}" for lab, v in
                                      zip(others, ours, strict=True)])
        theirs = _paper_verdicts(res, name, proposed, others)
        p = paper.get(name)
        if p:
            rows.append([name, res.citation] + [
                f"{fmt(p[lab].get('p'), 3)} {p[lab].get('R', '')}" if lab in p else "-"
                for lab in others])
        elif theirs:
            rows.append([name, f"{res.citation} (by mean)"] + [v or "-" for v in theirs])
        for lab, a, b in zip(others, ours, theirs, strict=False):
            if b:
                compared += 1
                if a != b:
                    differ.append(f"{name} vs {lab} (moik {a}, paper {b})")
    notes = ["+: proposed better (lower median, p < 0.05); -: worse; =: no significant "
             "difference; infeasible runs rank last; paper rows by mean: + where the paper's "
             "mean of the proposed algorithm is lower"]
    if compared:
        notes.append(f"moik's verdict matches the paper's in {compared - len(differ)} of "
                     f"{compared} comparisons" + (f"; differs: {'; '.join(differ)}"
                                                   if differ else ""))
    return [Table(f"Wilcoxon rank-sum test of {proposed} vs each algorithm, per target",
                  ["target", "source"] + [f"{proposed} vs {lab}" for lab in others], rows,
                  notes)]


def wrapped_distance(robot: Robot, q1, q2) -> float:
    """The joint distance of two joint vectors of ``robot`` (revolute differences wrapped to
    ``[-pi, pi)``, prismatic ones not: :func:`~moik.kinematics.criteria.joint_distance`)."""
    return float(joint_distance(robot, np.asarray(q1, dtype=float),
                                np.asarray(q2, dtype=float))[0])


def cluster_solutions(robot: Robot, records: list[dict], distinct: float = DISTINCT
                      ) -> list[list[dict]]:
    """Group solved runs into branches: each joins the first branch whose best is near it."""
    branches: list[list[dict]] = []
    for r in sorted(records, key=lambda r: r["best_f"]):
        for b in branches:
            if wrapped_distance(robot, b[0]["best_x"], r["best_x"]) <= distinct:
                b.append(r)
                break
        else:
            branches.append([r])
    return branches


def _q(q) -> str:
    return "(" + ", ".join(f"{v:.5f}" for v in q) + ")"


def branches_table(res: Results) -> list[Table]:
    """Distinct solutions per target vs the paper's geometric and I-BES branches.

    Per paper branch: the branch found nearest the geometric solution and, in
    it, the run nearest the geometric solution; ``|dq|`` to the geometric and
    to the paper's own I-BES solution. A note gives the largest gap to the
    geometric solutions over all matched branches.
    """
    if not res.labels:
        return []
    lab, thr = res.labels[0], res.config.get("success_threshold", 1e-6)
    robot = experiment_robot(res.robot, res.config.get("problem", {}))
    paper = res.paper.get("branches", {})
    rows, notes, gaps, n_ref = [], [], [], 0
    for ti, target in enumerate(res.meta["targets"]):
        recs = _runs(res, lab, ti)
        solved = [r for r in recs if r.get("best_f") is not None and r["best_f"] < thr
                  and r.get("best_x") is not None]
        found = cluster_solutions(robot, solved)
        ref = paper.get(target["name"], [])
        n_ref += len(ref)
        used = set()
        for bi, pb in enumerate(ref):
            dist = [min(wrapped_distance(robot, pb["geometric"], r["best_x"]) for r in b)
                    for b in found]
            k = int(np.argmin(dist)) if dist else -1
            b = found[k] if k >= 0 and dist[k] <= DISTINCT else None
            cells = ["not found", "-", "-", "0", "-"]
            if b is not None:
                used.add(k)
                geometric = pb["geometric"]
                near = min(b, key=lambda r: wrapped_distance(robot, geometric, r["best_x"]))
                gaps.append(dist[k])
                cells = [_q(near["best_x"]), fmt(dist[k], 3),
                         fmt(wrapped_distance(robot, pb["paper"], near["best_x"]), 3),
                         str(len(b)),
                         fmt(near["best_f"], 3)]
            rows.append([target["name"], f"q{bi + 1}", _q(pb["geometric"]), _q(pb["paper"]),
                         fmt(wrapped_distance(robot, pb["geometric"], pb["paper"]), 3), *cells])
        for k, b in enumerate(found):
            if k not in used:
                rows.append([target["name"], "other", "-", "-", "-", _q(b[0]["best_x"]), "-", "-",
                             str(len(b)), fmt(b[0]["best_f"], 3)])
        notes.append(f"{target['name']}: {len(solved)} of {len(recs)} runs solved "
                     f"(f < {thr:g}), {len(found)} distinct branch(es)")
    if gaps:
        notes.append(f"{len(gaps)} of {n_ref} paper branches found; largest |dq| to the "
                     f"geometric solution {max(gaps):.3g} rad, median {np.median(gaps):.3g} rad "
                     "(the geometric angles are printed to 4 decimals: rounding alone "
                     "allows up to sqrt(3) x 5e-5 = 8.7e-5 rad)")
    header = ["target", "branch", "geometric (paper)", f"{lab} (paper)", "paper |dq|",
              f"{lab} (moik, run of the branch nearest the geometric)",
              "moik |dq| to geometric", f"moik |dq| to {lab} (paper)", "runs in branch",
              "position error"]
    return [Table(f"Solution branches found by {lab} (joint angles in rad)", header, rows,
                  notes)]


FUNCTIONS = {"per-target": per_target_table, "per-target-ranksum": per_target_ranksum_table,
             "branches": branches_table}
"""Analysis name -> table function, merged into those of :mod:`moik.experiments.analysis`."""
