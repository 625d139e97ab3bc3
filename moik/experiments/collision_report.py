"""The ``collision`` analysis: feasibility of the returned fronts of a collision-constrained
IK experiment (:mod:`moik.experiments.kinds.ik_collision` records it per trial).

Per target and algorithm: the share of returned members that are collision-free (their
minimum distance, recomputed from the returned joint values, is >= the clearance), the
share of runs that returned at least one, and the smallest distance over all returned
members (negative: penetration depth).
"""

from __future__ import annotations

import numpy as np

from moik.experiments.tables import Results, Table, fmt


def collision_table(res: Results) -> list[Table]:
    """Feasible shares and distances per target and algorithm."""
    names = [t.get("name") for t in res.store.meta.get("targets", [])]
    rows = []
    for ti, name in enumerate(names):
        for lab in res.labels:
            runs = [r for r in res.by_label[lab] if r["target"] == ti and "n_feasible" in r]
            if not runs:
                continue
            feas = np.array([r["n_feasible"] for r in runs], dtype=float)
            size = np.array([r["n_front"] for r in runs], dtype=float)
            rows.append([str(name), lab, f"{100 * feas.sum() / max(size.sum(), 1):.1f} %",
                         f"{100 * np.mean(feas > 0):.0f} %",
                         fmt(float(min(r["min_distance"] for r in runs)), 4), str(len(runs))])
    if not rows:
        return []
    return [Table("Collision-free members of the returned fronts",
                  ["target", "algorithm", "feasible members", "runs with a feasible member",
                   "smallest distance", "runs"], rows,
                  ["distances recomputed from the returned joint values with the compiled "
                   "checker (moik.collision); HV counts the feasible members only"])]


FUNCTIONS = {"collision": collision_table}
