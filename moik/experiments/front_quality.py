"""Tables of front quality (IGD, HV) on multi-objective benchmark problems.

For experiments of the kind :mod:`moik.experiments.kinds.moo_functions`
(records with ``igd`` and ``hv``):

- ``front-quality``: per problem and algorithm, IGD and HV mean and std over
  the runs, each with the two-sided Wilcoxon rank-sum test against the
  config's ``proposed`` label (the reference algorithm, NSGA-II in
  ``moo-suite``) and its verdict: ``+`` the row's algorithm is better (lower
  IGD / higher HV by median, p < 0.05), ``-`` worse, ``=`` no significant
  difference; HV as a share of the reference's mean HV. On constrained
  problems (records with ``n_infeasible``) the members are the feasible ones
  and columns count the runs that returned a feasible member and the infeasible
  members reported over the runs.
- ``mean-ranks``: per problem, the algorithms ranked by mean IGD (1 = lowest)
  and by mean HV (1 = highest), ties sharing the mean of their ranks; the mean
  over the problems, and the ``+``/``=``/``-`` counts of the IGD test over the
  problems. Only problems where every algorithm has runs are ranked.

The compact per-algorithm x per-problem tables (``hv-shares``,
``versus-random``) are in :mod:`moik.experiments.front_shares`.

The computations are plain functions of numbers (:func:`mean_ranks`,
:func:`ranksum_verdicts`); the table functions only gather the records. The
headline of a generated docs block (:data:`HEADLINES`): the lowest mean IGD per
problem, and the mean ranks with the +/=/- counts.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from scipy.stats import rankdata

from moik.experiments.kinds.moo_fronts import CONSTRAINED
from moik.experiments.tables import Results, Table, fmt
from moik.metrics import ranksum_pvalues

ALPHA = 0.05
"""Significance level of the rank-sum verdicts."""

def ranksum_verdicts(samples: Mapping[str, Sequence[float] | np.ndarray], reference: str, *,
                     higher_is_better: bool) -> dict[str, tuple[float, str]]:
    """Rank-sum p-value and verdict of every sample against ``reference``.

    Args:
        samples: Label -> values of its runs (independent samples).
        reference: The label the others are compared with.
        higher_is_better: True for HV, False for IGD.

    Returns:
        Label (every one but ``reference``) -> ``(p, verdict)``: ``"+"`` the label is
        better than ``reference`` by median at p < :data:`ALPHA`, ``"-"`` worse,
        ``"="`` no significant difference.
    """
    finite = np.concatenate([np.asarray(v, dtype=float) for v in samples.values()])
    finite = finite[np.isfinite(finite)]
    # a rank test needs only the order: an infinite value (IGD of a run without a
    # feasible member) becomes one above every finite one, a -inf one below
    top = float(np.max(np.abs(finite))) * 2.0 + 1.0 if finite.size else 1.0
    pvalues = ranksum_pvalues({k: list(np.clip(np.asarray(v, dtype=float), -top, top))
                               for k, v in samples.items()}, reference)
    ref_median = float(np.median(samples[reference]))
    out = {}
    for label, p in pvalues.items():
        median = float(np.median(samples[label]))
        if not np.isfinite(p) or p >= ALPHA or median == ref_median:
            out[label] = (p, "=")
        else:
            better = median > ref_median if higher_is_better else median < ref_median
            out[label] = (p, "+" if better else "-")
    return out


def mean_ranks(means: Mapping[str, Mapping[str, float]], *, higher_is_better: bool
               ) -> tuple[dict[str, dict[str, float]], dict[str, float]]:
    """Ranks of the algorithms per problem by their mean, and the mean rank over problems.

    Args:
        means: Problem -> (label -> mean value); every problem must list the same labels.
        higher_is_better: True for HV (rank 1 = highest), False for IGD (1 = lowest).

    Returns:
        ``(ranks, mean_rank)``: problem -> (label -> rank), ties sharing the mean of their
        ranks; label -> the mean of its ranks over the problems.
    """
    ranks = {}
    for problem, by_label in means.items():
        labels = list(by_label)
        values = np.array([by_label[lab] for lab in labels], dtype=float)
        r = rankdata(-values if higher_is_better else values, method="average")
        ranks[problem] = {lab: float(v) for lab, v in zip(labels, r, strict=True)}
    labels = list(next(iter(means.values()))) if means else []
    mean_rank = {lab: float(np.mean([ranks[p][lab] for p in ranks])) for lab in labels}
    return ranks, mean_rank


def samples(res: Results, ti: int, key: str) -> dict[str, np.ndarray]:
    """Per label, ``key`` of its runs on target ``ti``; a missing IGD (a run without a
    feasible member, stored as null) reads as inf."""
    return {lab: np.array([np.inf if r[key] is None else r[key] for r in res.by_label[lab]
                           if r["target"] == ti], dtype=float) for lab in res.labels}


def _std(v: np.ndarray) -> float:
    if not np.all(np.isfinite(v)):
        return float("nan")  # printed "-"
    return float(np.std(v, ddof=1)) if v.size > 1 else 0.0


def front_quality_table(res: Results) -> list[Table]:
    """IGD and HV per problem and algorithm with the rank-sum test against ``proposed``."""
    reference = res.config.get("proposed")
    tables = []
    for ti, target in enumerate(res.meta["targets"]):
        igd, hv = samples(res, ti, "igd"), samples(res, ti, "hv")
        labels = [lab for lab in res.labels if igd[lab].size]
        compare = reference in labels and len(labels) > 1
        tests = ({key: ranksum_verdicts({lab: s[lab] for lab in labels}, reference,
                                        higher_is_better=key == "hv")
                  for key, s in (("igd", igd), ("hv", hv))} if compare else {})
        ref_hv = float(np.mean(hv[reference])) if compare else np.nan
        constrained = target.get("benchmark") in CONSTRAINED
        rows = []
        for lab in labels:
            recs = [r for r in res.by_label[lab] if r["target"] == ti]
            cells = [lab]
            for key, s in (("igd", igd), ("hv", hv)):
                test = tests.get(key, {}).get(lab)
                cells += [fmt(float(np.mean(s[lab])), 4), fmt(_std(s[lab]), 2),
                          f"{test[1]} ({test[0]:.2g})" if test else "-"]
            share = float(np.mean(hv[lab])) / ref_hv if compare and ref_hv > 0 else np.nan
            cells += ["-" if np.isnan(share) else f"{100 * share:.1f}%",
                      fmt(float(np.mean([r["n_front"] for r in recs])), 4)]
            if constrained:
                cells += [f"{sum(int(r['n_front']) > 0 for r in recs)}/{len(recs)}",
                          str(sum(int(r.get("n_infeasible", 0)) for r in recs))]
            cells += [fmt(float(np.mean([r["time"] for r in recs])), 3), str(len(recs))]
            rows.append(cells)
        first = [r for lab in labels for r in res.by_label[lab] if r["target"] == ti][:1]
        ref_point = first[0].get("hv_ref_point") if first else None
        notes = [f"HV reference point {np.round(ref_point, 6).tolist() if ref_point else '-'} "
                 "(the analytic front's nadir + 0.1 x its magnitude per objective: 1.1 x the "
                 "nadir where positive); std with ddof=1"]
        if constrained:
            notes.append("members re-evaluated: front size counts the feasible members (IGD "
                         "and HV score only those; a run with none scores IGD inf and HV 0); "
                         "feasible runs: the runs that returned a feasible member; infeasible "
                         "reported: the members with a violated constraint returned, summed "
                         "over the runs")
        if compare:
            notes.append(f"vs {reference}: two-sided Wilcoxon rank-sum test; + the row's "
                         f"algorithm better by median (p < {ALPHA:g}), - worse, = no "
                         "significant difference; (p-value)")
        tables.append(Table(f"{target['name']}: IGD and HV over the runs",
                            ["algorithm", "IGD mean", "IGD std", f"IGD vs {reference}",
                             "HV mean", "HV std", f"HV vs {reference}",
                             f"HV / {reference}", "front size"]
                            + (["feasible runs", "infeasible reported"] if constrained else [])
                            + ["time (s)", "runs"],
                            rows, notes))
    return tables


def mean_ranks_table(res: Results) -> list[Table]:
    """Mean ranks by IGD and HV over the problems, and the IGD test's +/=/- counts."""
    reference = res.config.get("proposed")
    names = [t["name"] for t in res.meta["targets"]]
    igd_means: dict[str, dict[str, float]] = {}
    hv_means: dict[str, dict[str, float]] = {}
    signs: dict[str, list[str]] = {lab: [] for lab in res.labels}
    left_out: list[str] = []
    for ti, name in enumerate(names):
        igd, hv = samples(res, ti, "igd"), samples(res, ti, "hv")
        if not res.labels or any(igd[lab].size == 0 for lab in res.labels):
            left_out.append(name)
            continue
        igd_means[name] = {lab: float(np.mean(igd[lab])) for lab in res.labels}
        hv_means[name] = {lab: float(np.mean(hv[lab])) for lab in res.labels}
        if reference in res.labels and len(res.labels) > 1:
            for lab, (_, sign) in ranksum_verdicts(igd, reference,
                                                   higher_is_better=False).items():
                signs[lab].append(sign)
    if not igd_means:
        return []
    igd_ranks, igd_mean = mean_ranks(igd_means, higher_is_better=False)
    _, hv_mean = mean_ranks(hv_means, higher_is_better=True)
    ranked = [n for n in names if n in igd_ranks]
    rows = []
    for lab in sorted(res.labels, key=lambda lab: (igd_mean[lab], hv_mean[lab])):
        counts = ("-" if lab == reference or not signs[lab] else
                  "/".join(str(signs[lab].count(s)) for s in "+=-"))
        rows.append([lab, f"{igd_mean[lab]:.2f}", f"{hv_mean[lab]:.2f}", counts]
                    + [f"{igd_ranks[n][lab]:g}" for n in ranked])
    notes = [f"ranks of the mean over the runs per problem, ties sharing their mean rank; "
             f"{len(ranked)} problem(s) ranked"]
    if left_out:
        notes.append("left out (not every algorithm has runs there): " + ", ".join(left_out))
    return [Table("Mean ranks over the problems (1 = best)",
                  ["algorithm", "mean IGD rank", "mean HV rank", f"IGD vs {reference} +/=/-"]
                  + [f"{n} IGD rank" for n in ranked], rows, notes)]


