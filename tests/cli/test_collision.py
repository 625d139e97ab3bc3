"""``moik solve --scene FILE | --self-collision [--clearance D]`` (also with ``--pareto``):
each solution's distance, in text and JSON."""

import json
from pathlib import Path

import numpy as np
import pytest

from moik import get_robot
from moik.cli import main
from moik.collision import CollisionChecker
from moik.collision.io import load_scene
from moik.solver.collision import default_model

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
    # the scene's pairs only: --self-collision is off unless given, as in solve_ik
    checker = CollisionChecker(model=default_model(get_robot("panda")), scene=load_scene(SCENE))
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


def test_target_in_an_obstacle_collides(tmp_path, capsys):
    """A target deep inside a block: the hand (its mesh ends about 4 cm short of the tool
    point between the fingers) is in the block too, whichever way it comes."""
    block = tmp_path / "block.json"
    block.write_text(json.dumps({"obstacles": [{"name": "block", "type": "box",
                                                "size": [0.3, 0.3, 0.3], "xyz": [0.55, 0, 0.35]}]}))
    code = main(["solve", "panda", "--target", "0.55", "0.0", "0.35", "--scene", str(block),
                 "--starts", "30", "--max-evals", "3000", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 1 and doc["status"] == "collides" and not doc["success"]
    assert doc["min_distance"] < 0 and doc["solutions"] == []


def test_negative_clearance(scene_file, capsys):
    assert main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--scene", str(scene_file),
                 "--clearance", "-1"]) != 0
    assert "--clearance" in capsys.readouterr().err


PARETO = ["solve", "panda", "--target", "0.5", "0.1", "0.45", "--pareto-size", "4"]


