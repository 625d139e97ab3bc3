"""pareto_explorer / write_explorer: one self-contained page, its data built from the
robot's FK, and clear errors for what it cannot show. (In a browser:
test_explorer_browser.py.)"""

import json
import re
import sys

import numpy as np
import pytest

from moik import get_robot, solve_ik, solve_ik_pareto
from moik.exceptions import ParameterError, ShapeError
from moik.plotting import pareto_explorer, write_explorer
from moik.plotting.explorer import CurvePanel, Front, FrontPanel, TablePanel
from moik.problems import Target

pytest.importorskip("plotly", reason="the explorer needs plotly (the explorer extra)")


def page_data(path) -> dict:
    text = path.read_text()
    return json.loads(re.search(r'id="moik-data">(.*?)</script>', text, re.S).group(1))


@pytest.fixture(scope="module")
def panda():
    return get_robot("panda")


@pytest.fixture
def members(panda):
    rng = np.random.default_rng(3)
    X = panda.random_q(12, rng=rng)
    F = np.column_stack([np.linspace(0, 1, 12), np.linspace(1, 0, 12) ** 2])
    return X, F


def test_one_self_contained_file_with_plotly_inline_once(tmp_path, panda, members):
    X, F = members
    box = {"type": "mesh3d", "x": [0, 1, 0], "y": [0, 0, 1], "z": [0, 0, 0], "name": "obstacle"}
    path = pareto_explorer({"X": X, "F": F, "objectives": ["a", "b"]}, panda,
                           tmp_path / "p.html", target=panda.fk(X[0]), obstacles=[box])
    assert page_data(path)["panels"][0]["obstacles"] == [box]  # drawn in every posture
    text = path.read_text()
    from plotly.offline import get_plotlyjs

    assert text.count(get_plotlyjs()) == 1
    # no external script, style sheet, image or frame: nothing is fetched
    assert not re.search(r"<(script|link|img|iframe)[^>]*(src|href)\s*=", text, re.I)
    assert len(re.findall(r"<script", text)) == 3  # plotly.js, the data, the page's script


def test_a_scenes_obstacles_are_drawn_in_every_posture(tmp_path, panda, members):
    from moik.collision import Box, HalfSpace, Scene
    from moik.plotting.geometry import scene_traces

    X, F = members
    scene = Scene({"table": HalfSpace(), "shelf": Box(size=(0.3, 0.7, 0.02))})
    extra = {"type": "mesh3d", "x": [0, 1, 0], "y": [0, 0, 1], "z": [0, 0, 0], "name": "mine"}
    path = pareto_explorer({"X": X, "F": F}, panda, tmp_path / "p.html", scene=scene,
                           obstacles=[extra])
    drawn = page_data(path)["panels"][0]["obstacles"]
    assert drawn == [*scene_traces(scene, span=panda.reach), extra]
    assert [t["name"] for t in drawn] == ["table", "shelf", "mine"]
    assert "obstacles grey" in page_data(path)["panels"][0]["scene_layout"]["title"]["text"]
    plain = pareto_explorer({"X": X, "F": F}, panda, tmp_path / "q.html")
    assert "obstacles" not in page_data(plain)["panels"][0]["scene_layout"]["title"]["text"]


def test_postures_come_from_the_robots_frames(tmp_path, panda, members):
    X, F = members
    target = Target(panda.fk(X[4])[:3, 3], panda.fk(X[4])[:3, :3])
    panel = page_data(pareto_explorer({"X": X, "F": F}, panda, tmp_path / "p.html",
                                      target=target))["panels"][0]
    P = panel["postures"][0]
    frames = panda.frames(X)
    np.testing.assert_allclose(P["origins"], frames[:, :, :3, 3], atol=1e-5)
    np.testing.assert_allclose(P["rotations"], frames[:, :, :3, :3], atol=1e-5)
    np.testing.assert_array_equal(P["q"], X)
    assert P["position_error"][4] < 1e-12 and P["orientation_error"][4] < 1e-7
    assert P["position_error"][0] > 1e-3
    assert panel["joint_names"] == list(panda.joint_names)
    # panda's joints 1 and 2 are at one place: one label, as plot_robot writes it
    assert P["joint_labels"][0][:3] == ["1,2", "", "3"]
    assert panel["traces"][0]["size"] == 12 and panel["initial"] == [0, 0]
    assert panel["objectives"] == ["f1 (smaller is better)", "f2 (smaller is better)"]


def test_a_pareto_solve_starts_at_its_compromise(tmp_path, panda):
    q0 = np.array([0.0, -0.3, 0.0, -2.0, 0.0, 1.8, 0.8])
    T = panda.fk(q0 + 0.2)
    res = solve_ik_pareto(panda, T, q_current=q0, n_solutions=8, starts=16, pop_size=10,
                          generations=2, local_iterations=1, seed=1)
    panel = page_data(pareto_explorer(res, panda, tmp_path / "p.html", target=T))["panels"][0]
    assert panel["initial"] == [0, res.compromise_index()]
    np.testing.assert_array_equal(panel["traces"][0]["F"], res.F)
    assert panel["objectives"][1] == "manipulability (larger is better)"
    assert max(panel["postures"][0]["position_error"]) < 1e-6


