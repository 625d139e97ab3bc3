"""``--html``: ``moik solve ... --pareto ... --html FILE``, ``moik solve`` of an unreachable
pose with ``--html FILE`` (its error front), ``moik report DIR --html [FILE]``."""

import json
import re

import numpy as np
import pytest

from moik.cli.main import main
from moik.experiments.config import ExperimentConfig
from moik.experiments.runner import run_experiment
from moik.kinematics.orientation import zyx_euler
from moik.problems import random_reachable_targets
from moik.robots import get_robot

pytest.importorskip("plotly", reason="the explorer needs plotly (the explorer extra)")


def page_data(path) -> dict:
    text = path.read_text()
    return json.loads(re.search(r'id="moik-data">(.*?)</script>', text, re.S).group(1))


def test_pareto_html(tmp_path, capsys):
    robot = get_robot("iiwa14")
    pose = random_reachable_targets(robot, 1, seed=11)[0]
    out = tmp_path / "pareto.html"
    argv = ["solve", "iiwa14", "--target", *map(str, pose.position), "--euler",
            *map(str, np.degrees(zyx_euler(pose.rotation))), "--deg", "--q-current",
            *map(str, np.degrees(pose.q_source + 0.1)), "--pareto",
            "joint_motion,manipulability", "--pareto-size", "6", "--html", str(out)]
    assert main(argv) == 0
    assert f"explorer written to {out}" in capsys.readouterr().out
    panel = page_data(out)["panels"][0]
    assert panel["traces"][0]["size"] <= 6 and panel["postures"][0]["q"]


def test_an_unreachable_pose_writes_its_error_front(tmp_path, capsys):
    out = tmp_path / "front.html"
    assert main(["solve", "eosma7-m", "--target", "-0.25", "1", "0.5", "--euler", "0", "0",
                 "0", "--html", str(out)]) == 1  # unreachable: exit status 1, as without
    assert f"explorer written to {out}" in capsys.readouterr().out
    panel = page_data(out)["panels"][0]
    assert panel["objectives"][0].startswith("position error")


def test_a_solved_pose_has_no_front_to_explore(tmp_path, capsys):
    out = tmp_path / "none.html"
    assert main(["solve", "eosma7", "--target", "-24.748737", "100.961941", "50", "--euler",
                 "135", "0", "-90", "--deg", "--html", str(out)]) == 0
    assert "--html: no front to explore (status solved" in capsys.readouterr().err
    assert not out.exists()


def test_a_bad_html_path_is_refused_before_solving(tmp_path, capsys):
    assert main(["solve", "eosma7", "--target", "1", "2", "3", "--html",
                 str(tmp_path / "missing" / "x.html")]) == 2
    err = capsys.readouterr().err
    assert "--html folder" in err and "does not exist" in err


def test_report_html(tmp_path, capsys, tiny):
    folder = tmp_path / "tiny"
    run_experiment(ExperimentConfig.from_dict(tiny), out=folder)
    assert main(["report", str(folder), "--html"]) == 0
    assert (folder / "report.html").is_file() and not (folder / "report.md").exists()
    page = tmp_path / "mine.html"
    assert main(["report", str(folder), "--html", str(page)]) == 0
    assert f"interactive report written to {page}" in capsys.readouterr().out
    kinds = [p["kind"] for p in page_data(page)["panels"]]
    assert "curves" in kinds and "table" in kinds
    assert main(["report", str(folder), str(folder), "--html", str(page)]) == 2
    assert "--html FILE names one page" in capsys.readouterr().err
    assert main(["report", str(folder), "--docs", str(tmp_path), "--html"]) == 2
    assert "give one of them" in capsys.readouterr().err
