"""report_explorer: the interactive page of a results folder holds the report's own tables,
every stored front (one trace per algorithm and run) with its members' postures, and the
convergence curves of single-objective experiments."""

import json
import re

import numpy as np
import pytest

from moik.exceptions import ResultsError
from moik.experiments.analysis import analyze
from moik.experiments.config import ExperimentConfig
from moik.experiments.explorer import report_explorer
from moik.experiments.figures import benchmark_curves
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore
from moik.metrics.compromise import closest_to_utopia
from moik.robots import get_robot

pytest.importorskip("plotly", reason="the explorer needs plotly (the explorer extra)")

BI = {
    "name": "tiny-front", "title": "tiny bi-objective experiment", "source": "test",
    "robot": "eosma7-m", "problem": {"kind": "bi-objective", "orientation": "eosma-euler"},
    "targets": {"kind": "fixed", "points": [
        {"name": "P2", "position": [0.50, -0.25, 0.75], "euler_deg": [0, 0, 0],
         "convention": "eosma-euler", "hv_ref_point": [1.695669, 2.524178]}]},
    "algorithms": [{"name": "moeosma"}, {"name": "nsga2"}],
    "pop_size": 8, "archive_size": 8, "iterations": 3, "runs": 2, "seed": 5,
    "analyses": ["friedman-hv"],
}


def data(path) -> dict:
    text = path.read_text()
    return json.loads(re.search(r'id="moik-data">(.*?)</script>', text, re.S).group(1))


@pytest.fixture(scope="module")
def bi_results(tmp_path_factory):
    out = tmp_path_factory.mktemp("bi") / "tiny-front"
    run_experiment(ExperimentConfig.from_dict(BI), out=out, workers=1, progress=False)
    return out


def test_fronts_of_every_algorithm_and_run_with_their_postures(bi_results, tmp_path):
    page = report_explorer(bi_results, tmp_path / "r.html", posture_runs=1)
    panels = data(page)["panels"]
    front = panels[0]
    assert front["kind"] == "front"
    names = [t["name"] for t in front["traces"]]
    assert names == ["moeosma run 0", "moeosma run 1", "nsga2 run 0", "nsga2 run 1"]
    store = ResultStore.open(bi_results)
    robot = get_robot("eosma7-m")
    records = sorted(store.records(), key=lambda r: (r["algorithm"] != "moeosma", r["run"]))
    for trace, posture, rec in zip(front["traces"], front["postures"], records, strict=True):
        arrays = store.load_arrays(rec["trial"])
        np.testing.assert_array_equal(trace["F"], arrays["front_F"])
        if rec["run"] >= 1:
            assert posture is None  # posture_runs=1: run 0 only
            continue
        tip = np.array(posture["origins"])[:, -1]
        np.testing.assert_allclose(tip, robot.fk_position(arrays["front_X"]), atol=1e-5)
        # the stored first objective is the position error the page recomputes by FK
        np.testing.assert_allclose(posture["position_error"], arrays["front_F"][:, 0],
                                   rtol=1e-9, atol=1e-12)
    visible = [t["visible"] for t in front["figure"]["data"][:-1]]
    assert visible == [True, "legendonly", True, "legendonly"]
    # the page opens on the compromise of the first trace, as its note says
    assert front["initial"] == [0, closest_to_utopia(np.array(front["traces"][0]["F"]))]
    assert any("compromise" in note for note in front["notes"])
    # the front's eosma-euler axis and the details' geodesic angle are both explained
    assert any("Two orientation errors" in note and "eosma-euler" in note
               for note in front["notes"])


def test_the_tables_are_the_reports_own(bi_results, tmp_path):
    page = report_explorer(bi_results, tmp_path / "r.html")
    _, tables = analyze(ResultStore.open(bi_results))
    text = page.read_text()
    assert tables
    for table in tables:
        assert f"tiny-front: {table.title}" in text
        for row in table.rows:  # every formatted cell, in order, in one table row
            assert "".join(f">{c}</td>" for c in row[1:]) in re.sub(r'<td[^>]*>', ">", text)


