"""``moik solve ... --pareto`` (moik.cli.pareto): its functions on ``solve``'s arguments."""

import argparse
import json

import matplotlib
import numpy as np
import pytest

from moik.cli.pareto import parse_criteria, run_pareto
from moik.cli.parser import build_parser
from moik.exceptions import ParameterError
from moik.kinematics.orientation import zyx_euler
from moik.problems import random_reachable_targets
from moik.robots import get_robot

matplotlib.use("Agg")

IIWA = get_robot("iiwa14")
POSE = random_reachable_targets(IIWA, 1, seed=11)[0]


def _solve_args(argv: list[str]) -> argparse.Namespace:
    """``moik solve ARGV`` as the command's parser reads it."""
    return build_parser().parse_args(["solve", *argv])


def _pose_args(*extra: str) -> argparse.Namespace:
    euler = np.degrees(zyx_euler(POSE.rotation))
    q = np.degrees(POSE.q_source + 0.1)
    return _solve_args(["iiwa14", "--target", *map(str, POSE.position),
                                       "--euler", *map(str, euler), "--deg",
                                       "--q-current", *map(str, q), *extra])


def test_text_output_lists_the_members_and_the_compromise(capsys, tmp_path):
    args = _pose_args("--pareto", "joint_motion,manipulability", "--pareto-size", "8",
                      "--plot", str(tmp_path / "front.png"))
    assert run_pareto(args) == 0
    out = capsys.readouterr().out
    assert "8 exact solutions, mutually non-dominated (memetic search over" in out
    assert "joint_motion (min)" in out and "manipulability (max)" in out
    assert out.count("\n*") == 2  # the compromise member and the legend line
    assert "* compromise (closest to the utopia point)" in out
    assert (tmp_path / "front.png").exists() and (tmp_path / "front.pdf").exists()


def test_json_output(capsys):
    assert run_pareto(_pose_args("--pareto", "manipulability,limit_margin", "--json",
                                 "--pareto-size", "5")) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["objectives"] == ["manipulability", "limit_margin"]
    members = data["solutions"]
    assert data["senses"] == ["max", "max"] and len(members) == len(data["F"]) <= 5
    assert max(m["position_error"] for m in members) <= 1e-9 * IIWA.reach
    assert data["redundant"] is True and 0 <= data["compromise"] < len(members)
    assert data["status"] == "solved" and data["success"] is True
    assert data["q"] == members[data["compromise"]]["q"]


def test_no_solution_exits_1(capsys):
    args = _solve_args(["iiwa14", "--target", "2", "0", "0", "--pareto",
                                       "manipulability", "--pareto-size", "3"])
    assert run_pareto(args) == 1
    assert "no exact solution found" in capsys.readouterr().out


def test_bad_criteria_and_q_current():
    assert parse_criteria(" joint_motion , limit_margin ") == ("joint_motion", "limit_margin")
    with pytest.raises(ParameterError, match="comma-separated"):
        parse_criteria(" , ")
    args = _pose_args("--pareto", "joint_motion")
    args.q_current = [0.0, 1.0]
    with pytest.raises(ParameterError, match=r"needs 7 joint values, got 2 \(--q-current\)"):
        run_pareto(args)


def test_html_without_plotly_stops_before_the_search(capsys, tmp_path, monkeypatch):
    """Before: the whole search ran and printed its members, then exit 2 for plotly."""
    import importlib.util

    from moik.cli import main

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "plotly" else real(name, *a))
    euler = np.degrees(zyx_euler(POSE.rotation))
    argv = ["solve", "iiwa14", "--target", *map(str, POSE.position), "--euler",
            *map(str, euler), "--deg", "--pareto", "manipulability,limit_margin",
            "--html", str(tmp_path / "x.html")]
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and "--html: the explorer needs plotly" in err


def test_clearance_is_named_as_a_criterion():
    """Before: --pareto's help and the unknown-criterion error left out 'clearance'."""
    from moik.exceptions import UnknownNameError
    from moik.kinematics.criteria import build_criteria

    assert "clearance with --scene or --self-collision" in _solve_help()
    with pytest.raises(UnknownNameError, match="expected one of: .*clearance"):
        build_criteria(("foo",), IIWA)
    with pytest.raises(ParameterError, match="criterion 'clearance' needs geometry"):
        build_criteria(("clearance",), IIWA)


def _solve_help() -> str:
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return " ".join(sub.choices["solve"].format_help().split())