def front_quality_lines(res: Results) -> list[str]:
    """Headline: per problem, the lowest mean IGD and the reference algorithm's."""
    reference = res.config.get("proposed")
    parts = []
    for ti, target in enumerate(res.meta["targets"]):
        igd = {lab: v for lab, v in samples(res, ti, "igd").items() if v.size}
        if not igd:
            continue
        best = min(igd, key=lambda lab: float(np.mean(igd[lab])))
        ref = (f", {reference} {fmt(float(np.mean(igd[reference])), 3)}"
               if reference in igd and reference != best else "")
        parts.append(f"{target['name']} {best} {fmt(float(np.mean(igd[best])), 3)}{ref}")
    return ["- lowest mean IGD per problem: " + "; ".join(parts)] if parts else []


def mean_ranks_lines(res: Results) -> list[str]:
    """Headline: the mean-ranks table without its per-problem columns."""
    tables = mean_ranks_table(res)
    if not tables:
        return []
    (table,) = tables
    lines = ["| " + " | ".join(table.header[:4]) + " |", "|---|---|---|---|"]
    return lines + ["| " + " | ".join(row[:4]) + " |" for row in table.rows] + [
        f"- {table.notes[0]}"]


FUNCTIONS = {"front-quality": front_quality_table, "mean-ranks": mean_ranks_table}
"""Analysis name -> table function, merged into those of :mod:`moik.experiments.analysis`."""

HEADLINES = {"front-quality": front_quality_lines, "mean-ranks": mean_ranks_lines}
"""Analysis name -> headline function, merged into :data:`moik.experiments.headlines.HEADLINES`."""
