"""The papers' figures drawn from a results folder with :mod:`moik.plotting`.

Which figures an experiment gets follows its analyses: random-target summaries
get the targets (EOSMA Figs. 7, 12), mean convergence (Figs. 8, 13), solve
times (Figs. 9, 14) and error boxes (Figs. 10, 15); ``ranksum`` the p-value bars
(Figs. 11, 16); ``friedman-hv`` the fronts at each pose (Figs. 17-18);
``joint-motion`` the quintic motion (Fig. 20); ``compromise`` the tracked
circle (MO-m-PSO Fig. 7) or the front with its compromise (Fig. 5a);
``signed-rank`` convergence and errors (MO-m-PSO Fig. 8); ``per-target``
with several algorithms and targets the final errors per target (I-BES Figs.
8-13, one figure per arm). Benchmark experiments get the mean convergence of
every problem on one grid (MChOA Fig. 5), as the error ``f - f*`` where the
optimum is known. Files go to
``OUT/figures/NAME.png`` and ``.pdf``. A figure that cannot be drawn is skipped
with a note; drawing never fails the report.

Every axis says its unit: objective values carry the objective's formula and
units (:func:`objective_label`; Eq. 28 adds metres to radians, and the label says
so), orientation errors the metric's unit. The config's ``proposed`` algorithm
(else its first one: the configs list the paper's method first) is emphasised
in every figure that compares algorithms.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from pathlib import Path

import numpy as np

import moik.plotting as mp
from moik._paths import file_name, inside
from moik.exceptions import MoikError
from moik.experiments.kinds.ik_robot import arm
from moik.experiments.tables import Results
from moik.metrics import ranksum_pvalues


def _curves(res: Results, labels) -> dict[str, np.ndarray]:
    out = {}
    for lab in labels:
        found = [res.store.load_arrays(r["trial"]).get("convergence")
                 for r in res.by_label[lab]]
        runs = [c for c in found if c is not None and c.size]
        if runs:
            n = min(c.size for c in runs)
            out[lab] = np.array([c[:n] for c in runs])
    return out


def _per_target(res: Results, lab: str, key: str) -> np.ndarray:
    n_t = len(res.meta["targets"])
    vals = [[r[key] for r in res.by_label[lab] if r["target"] == t] for t in range(n_t)]
    return np.array([np.mean(v) if v else np.nan for v in vals])


def orientation_unit(metric: str) -> str:
    """Unit of an orientation metric's values (the Frobenius norm has none)."""
    return "dimensionless" if metric == "frobenius" else "rad"


def objective_label(problem: dict, unit: str) -> tuple[str, str]:
    """``(units, formula)`` of a single-objective IK problem's objective value.

    E.g. ``("m", "position error (m)")`` or ``("m and rad added", "0.5 x position
    error (m) + 0.5 x eosma-euler orientation error (rad)")``.
    """
    kind, metric = problem["kind"], problem.get("orientation", "geodesic")
    o_unit = orientation_unit(metric)
    if kind == "pose":
        w1, w2 = problem.get("weights", (0.5, 0.5))
        formula = (f"{w1:g} x position error ({unit}) + {w2:g} x {metric} orientation error "
                   f"({o_unit})")
        units = {unit, o_unit}
    else:
        formula, units = f"position error ({unit})", {unit}
    w = float(problem.get("displacement_weight", 0.0))
    if w > 0:
        formula += f" + {w:g} x joint distance (rad)"
        units.add("rad")
    units.discard("dimensionless")
    text = " and ".join(sorted(units)) + (" added" if len(units) > 1 else "")
    return text, formula


def benchmark_curves(res: Results) -> tuple[dict[str, dict[str, np.ndarray]], set[str]]:
    """Convergence curves ``{problem: {algorithm: (runs, n)}}`` of a benchmark experiment,
    as ``f - f*`` where the optimum is known (those problems' names in the set); a problem
    with a non-finite or negative curve is left out (it cannot go on a log axis)."""
    panels, shifted = {}, set()
    for ti, target in enumerate(res.meta["targets"]):
        curves = {}
        for lab in res.labels:
            recs = [r for r in res.by_label[lab] if r["target"] == ti]
            found = [res.store.load_arrays(r["trial"]).get("convergence") for r in recs]
            runs = [c for c in found if c is not None and c.size]
            if not runs:
                continue
            n = min(c.size for c in runs)
            f_opt = recs[0].get("f_opt")
            C = np.array([c[:n] for c in runs])
            if f_opt is not None and np.isfinite(f_opt):
                C = np.maximum(C - f_opt, 0.0)
                shifted.add(target["name"])
            curves[lab] = C
        if curves and all(np.all(np.isfinite(c)) and np.all(c >= 0) for c in curves.values()):
            panels[target["name"]] = curves
    return panels, shifted


