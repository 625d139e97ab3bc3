"""Compact front-quality tables: one row per algorithm, one column per problem.

For experiments of the kind :mod:`moik.experiments.kinds.moo_functions`
(records with ``igd`` and ``hv``; a run without a feasible member has IGD inf):

- ``hv-shares``: per algorithm and problem, its mean HV as a share of the
  ``proposed`` algorithm's;
- ``versus-random``: per algorithm and problem, its mean IGD divided by the
  ``random-search`` baseline's (uniform sampling of the same budget); 1 or more
  is flagged "not below".

Their headlines (:data:`HEADLINES`) are the tables whole.
"""

from __future__ import annotations

import numpy as np

from moik.experiments.front_quality import samples
from moik.experiments.tables import Results, Table, fmt

BASELINE = "random-search"
"""The uniform-sampling baseline's label (see :mod:`moik.experiments.kinds.moo_functions`)."""


def _means(res: Results, key: str) -> tuple[list[str], dict[str, dict[str, float]]]:
    """Problem names, and per label the mean of ``key`` per problem (where it has runs)."""
    names = [t["name"] for t in res.meta["targets"]]
    means: dict[str, dict[str, float]] = {lab: {} for lab in res.labels}
    for ti, name in enumerate(names):
        for lab, v in samples(res, ti, key).items():
            if v.size:
                means[lab][name] = float(np.mean(v))
    return names, means


def versus_random_table(res: Results) -> list[Table]:
    """Per algorithm and problem, its mean IGD over the ``random-search`` baseline's."""
    if BASELINE not in res.labels:
        return []
    names, igd = _means(res, "igd")
    rows, behind = [], 0
    for lab in res.labels:
        if lab == BASELINE:
            continue
        cells = [lab]
        for n in names:
            if n not in igd[lab] or n not in igd[BASELINE]:
                cells.append("-")
                continue
            ratio = igd[lab][n] / igd[BASELINE][n]
            behind += ratio >= 1.0
            cells.append(f"{fmt(ratio, 3)}" + (" (not below)" if ratio >= 1.0 else ""))
        rows.append(cells)
    return [Table(f"Mean IGD over {BASELINE}'s (below 1: better than uniform sampling)",
                  ["algorithm"] + names, rows,
                  [f"{behind} cell(s) not below 1; {BASELINE}: the same budget sampled "
                   "uniformly in the box, non-dominated (and feasible) points kept"])]


def hv_shares_table(res: Results) -> list[Table]:
    """Per algorithm and problem, its mean HV as a share of the ``proposed`` algorithm's."""
    reference = res.config.get("proposed")
    if reference not in res.labels:
        return []
    names, hv = _means(res, "hv")
    rows = []
    for lab in res.labels:
        cells = [lab]
        for n in names:
            ref = hv[reference].get(n, 0.0)
            cells.append(f"{100 * hv[lab][n] / ref:.1f}%" if n in hv[lab] and ref > 0 else "-")
        rows.append(cells)
    return [Table(f"Mean HV as a share of {reference}'s", ["algorithm"] + names, rows,
                  ["HV reference point per problem as in the front-quality tables"])]


def _table_lines(tables: list[Table]) -> list[str]:
    """A table of one row per algorithm as markdown lines, with its notes."""
    lines: list[str] = []
    for table in tables:
        lines += [f"{table.title}:", "", "| " + " | ".join(table.header) + " |",
                  "|" + "---|" * len(table.header)]
        lines += ["| " + " | ".join(row) + " |" for row in table.rows]
        lines += [f"- {note}" for note in table.notes] + [""]
    return lines


def versus_random_lines(res: Results) -> list[str]:
    """Headline: the versus-random table whole."""
    return _table_lines(versus_random_table(res))


def hv_shares_lines(res: Results) -> list[str]:
    """Headline: the hv-shares table whole."""
    return _table_lines(hv_shares_table(res))


FUNCTIONS = {"versus-random": versus_random_table, "hv-shares": hv_shares_table}
"""Analysis name -> table function, merged into those of :mod:`moik.experiments.analysis`."""

HEADLINES = {"versus-random": versus_random_lines, "hv-shares": hv_shares_lines}
"""Analysis name -> headline function, merged into :data:`moik.experiments.headlines.HEADLINES`."""
