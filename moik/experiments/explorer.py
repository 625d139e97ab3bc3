"""``moik report RESULTS --html``: the report of stored results as an interactive page.

Per results folder (as :func:`moik.experiments.report.result_folders` finds them):
the fronts of every algorithm and run at each target, linked to the postures behind
their points (multi-objective IK experiments store each trial's ``front_F`` and
``front_X``; a multi-objective benchmark's fronts have no posture), with a collision
experiment's obstacles and the arm's collision shapes at each posture, the geometry its
trials checked (:func:`moik.experiments.kinds.ik_collision.checker_of`: a compound as its
convex parts); the mean
convergence curves the report's figures draw (single-objective experiments store a
``convergence`` array per trial: IK ones pooled as the report's ``_curves``,
benchmark-function ones one panel per problem as
:func:`moik.experiments.figures.benchmark_curves`); and the report's tables, from the
same :func:`moik.experiments.analysis.analyze` the Markdown report prints. Statistics
are never recomputed here. The page is written by
:func:`moik.plotting.explorer.write_explorer` (plotly, the ``explorer`` extra).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from moik._paths import inside
from moik.experiments.analysis import analyze
from moik.experiments.figures import (
    _curves,
    benchmark_curves,
    objective_label,
    orientation_unit,
)
from moik.experiments.kinds.ik_collision import checker_of, is_checked
from moik.experiments.kinds.ik_robot import arm
from moik.experiments.report import FOLDER_ERRORS, damaged_warning, result_folders
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results
from moik.metrics.compromise import closest_to_utopia
from moik.plotting.explorer import CurvePanel, Front, FrontPanel, TablePanel, write_explorer
from moik.plotting.geometry import robot_meshes, scene_traces
from moik.problems.targets import Target


def _target(t: dict):
    rot = t.get("rotation")
    return Target(np.asarray(t["position"], dtype=float),
                  None if rot is None else np.asarray(rot, dtype=float))


def front_panels(res: Results, *, posture_runs: int | None = 3) -> list[FrontPanel]:
    """One panel per target: a trace per (algorithm, run) holding its stored front.

    Args:
        res: The grouped records of one results folder.
        posture_runs: Runs (0, 1, ...) whose members carry their postures (each
            member adds about 1 kB to the page); ``None``: every run. Traces of the
            first run are shown, the others one legend click away.
    """
    cfg = res.config
    kind = cfg["problem"]["kind"]
    if kind not in ("bi-objective", "moo-benchmark"):
        return []  # single-objective trials store no front
    robot = arm(res.robot) if kind == "bi-objective" else None
    unit = robot.unit if robot is not None else ""
    metric_note = []
    if robot is not None:
        metric = cfg["problem"].get("orientation", "geodesic")
        if metric != "geodesic":
            metric_note = [f"Two orientation errors: the front's axis is the experiment's "
                           f"metric, {metric} (the paper's); a member's details give the "
                           "geodesic angle of the same rotation error, recomputed by forward "
                           "kinematics. They differ: an Euler-angle error compares three "
                           "angles, the geodesic angle is the one rotation between the two "
                           "frames."]
        axes = [f"position error ({unit})", f"{metric} orientation error "
                f"({orientation_unit(metric)})"]
    obstacles: list[dict] = []
    shapes: list[dict] = []
    if robot is not None and is_checked(cfg["problem"]):
        checker = checker_of(robot, cfg["problem"])
        shapes = robot_meshes(checker.model)
        if checker.scene is not None:
            obstacles = scene_traces(checker.scene, span=robot.reach)
    panels = []
    for ti, t in enumerate(res.meta["targets"]):
        fronts = []
        for lab in res.labels:
            for r in (r for r in res.by_label[lab] if r["target"] == ti):
                arrays = res.store.load_arrays(r["trial"])
                if "front_F" not in arrays or not len(arrays["front_F"]):
                    continue
                with_x = posture_runs is None or r["run"] < posture_runs
                fronts.append(Front(f"{lab} run {r['run']}", arrays["front_F"],
                                    arrays.get("front_X") if with_x else None, group=lab,
                                    visible=r["run"] == 0))
        if not fronts:
            continue
        m = fronts[0].F.shape[1]
        names = axes if robot is not None and m == 2 else [f"f{k + 1}" for k in range(m)]
        kept = ("every run" if posture_runs is None else
                f"runs below {posture_runs} (report_explorer(..., posture_runs=None): all)")
        panels.append(FrontPanel(
            title=f"{cfg['name']}: fronts at {t['name']} (one trace per algorithm and run)",
            fronts=fronts, objectives=names, robot=robot,
            target=_target(t) if robot is not None else None,
            initial=(0, closest_to_utopia(fronts[0].F)), obstacles=obstacles,
            robot_shapes=shapes,
            notes=[f"{len(fronts)} fronts; run 0 of each algorithm shown, the others in the "
                   f"legend; postures embedded for {kept}. The member shown first is the "
                   f"compromise (closest to the utopia point) of {fronts[0].name}.",
                   *metric_note]))
    return panels


def folder_panels(store: ResultStore, *, posture_runs: int | None = 3) -> list:
    """The panels of one results folder: fronts, convergence curves, the report's tables."""
    res, tables = analyze(store)
    panels: list = front_panels(res, posture_runs=posture_runs)
    kind = res.config["problem"]["kind"]
    name = res.config["name"]
    if kind == "benchmark":  # one panel per problem, as the report's figure
        problems, shifted = benchmark_curves(res) if res.ok else ({}, set())
        for problem, by_label in problems.items():
            what = "f - f*" if problem in shifted else "best f"
            panels.append(CurvePanel(f"{name}: mean convergence on {problem}", by_label,
                                     ylabel=f"mean {what} (function value)",
                                     notes=["Mean over the runs, as the report's figure."]))
    curves = _curves(res, res.labels) if res.ok and kind != "benchmark" else {}
    if curves:
        ylabel = "mean best objective"
        if kind in ("position", "pose"):
            unit = arm(res.robot).unit
            ylabel += f" ({objective_label(res.config['problem'], unit)[0]})"
        panels.append(CurvePanel(f"{res.config['name']}: mean convergence curves", curves,
                                 ylabel=ylabel, notes=["Mean over every target and run, as "
                                                       "the report's convergence figure."]))
    notes = res.notes() + ([f"warning: {damaged_warning(store)}"] if store.damaged else [])
    for k, table in enumerate(tables):
        panels.append(TablePanel(f"{res.config['name']}: {table.title}", table.header,
                                 table.rows, list(table.notes) + (notes if k == 0 else [])))
    return panels