def _benchmark_plans(res: Results) -> list[tuple[str, str, Callable]]:
    """The mean convergence of every benchmark problem, one panel each."""
    panels, shifted = benchmark_curves(res)
    if not panels:
        return []
    proposed = res.config.get("proposed") or res.labels[0]
    what = ("f - f* (best value found minus the known optimum)" if shifted
            else "best value found")
    return [("convergence", "Mean convergence per problem", lambda s: mp.plot_convergence_panels(
        panels, ylabel=f"mean best {('f - f*' if shifted else 'f')} (function value)",
        title=f"Mean convergence over the runs: {what}; x = iteration", proposed=proposed,
        save=s))]


def _error_boxes_per_target(res: Results, formula: str, units: str, proposed
                            ) -> list[tuple[str, str, Callable]]:
    """Final objective per algorithm at each target (I-BES Figs. 8-13), one figure each."""
    plans = []
    for ti, target in enumerate(res.meta["targets"]):
        errors = {lab: np.array([r["best_f"] for r in res.by_label[lab] if r["target"] == ti
                                 and r.get("best_f") is not None]) for lab in res.labels}
        errors = {lab: e for lab, e in errors.items() if e.size}
        if len(errors) < 2:
            continue
        name = target["name"]
        plans.append((f"errors-{name}", f"Final {formula} at {name}, every run",
                      lambda s, e=errors, n=name: mp.plot_error_boxes(
                          e, ylabel=f"final {formula}", proposed=proposed,
                          title=f"{n}: final objective over the runs ({units})", save=s)))
    return plans


