"""The ``reference-front`` analysis: bi-objective IK runs measured against the true front.

For an IK experiment with a ``bi-objective`` problem (EOSMA Table 8's poses), per target
the reference front (:meth:`moik.problems.BiObjectiveIK.reference_front`, shipped for the
registered poses, else computed once and cached) and, per algorithm over its runs: the
mean HV (the target's ``hv_ref_point``, else the box of the reference front and the
runs), that HV as a share of the reference front's HV, and pymoo's IGD+ to the reference
front (mean, std, best run). The notes give the reference front's HV and the best run of
any algorithm.
"""

from __future__ import annotations

import numpy as np
from pymoo.indicators.igd_plus import IGDPlus

from moik.experiments.kinds.ik_robot import experiment_robot
from moik.experiments.tables import Results, Table, fmt
from moik.metrics import hypervolume
from moik.problems import BiObjectiveIK


def _front(res: Results, target: dict) -> np.ndarray | None:
    problem = res.config["problem"]
    if problem.get("kind") != "bi-objective" or target.get("rotation") is None or \
            problem.get("displacement_weight", 0.0):
        return None
    robot = experiment_robot(target.get("robot") or res.robot, problem)
    ik = BiObjectiveIK(robot, (np.asarray(target["position"]), np.asarray(target["rotation"])),
                       orientation=problem.get("orientation", "geodesic"))
    return ik.pareto_front()


def reference_front_table(res: Results) -> list[Table]:
    """HV share of the reference front and IGD+ to it, per target and algorithm."""
    tables = []
    for ti, target in enumerate(res.meta["targets"]):
        front = _front(res, target)
        if front is None:
            continue
        stored = {lab: [res.store.load_arrays(r["trial"]).get("front_F")
                        for r in res.by_label[lab] if r["target"] == ti] for lab in res.labels}
        runs: dict[str, list[np.ndarray]] = {
            lab: [np.atleast_2d(F) for F in Fs if F is not None] for lab, Fs in stored.items()}
        if target.get("hv_ref_point") is not None:
            ref = np.asarray(target["hv_ref_point"], dtype=float)
        else:
            ref = 1.1 * np.max([front.max(axis=0)] + [F.max(axis=0) for Fs in runs.values()
                                                      for F in Fs], axis=0)
        ref_hv = hypervolume(front, ref)
        igd = IGDPlus(front)
        rows, best = [], (-np.inf, "-")
        for lab, Fs in runs.items():
            if not Fs:
                continue
            hv = np.array([hypervolume(F, ref) for F in Fs])
            d = np.array([float(igd(F)) for F in Fs])
            best = max(best, (float(hv.max()), lab))
            rows.append([lab, str(len(Fs)), fmt(float(hv.mean()), 6),
                         f"{100 * hv.mean() / ref_hv:.3f} %" if ref_hv > 0 else "-",
                         fmt(float(d.mean()), 4), fmt(float(d.std()), 3), fmt(float(d.min()), 4)])
        rows.sort(key=lambda row: float(row[4]))
        notes = [f"reference front: {len(front)} points, HV {fmt(ref_hv, 6)} (reference point "
                 f"{np.round(ref, 6).tolist()}); best run of any algorithm: HV "
                 f"{fmt(best[0], 6)} ({best[1]})",
                 "IGD+: pymoo's IGDPlus to the reference front (moik.fronts); share: mean HV "
                 "over the reference front's HV"]
        tables.append(Table(f"Against the reference front at {target['name']}",
                            ["algorithm", "runs", "HV mean", "share of the reference HV",
                             "IGD+ mean", "IGD+ std", "IGD+ best"], rows, notes))
    return tables


FUNCTIONS = {"reference-front": reference_front_table}
"""Analysis name -> table function."""