def test_pareto_members_keep_the_clearance_of_the_scene(scene_file, capsys):
    """--pareto is collision-aware as solve is: each member's distance, recomputed here by
    a checker of our own, is at least --clearance, and the criterion clearance is it."""
    code = main([*PARETO, "--pareto", "manipulability,clearance", "--scene", str(scene_file),
                 "--clearance", "0.01", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0 and doc["solutions"]
    # the scene's pairs only: --self-collision is off unless given, as in solve_ik
    checker = CollisionChecker(model=default_model(get_robot("panda")), scene=load_scene(SCENE))
    for sol, f in zip(doc["solutions"], doc["F"], strict=True):
        d = float(checker.min_distance(np.array(sol["q"])))
        assert sol["min_distance"] == pytest.approx(d, abs=1e-12)
        assert f[1] == pytest.approx(d, abs=1e-12)
        assert d >= 0.01 and not sol["collides"]
    assert doc["min_distance"] == doc["solutions"][doc["compromise"]]["min_distance"]


def test_pareto_text_gives_each_members_distance(scene_file, capsys):
    main([*PARETO, "--pareto", "manipulability,limit_margin", "--scene", str(scene_file)])
    out = capsys.readouterr().out
    assert "member 0: collision-free" in out


@pytest.mark.parametrize("argv, option", [
    ([*PARETO, "--pareto", "manipulability,clearance"], "--scene FILE"),
    (["solve", "panda", "--target", "0.5", "0.1", "0.45", "--clearance", "0.01"], "--scene FILE"),
])
def test_clearance_without_geometry_names_the_options(argv, option, capsys):
    assert main(argv) != 0
    err = capsys.readouterr().err
    assert option in err and "--self-collision" in err and "scene=" not in err


def test_self_collision_alone_checks_the_self_pairs(capsys):
    code = main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--self-collision",
                 "--clearance", "0.01", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0 and doc["status"] == "solved"
    checker = CollisionChecker(model=default_model(get_robot("panda")),
                               self_collision=True)  # no scene
    assert doc["min_distance"] == pytest.approx(float(checker.min_distance(np.array(doc["q"]))),
                                                abs=1e-12)
    assert doc["min_distance"] >= 0.01


def test_scene_and_self_collision_check_both(scene_file, capsys):
    code = main(["solve", "panda", "--target", "0.5", "0.1", "0.45", "--scene", str(scene_file),
                 "--self-collision", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0
    both = CollisionChecker(model=default_model(get_robot("panda")), scene=load_scene(SCENE),
                            self_collision=True)
    assert doc["min_distance"] == pytest.approx(float(both.min_distance(np.array(doc["q"]))),
                                                abs=1e-12)


def test_pareto_explorer_draws_the_scene_and_the_arms_geometry(scene_file, tmp_path, capsys):
    html = tmp_path / "x.html"
    assert main([*PARETO, "--pareto", "manipulability,limit_margin", "--scene", str(scene_file),
                 "--html", str(html)]) == 0
    text = html.read_text()
    data = json.loads(text.split('id="moik-data">', 1)[1].split("</script>", 1)[0])
    assert [t["name"] for t in data["panels"][0]["obstacles"]] == ["table", "shelf"]
    # and the arm's own geometry the members were checked against (the URDF's mesh parts)
    shapes = data["panels"][0]["robot_shapes"]
    assert {s["name"] for s in shapes} >= {"panda_link0", "panda_link5", "panda_link7"}


def test_pareto_with_no_member_keeping_the_clearance_says_collides(capsys):
    argv = [*PARETO, "--pareto", "manipulability,limit_margin", "--self-collision",
            "--clearance", "5"]
    assert main(argv) == 1
    assert "status: collides (no exact point keeps the clearance 5 m" in capsys.readouterr().out
    assert main([*argv, "--json"]) == 1
    doc = json.loads(capsys.readouterr().out)
    assert doc["status"] == "collides" and not doc["success"] and doc["solutions"] == []


URDF_DIR = Path(__file__).resolve().parents[1] / "data" / "urdf"
TABLE = {"obstacles": [{"name": "table", "type": "halfspace", "normal": [0, 0, 1],
                        "offset": -0.01}], "allowed": [["table", "base_link"]]}


def test_a_urdf_arm_with_its_meshes(tmp_path, capsys):
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps(TABLE))
    argv = ["solve", str(URDF_DIR / "kr16_2.urdf"), "--tip", "tool0", "--target", "0.9", "0.2",
            "0.6", "--scene", str(scene), "--self-collision", "--json"]
    assert main([*argv, "--package-dir", str(URDF_DIR / "packages")]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["status"] == "solved" and 0.0 <= doc["min_distance"] < np.inf
    assert main(argv) != 0  # the meshes' package not given: the error says which option
    err = capsys.readouterr().err
    assert "kuka_kr16_support" in err and "give --package-dir" in err


def test_a_batch_of_a_urdf_arm_with_its_meshes(tmp_path, capsys):
    """moik batch takes --package-dir as moik solve does (it had no such option: a URDF
    arm's package:// meshes were found through ROS_PACKAGE_PATH only)."""
    from moik import load_urdf

    robot = load_urdf(URDF_DIR / "kr16_2.urdf", tip_link="tool0")
    targets = tmp_path / "targets.npy"
    np.save(targets, robot.fk(robot.random_q(3, rng=np.random.default_rng(0)))[:, :3, 3])
    out = tmp_path / "out.npz"
    argv = ["batch", str(URDF_DIR / "kr16_2.urdf"), "--tip", "tool0", str(targets),
            "--out", str(out), "--self-collision", "--no-progress"]
    assert main([*argv, "--package-dir", str(URDF_DIR / "packages")]) in (0, 1)
    capsys.readouterr()
    with np.load(out) as res:
        assert res["q"].shape == (3, robot.dof) and np.all(np.isfinite(res["min_distance"]))


BARE = """<robot name="two">
  <link name="base"><collision><origin xyz="0 0 0.05"/><geometry><box size="0.2 0.2 0.1"/>
    </geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.25"/><geometry>
    <cylinder radius="0.04" length="0.5"/></geometry></collision></link>
  <link name="fore"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 1 0"/><limit lower="-2" upper="2"/></joint>
  <joint name="j2" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 1 0"/><limit lower="-2" upper="2"/></joint>
</robot>"""


def test_a_link_without_geometry_is_refused_or_explicitly_left_unchecked(tmp_path, capsys):
    """`fore` has no <collision>: an error naming the option, or, with the option, solved
    and named as not checked (text and JSON)."""
    urdf = tmp_path / "two.urdf"
    urdf.write_text(BARE)
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"obstacles": [{"name": "ball", "type": "sphere",
                                                "radius": 0.1, "xyz": [2, 2, 2]}]}))
    argv = ["solve", str(urdf), "--target", "0.3", "0.0", "0.5", "--scene", str(scene)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "['fore'] have no <collision>" in err and "give --allow-missing-geometry" in err
    assert main([*argv, "--allow-missing-geometry"]) == 0
    assert "not checked (no collision geometry): fore" in capsys.readouterr().out
    assert main([*argv, "--allow-missing-geometry", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["unchecked_links"] == ["fore"]
    assert main(["solve", str(urdf), "--target", "0.3", "0.0", "0.5",
                 "--allow-missing-geometry"]) == 2
    assert "goes with --scene or --self-collision" in capsys.readouterr().err
    assert main(["solve", "puma560", "--target", "0.3", "0.0", "0.5", "--scene", str(scene),
                 "--allow-missing-geometry"]) == 2
    assert "is for a URDF arm" in capsys.readouterr().err
