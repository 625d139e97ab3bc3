"""Checks of a paper's printed statistics against each other (MO-m-PSO Tables 2-5).

- :func:`bhatia_davis_std_bound`: values in ``[lo, hi]`` with mean ``mu`` have a
  population variance of at most ``(hi - mu)(mu - lo)`` (Bhatia & Davis, "A
  better bound on the variance", Amer. Math. Monthly 107(4), 2000); the sample
  standard deviation (``ddof=1``) of ``n`` such values is at most
  ``sqrt(n / (n - 1) (hi - mu)(mu - lo))``. A printed standard deviation above
  that bound cannot come from the printed best, worst and mean.
- :func:`smallest_p_values`: the smallest two-sided p-value each Wilcoxon test can
  give for ``n`` runs (signed-rank of ``n`` pairs; rank-sum of ``n`` vs ``n``
  samples): the signed-rank one exact (``2 / 2^n``, smaller than its normal
  approximation), the rank-sum one as scipy's ``mannwhitneyu`` and MATLAB's
  ``ranksum`` give it for samples this large (normal approximation with continuity
  correction), so that a printed p can be told apart.

The analysis ``paper-consistency`` (:func:`printed_statistics_table`) applies the
bound to every best/worst/mean/std row of the config's ``paper`` dict (keys
``compromise`` and ``summary``; ``n_values``: how many values each printed row
summarises).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import stats

from moik.experiments.tables import Results, Table, fmt


def bhatia_davis_std_bound(lo: float, hi: float, mean: float, n: int | None = None) -> float:
    """Largest standard deviation of values in ``[lo, hi]`` with this mean.

    Args:
        lo, hi: Smallest and largest value (a table's best and worst).
        mean: Their mean.
        n: Number of values: the bound of the sample standard deviation
            (``ddof=1``); None: of the population one.
    """
    var = max(hi - mean, 0.0) * max(mean - lo, 0.0)
    if n is not None:
        var *= n / (n - 1)
    return math.sqrt(var)


def smallest_p_values(n: int) -> tuple[float, float]:
    """Smallest two-sided p of ``n`` runs: (signed-rank of n pairs, rank-sum of n vs n)."""
    a, b = np.arange(n, dtype=float), np.arange(n, dtype=float) + n
    p_signed = float(stats.wilcoxon(a - b, alternative="two-sided", method="exact").pvalue)
    p_ranksum = float(stats.mannwhitneyu(a, b, alternative="two-sided").pvalue)
    return p_signed, p_ranksum


def _printed_rows(paper: dict):
    for label, errors in paper.get("compromise", {}).items():
        for error, row in errors.items():
            yield label, error, row
    for label, row in paper.get("summary", {}).items():
        yield label, "objective", row


def printed_statistics_table(res: Results) -> list[Table]:
    """The Bhatia-Davis bound beside every printed std of the paper (``paper-consistency``)."""
    n = res.paper.get("n_values")
    rows = []
    for label, error, row in _printed_rows(res.paper):
        if not all(k in row for k in ("best", "worst", "mean", "std")):
            continue
        lo, hi, mean, std = row["best"], row["worst"], row["mean"], row["std"]
        bound = bhatia_davis_std_bound(lo, hi, mean, n)
        verdict = "possible" if std <= bound else "impossible"
        if not lo <= mean <= hi:
            verdict = "impossible (mean outside [best, worst])"
        rows.append([label, error, fmt(lo), fmt(hi), fmt(mean), fmt(std), fmt(bound), verdict])
    if not rows:
        return []
    which = f"sample std of {n} values" if n else "population std"
    return [Table("The paper's printed statistics: is the std possible? (Bhatia-Davis bound)",
                  ["algorithm", "error", "best", "worst", "mean", "printed std",
                   f"largest possible std ({which})", "verdict"], rows,
                  ["largest std = sqrt(n / (n - 1) (worst - mean)(mean - best)) for n values "
                   "in [best, worst] with that mean (Bhatia & Davis 2000)"])]


FUNCTIONS = {"paper-consistency": printed_statistics_table}