def report_explorer(folder: str | Path, path: str | Path | None = None, *,
                    posture_runs: int | None = 3) -> Path:
    """Write the interactive report of ``folder`` (default ``folder/report.html``).

    Args:
        folder: A results folder or a folder of results folders.
        path: The HTML file.
        posture_runs: See :func:`front_panels`.

    Returns:
        The path written.

    Raises:
        ResultsError: ``folder`` holds no results.
        ParameterError: plotly is not installed.
    """
    base = Path(folder)
    out = Path(path) if path is not None else base / "report.html"
    if path is None:
        inside(base, out)
    panels, notes = [], []
    for sub in result_folders(base):
        try:
            store = ResultStore.open(sub, verify=True)
            panels += folder_panels(store, posture_runs=posture_runs)
            meta = store.meta
            notes.append(f"{meta['config']['name']}: {meta['config']['title']} "
                         f"({'quick' if meta.get('quick') else 'full'} size), source "
                         f"{meta['config']['source']}; results folder {sub}")
        except FOLDER_ERRORS as exc:
            why = f"{exc.__class__.__name__}: {exc}"
            print(f"moik: warning: {sub} not reported: {why}", file=sys.stderr)
            notes.append(f"{sub} could not be read or analysed: {why}")
    if not panels:
        panels = [TablePanel("nothing to show", ["folder", "why"], [[n, ""] for n in notes])]
    return write_explorer(out, panels, title="moik reproduction report", notes=notes)