def test_several_fronts_and_the_other_panels(tmp_path, panda, members):
    X, F = members
    fronts = [Front("a run 0", F, X, group="a"), Front("a run 1", F + 0.1, None, group="a",
                                                        visible=False)]
    path = write_explorer(tmp_path / "p.html", [
        FrontPanel("fronts", fronts, ["x", "y"], robot=panda, target=panda.fk(X[0])[:3, 3]),
        CurvePanel("curves", {"alg": np.array([[3.0, 2.0, 1.0], [4.0, 2.0, 0.5]])}, "f"),
        TablePanel("stats", ["algorithm", "HV"], [["a", "0.5<1"]])], title="t")
    panels = page_data(path)["panels"]
    assert [p["kind"] for p in panels] == ["front", "curves", "table"]
    assert panels[0]["postures"][1] is None
    assert panels[0]["figure"]["data"][1]["visible"] == "legendonly"
    assert panels[1]["figure"]["layout"]["yaxis"]["type"] == "log"
    assert "<td>0.5&lt;1</td>" in path.read_text()


def test_bad_input_is_refused_clearly(tmp_path, panda, members):
    X, F = members
    with pytest.raises(ShapeError, match=r"members of 'Pareto set' must have shape \(12, n\)"):
        pareto_explorer({"X": X[:3], "F": F}, panda, tmp_path / "p.html")
    with pytest.raises(ShapeError, match="same criteria"):
        pareto_explorer({"a": {"F": F}, "b": {"F": F, "objectives": ["u", "v"]}}, panda,
                        tmp_path / "p.html")
    with pytest.raises(ParameterError, match="must be a ParetoIKResult"):
        pareto_explorer([1, 2], panda, tmp_path / "p.html")
    with pytest.raises(ParameterError, match="at least one panel"):
        write_explorer(tmp_path / "p.html", [], title="t")
    with pytest.raises(ShapeError, match="at least 2 criteria"):
        write_explorer(tmp_path / "p.html", [FrontPanel("f", [Front("a", F[:, :1])], ["x"])],
                       title="t")


def test_without_plotly_the_error_says_how_to_install_it(tmp_path, panda, members, monkeypatch):
    monkeypatch.setitem(sys.modules, "plotly", None)
    monkeypatch.setitem(sys.modules, "plotly.graph_objects", None)
    with pytest.raises(ParameterError, match=r"pip install -e '\.\[explorer\]'"):
        pareto_explorer({"F": members[1]}, panda, tmp_path / "p.html")


def test_an_unreachable_solve_ik_shows_its_front(tmp_path):
    robot = get_robot("eosma7-m")
    T = np.eye(4)
    T[:3, 3] = [-0.25, 1.0, 0.5]  # EOSMA's P1, out of reach
    res = solve_ik(robot, T, seed=0)
    assert res.status == "unreachable"
    panel = page_data(pareto_explorer(res, robot, tmp_path / "p.html", target=T))["panels"][0]
    np.testing.assert_array_equal(panel["traces"][0]["F"], res.front)
    assert panel["objectives"][0] == "position error (m)"
    assert panel["traces"][0]["name"] == "error front"
    np.testing.assert_array_equal(res.front_q[panel["initial"][1]], res.q)  # the compromise
    # the front's errors are the ones the page recomputes by FK (geodesic, as solve_ik's)
    np.testing.assert_allclose(panel["postures"][0]["position_error"], res.front[:, 0],
                               rtol=1e-9)
    np.testing.assert_allclose(panel["postures"][0]["orientation_error"], res.front[:, 1],
                               rtol=1e-6, atol=1e-9)
    solved = solve_ik(robot, robot.fk(np.full(7, 0.3)), seed=0)
    with pytest.raises(ParameterError, match="has no front .status 'solved'"):
        pareto_explorer(solved, robot, tmp_path / "p.html")


def test_the_joint_limits_carry_their_units(tmp_path):
    """The members' joint tables label the limit columns and give each limit in the
    value's unit (rad, or the robot's unit for a prismatic joint) and in degrees."""
    robot = get_robot("panda")
    X = robot.random_q(3, rng=np.random.default_rng(0))
    F = np.column_stack([np.arange(3.0), -np.arange(3.0)])
    page = pareto_explorer({"F": F, "X": X}, robot, tmp_path / "p.html").read_text()
    assert "<th>lower limit</th><th>upper limit</th>" in page
    assert "fmt(v) + unit" in page and "' deg)'" in page


def test_the_collision_geometry_is_drawn_at_every_posture(tmp_path, panda, members):
    """collision= a checker: the arm's shapes (panda's compounds, as their convex parts) in
    their bodies' frames, which the page moves by each posture's frames, and the checker's
    obstacles; a model of another arm, or not a model, is refused."""
    from moik.collision import Box, CollisionChecker, Scene
    from moik.plotting.geometry import robot_meshes, scene_traces
    from moik.solver.collision import default_model

    X, F = members
    model = default_model(panda)
    checker = CollisionChecker(model=model, scene=Scene({"shelf": Box(size=(0.3, 0.7, 0.02))}),
                               self_collision=True)
    panel = page_data(pareto_explorer({"X": X, "F": F}, panda, tmp_path / "p.html",
                                      collision=checker))["panels"][0]
    assert panel["robot_shapes"] == robot_meshes(model)
    assert {s["frame"] for s in panel["robot_shapes"]} == {b for b, _ in model.items}
    assert panel["obstacles"] == scene_traces(checker.scene, span=panda.reach)
    assert "collision shapes blue" in panel["scene_layout"]["title"]["text"]
    alone = page_data(pareto_explorer({"X": X, "F": F}, panda, tmp_path / "q.html",
                                      collision=model))["panels"][0]
    assert alone["robot_shapes"] == panel["robot_shapes"] and alone["obstacles"] == []
    with pytest.raises(ParameterError, match="geometry of robot 'ur5'"):
        pareto_explorer({"X": X, "F": F}, panda, tmp_path / "r.html",
                        collision=default_model(get_robot("ur5")))
    with pytest.raises(ParameterError, match="collision must be a CollisionModel or a "
                                             "CollisionChecker, got str"):
        pareto_explorer({"X": X, "F": F}, panda, tmp_path / "r.html", collision="panda")
