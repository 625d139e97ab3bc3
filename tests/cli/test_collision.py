"""``moik solve --scene FILE [--clearance D]``: each solution's distance, in text and JSON."""

import json

import numpy as np
import pytest

from moik.cli import main
from moik.collision import CollisionChecker
from moik.collision.catalog import collision_model
from moik.collision.io import load_scene

SCENE = {"obstacles": [
    {"name": "table", "type": "halfspace", "normal": [0, 0, 1], "offset": 0.0},
    {"name": "shelf", "type": "box", "size": [0.3, 0.7, 0.02], "xyz": [0.55, 0, 0.35]}],
    "allowed": [["table", "panda_link0"], ["table", "panda_link1"]]}


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(SCENE))
    return path


def test_json_reports_the_recomputed_distance(scene_file, capsys):
    code = main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--scene", str(scene_file),
                 "--clearance", "0.01", "--n-solutions", "2", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0
    checker = CollisionChecker(model=collision_model("panda"), scene=load_scene(SCENE))
    for sol in doc["solutions"]:
        d = float(checker.min_distance(np.array(sol["q"])))
        assert sol["min_distance"] == pytest.approx(d, abs=1e-12)
        assert sol["collides"] == (d < 0.01) and len(sol["closest_pair"]) == 2


def test_text_marks_each_solution(scene_file, capsys):
    main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--scene", str(scene_file)])
    out = capsys.readouterr().out
    assert "solution 1: " in out and ("collision-free" in out or "IN COLLISION" in out)


def test_bad_scene_file(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text('{"obstacles": [{"type": "cone"}]}')
    assert main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--scene", str(bad)]) != 0
    assert "cone" in capsys.readouterr().err


def test_scene_goes_to_the_solver(scene_file, capsys):
    code = main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--scene", str(scene_file),
                 "--clearance", "0.02", "--n-solutions", "3", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0 and doc["status"] == "solved"
    assert doc["min_distance"] >= 0.02
    assert doc["solutions"] and not any(sol["collides"] for sol in doc["solutions"])


def test_target_in_an_obstacle_collides(scene_file, capsys):
    code = main(["solve", "panda", "--target", "0.55", "0.0", "0.35", "--scene", str(scene_file),
                 "--starts", "30", "--max-evals", "3000", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 1 and doc["status"] == "collides" and not doc["success"]
    assert doc["min_distance"] < 0 and doc["solutions"] == []


def test_negative_clearance(scene_file, capsys):
    assert main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--scene", str(scene_file),
                 "--clearance", "-1"]) != 0
    assert "--clearance" in capsys.readouterr().err
