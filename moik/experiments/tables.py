"""Result tables: the records of a results folder grouped for analysis, and a titled table.

:class:`Results` reads a :class:`~moik.experiments.store.ResultStore` (ok and
failed trials, records per algorithm label in (target, run) order);
:class:`Table` is what an analysis returns and :mod:`moik.experiments.report`
prints; :func:`fmt` formats a number as the report prints it.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field

import numpy as np

from moik.experiments.config_files import budget_of, budget_text
from moik.experiments.kinds.ik_robot import stored_robot
from moik.experiments.store import ResultStore, planned_ids


@dataclass
class Table:
    """A titled table of formatted cells."""

    title: str
    header: list[str]
    rows: list[list[str]]
    notes: list[str] = field(default_factory=list)


def fmt(value, digits: int = 4) -> str:
    """A number as the report prints it (``-`` for missing)."""
    if value is None or (isinstance(value, float) and np.isnan(value)):
        return "-"
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        return str(value)
    if isinstance(value, (float, np.floating)):
        return f"{value:.{digits}g}"
    return str(value)


class Results:
    """The records of a results folder grouped for analysis."""

    def __init__(self, store: ResultStore):
        self.store = store
        self.meta = store.meta
        self.config = store.meta["config"]
        # the robot as the trials loaded it (a URDF arm: its file, checked unchanged)
        self.robot = stored_robot(store.meta) if "robot" in self.config else None
        self.paper = self.config.get("paper", {})
        self.citation, self.source = "paper", "moik"
        cite = self.paper.get("citation")
        self.paper_note = f"paper rows: {cite}" if cite else None
        theirs, ours = self.paper.get("budget"), budget_of(self.config)
        if theirs and any(ours.get(k) != v for k, v in theirs.items()):
            # a variant at another budget than the paper's: its numbers are no comparison
            self.citation = f"paper, at {budget_text(theirs)}"
            self.source = f"this run, at {budget_text(ours)}"
            self.paper_note = (f"the paper's rows are at {budget_text(theirs)}, this run at "
                               f"{budget_text(ours)}: not comparable row by row"
                               + (f" (paper rows: {cite})" if cite else ""))
        records = store.records()
        planned = planned_ids(self.meta)
        self.unplanned = [r["trial"] for r in records
                          if planned is not None and r["trial"] not in planned]
        records = [r for r in records if planned is None or r["trial"] in planned]
        self.ok = [r for r in records if r.get("status") == "ok"]
        self.failed = [r for r in records if r.get("status") != "ok"]
        labels = self.meta.get("algorithms") or [a.get("label", a["name"])
                                                 for a in self.config["algorithms"]]
        self.labels = [lab for lab in labels if any(r["algorithm"] == lab for r in self.ok)]
        self.by_label: dict[str, list[dict]] = defaultdict(list)
        for r in sorted(self.ok, key=lambda r: (r["target"], r["run"])):
            self.by_label[r["algorithm"]].append(r)

    def values(self, label: str, key: str) -> np.ndarray:
        """``key`` of every ok record of ``label`` (missing/None as inf), target-major order."""
        return np.array([np.inf if r.get(key) is None else r[key] for r in self.by_label[label]],
                        dtype=float)

    def scalar_labels(self) -> list[str]:
        """The labels whose trials stored a final objective value (``best_f``): a
        multi-objective trial stores a front instead, and has none to summarise."""
        return [lab for lab in self.labels
                if any(r.get("best_f") is not None for r in self.by_label[lab])]

    def notes(self) -> list[str]:
        """Counts of finished and failed trials, then the config's ``paper["notes"]``."""
        planned = self.meta.get("trials")
        out = [f"{len(self.ok)} of {len(planned)} planned trials finished"
               if isinstance(planned, list) and planned else
               f"{len(self.ok)} trials finished (the number planned is unknown: meta.json "
               "lists no planned trials)"]
        if self.unplanned:
            shown = ", ".join(repr(t[:40]) for t in self.unplanned[:3])
            out.append(f"warning: {len(self.unplanned)} stored trial(s) that meta.json does not "
                       f"plan were left out ({shown}{', ...' if len(self.unplanned) > 3 else ''})")
        out += [f"about the paper's numbers: {n}" for n in self.paper.get("notes", [])]
        if self.citation != "paper" and self.paper_note:
            out.append(self.paper_note)
        if self.failed:
            out.append(f"{len(self.failed)} trials failed (status error), e.g. "
                       f"{self.failed[0]['trial']}: {self.failed[0].get('error')}")
        return out