def _plans(res: Results) -> list[tuple[str, str, Callable]]:
    """(file stem, caption, draw(save_stem)) of every figure that applies."""
    cfg, labels = res.config, res.labels
    plans: list[tuple[str, str, Callable]] = []
    if cfg["problem"]["kind"] == "benchmark":
        return _benchmark_plans(res)
    robot = arm(res.robot)
    unit = robot.unit
    proposed = cfg.get("proposed") or (res.meta.get("algorithms") or [None])[0]
    units, formula = objective_label(cfg["problem"], unit)
    analyses = cfg.get("analyses", [])
    targets = res.meta["targets"]
    pos = np.array([t["position"] for t in targets])
    rot = (np.array([t["rotation"] for t in targets])
           if all(t["rotation"] is not None for t in targets) else None)
    if ("summary" in analyses or "signed-rank" in analyses) and len(targets) > 1:
        plans.append(("targets", "Targets in the workspace", lambda s: mp.plot_targets(
            pos, rot, unit=unit, save=s)))
    if "summary" in analyses or "signed-rank" in analyses:
        curves = _curves(res, labels)
        if curves:
            plans.append(("convergence", "Mean convergence curves", lambda s: mp.plot_convergence(
                curves, ylabel=f"mean best objective ({units})", proposed=proposed,
                title="Mean convergence\n" + textwrap.fill(f"f = {formula}", 56), save=s)))
        errors = {lab: np.nan_to_num(res.values(lab, "best_f"), posinf=1e300) for lab in labels}
        plans.append(("errors", "Final objective values", lambda s: mp.plot_error_boxes(
            errors, ylabel=f"final objective ({units})", proposed=proposed,
            title="Final objective values\n" + textwrap.fill(f"f = {formula}", 56), save=s)))
    if "per-target" in analyses and len(targets) > 1 and len(labels) > 1:
        plans += _error_boxes_per_target(res, formula, units, proposed)
    if "summary" in analyses and len(targets) > 1:
        times = {lab: _per_target(res, lab, "time") for lab in labels}
        plans.append(("times", "Solve time per target", lambda s: mp.plot_solve_times(
            times, ylabel="solve time per target, mean over runs (s)", proposed=proposed,
            save=s)))
    if "ranksum" in analyses:
        samples = {lab: np.nan_to_num(res.values(lab, "best_f"), posinf=1e300) for lab in labels}
        if cfg["proposed"] in samples and len(samples) > 1:
            pv = ranksum_pvalues(samples, cfg["proposed"])
            plans.append(("wilcoxon", "Wilcoxon rank-sum p-values", lambda s: mp.plot_wilcoxon(
                pv, proposed=cfg["proposed"], save=s)))
    mo = cfg["problem"]["kind"] == "bi-objective"
    if mo and ("friedman-hv" in analyses or len(targets) == 1):
        for ti, t in enumerate(targets):
            fronts = {}
            for lab in labels:
                recs = [r for r in res.by_label[lab] if r["target"] == ti]
                if recs:
                    fronts[lab] = res.store.load_arrays(recs[0]["trial"])["front_F"]
            comp = None
            if len(fronts) == 1:
                r0 = [r for r in res.by_label[labels[0]] if r["target"] == ti][0]
                comp = [r0["position_error"], r0["orientation_error"]]
            if fronts:
                metric = cfg["problem"].get("orientation", "geodesic")
                ylabel = f"{metric} orientation error ({orientation_unit(metric)})"
                plans.append((f"front-{ti}", f"Pareto fronts at {t['name']} (first run)",
                              lambda s, f=fronts, c=comp, n=t["name"], y=ylabel:
                              mp.plot_pareto_fronts(
                                  f, compromise=c, xlabel=f"position error ({unit})", ylabel=y,
                                  title=f"PF at {n}", proposed=proposed, save=s)))
    if "joint-motion" in analyses and labels:
        best = {lab: min(res.by_label[lab], key=lambda r: r["best_f"])["best_x"]
                for lab in labels}
        q0 = np.radians(cfg["problem"]["q_start_deg"])
        first, others = labels[0], {lab: best[lab] for lab in labels[1:]}
        plans.append(("motion", "Motion from the start to the solutions", lambda s:
                      mp.plot_motion(robot, q0, best[first], label=first, others=others or None,
                                     target=pos[0], proposed=proposed, save=s)))
        best_run = min(res.by_label[first], key=lambda r: r["best_f"])
        history = res.store.load_arrays(best_run["trial"]).get("best_x_history")
        if history is not None and len(history):
            plans.append(("joint-history", f"Best candidate joint angles of {first} per "
                          "iteration (its best run)", lambda s, h=history: mp.plot_joint_history(
                              h, prismatic=robot.is_prismatic, unit=unit,
                              title=f"Best candidate joint angles ({first})", save=s)))
    if "compromise" in analyses and cfg["targets"]["kind"] == "circle" and labels:
        lab = labels[0]
        first_runs = {r["target"]: r for r in res.by_label[lab] if r["run"] == 0}
        if len(first_runs) == len(targets):
            Q = np.array([first_runs[t]["best_x"] for t in range(len(targets))])
            ori = np.array([first_runs[t]["orientation_error"] for t in range(len(targets))])
            plans.append(("path", f"Circle tracked by {lab}", lambda s: mp.plot_path_tracking(
                pos, robot.fk_position(Q), orientation_errors=ori, Q=Q,
                prismatic=robot.is_prismatic, unit=unit, log=True, save=s)))
    return plans


def make_figures(res: Results, folder: Path) -> tuple[list[tuple[str, Path]], list[str]]:
    """Draw the figures into ``folder``; returns ``[(caption, png path)]`` and notes.

    matplotlib is imported here, not at module level: only drawing needs it.
    """
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        plans = _plans(res)
    except (ImportError, AttributeError) as exc:
        return [], [f"figures skipped: matplotlib is not available ({exc})"]
    except MoikError as exc:
        return [], [f"figures skipped: {exc}"]
    folder.mkdir(parents=True, exist_ok=True)
    made, notes = [], []
    for stem, caption, draw in plans:
        try:
            for suffix in (".png", ".pdf"):  # never drawn through a link planted there
                inside(folder, folder / (file_name(stem, "figure name") + suffix))
            draw(str(folder / stem))
            made.append((caption, folder / f"{stem}.png"))
        except (MoikError, ValueError, KeyError, IndexError) as exc:
            notes.append(f"figure {stem!r} skipped: {exc}")
        finally:
            plt.close("all")
    return made, notes