def test_single_objective_results_get_their_convergence_curves(tmp_path, tiny_config):
    out = tmp_path / "tiny"
    run_experiment(tiny_config, out=out, workers=1, progress=False)
    panels = data(report_explorer(out))["panels"]
    curves = [p for p in panels if p["kind"] == "curves"]
    assert len(curves) == 1 and (out / "report.html").is_file()
    assert {t["name"].split(" ")[0] for t in curves[0]["figure"]["data"]} == {"eosma", "pso"}
    assert not [p for p in panels if p["kind"] == "front"]


def test_a_folder_without_results_is_an_error(tmp_path):
    with pytest.raises(ResultsError, match="holds no moik results"):
        report_explorer(tmp_path)


BENCH = {
    "name": "bench-test", "title": "tiny benchmark experiment", "source": "test",
    "problem": {"kind": "benchmark", "names": ["F1", {"name": "spring", "label": "spring"}],
                "params": {"n_var": 5}},
    "algorithms": [{"name": "ibes"}, {"name": "pso"}],
    "pop_size": 6, "iterations": 4, "runs": 2, "seed": 3,
    "analyses": ["per-target"], "proposed": "ibes",
}
MOO = {
    "name": "moo-test", "title": "tiny multi-objective benchmark experiment", "source": "test",
    "problem": {"kind": "moo-benchmark", "evaluations": 120, "names": [
        {"name": "zdt1", "params": {"n_var": 4}},
        {"name": "dtlz2", "label": "dtlz2-3", "params": {"n_var": 5, "n_obj": 3}}]},
    "algorithms": [{"name": "nsga2"}, {"name": "mogwo"}],
    "pop_size": 12, "iterations": 4, "runs": 1, "seed": 4,
    "analyses": ["front-quality"], "proposed": "nsga2",
}


def test_benchmark_functions_get_one_convergence_panel_per_problem(tmp_path):
    out = tmp_path / "bench"
    run_experiment(ExperimentConfig.from_dict(BENCH), out=out, workers=1, progress=False)
    res, _ = analyze(ResultStore.open(out))
    problems, _ = benchmark_curves(res)
    curves = [p for p in data(report_explorer(out))["panels"] if p["kind"] == "curves"]
    assert [p["title"] for p in curves] == [f"bench-test: mean convergence on {n}"
                                            for n in problems]
    assert problems  # F1's curves are finite and positive


def test_multi_objective_benchmarks_show_fronts_without_postures(tmp_path):
    out = tmp_path / "moo"
    run_experiment(ExperimentConfig.from_dict(MOO), out=out, workers=1, progress=False)
    fronts = [p for p in data(report_explorer(out))["panels"] if p["kind"] == "front"]
    assert len(fronts) == 2 and all(p["postures"] is None for p in fronts)
    assert fronts[1]["objectives"] == ["f1", "f2", "f3"]
    assert [t["name"] for t in fronts[0]["traces"]] == ["nsga2 run 0", "mogwo run 0"]


def test_a_collision_experiment_draws_the_geometry_its_trials_checked(tmp_path):
    """The obstacles and the arm's collision shapes: panda's compounds, the geometry
    solve_ik and the experiment's checker use (not the shipped capsules)."""
    from moik.collision.io import load_scene
    from moik.plotting.geometry import robot_meshes, scene_traces
    from moik.solver.collision import default_model

    scene = {"obstacles": [{"name": "shelf", "type": "box", "size": [0.3, 0.7, 0.02],
                            "xyz": [0.55, 0, 0.35]}]}
    cfg = ExperimentConfig.from_dict({
        "name": "tiny-collision", "title": "tiny collision experiment", "source": "test",
        "robot": "panda",
        "problem": {"kind": "bi-objective", "self_collision": True, "scene": scene},
        "targets": {"kind": "fixed", "points": [
            {"name": "T", "fk_q_deg": [0, -20, 0, -120, 0, 100, 45],
             "hv_ref_point": [1.5, 3.2]}]},
        "algorithms": [{"name": "nsga2"}], "pop_size": 8, "archive_size": 8,
        "iterations": 2, "runs": 1, "seed": 3, "analyses": ["collision"]})
    out = tmp_path / "tiny-collision"
    run_experiment(cfg, out=out, workers=1, progress=False)
    [front] = [p for p in data(report_explorer(out, tmp_path / "r.html"))["panels"]
               if p["kind"] == "front"]
    robot = get_robot("panda")
    assert front["robot_shapes"] == robot_meshes(default_model(robot))
    assert front["obstacles"] == scene_traces(load_scene(scene), span=robot.reach)
