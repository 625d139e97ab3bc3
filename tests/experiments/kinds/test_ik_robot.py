"""A URDF arm as an experiment's robot (moik.experiments.kinds.ik_robot): read from the config's
folder, recorded with its digest, refused when it changed, and run end to end (the shipped UR5
URDF and its collision meshes, copied beside a config in tmp_path)."""

import hashlib
import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from moik import load_urdf
from moik.collision.shapes import Compound
from moik.exceptions import ConfigError, ResultsError
from moik.experiments.config import ExperimentConfig, load_config
from moik.experiments.kinds.ik_collision import checker_of, feasibility
from moik.experiments.kinds.ik_robot import arm, stored_robot
from moik.experiments.report import make_report
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore
from moik.problems.collision_ik import CollisionIK
from moik.problems.ik import BiObjectiveIK
from moik.solver.collision import collision_guard

DATA = Path(__file__).resolve().parents[3] / "moik" / "robots" / "data"
UR = Path("example-robot-data") / "robots" / "ur_description"

CONFIG = """
name = "ur5-arm"
title = "position IK of a UR5 read from its URDF"
source = "test"
robot = { urdf = "arms/ur5_robot.urdf", package_dirs = ["arms/packages"], tip_link = "tool0" }
pop_size = 10
iterations = 5
runs = 1
seed = 4
quick = { runs = 1 }

[problem]
kind = "position"

[targets]
kind = "random"
n = 2
seed = 1
with_orientation = false

[[algorithms]]
name = "pso"
"""

COLLISION = """
name = "ur5-scene"
title = "bi-objective IK of a UR5 from its URDF beside a wall"
source = "test"
robot = { urdf = "arms/ur5_robot.urdf", package_dirs = ["arms/packages"], tip_link = "tool0" }
pop_size = 10
archive_size = 10
iterations = 3
runs = 1
seed = 4
analyses = ["collision"]

[problem]
kind = "bi-objective"
self_collision = true

[problem.scene]
obstacles = [{ name = "wall", type = "box", size = [0.05, 2.0, 2.0], xyz = [0.45, 0.0, 0.5] }]

[targets]
kind = "fixed"
points = [{ name = "front", fk_q_deg = [10, -60, 80, -20, 90, 0], hv_ref_point = [2.0, 3.2] }]

[[algorithms]]
name = "nsga2"
"""


@pytest.fixture
def folder(tmp_path):
    """A config folder holding ``arms/``: the UR5 URDF and its package of collision meshes."""
    arms = tmp_path / "arms"
    arms.mkdir()
    shutil.copy(DATA / "ur5_robot.urdf", arms)
    shutil.copytree(DATA / "packages" / UR / "meshes" / "ur5" / "collision",
                    arms / "packages" / UR / "meshes" / "ur5" / "collision")
    (tmp_path / "ur5_arm.toml").write_text(CONFIG)
    (tmp_path / "ur5_scene.toml").write_text(COLLISION)
    return tmp_path


def _with_robot(folder: Path, robot: str) -> Path:
    text = CONFIG.replace('robot = { urdf = "arms/ur5_robot.urdf", package_dirs = '
                          '["arms/packages"], tip_link = "tool0" }', f"robot = {robot}")
    path = folder / "ur5_arm.toml"
    path.write_text(text)
    return path


def test_the_urdf_is_read_from_the_configs_folder_and_recorded_with_its_digest(folder,
                                                                           monkeypatch):
    monkeypatch.chdir(folder.parent)  # the current folder is not the config's
    cfg = load_config(folder / "ur5_arm.toml")
    digest = hashlib.sha256((folder / "arms" / "ur5_robot.urdf").read_bytes()).hexdigest()
    assert cfg["robot"] == {"urdf": "arms/ur5_robot.urdf", "package_dirs": ["arms/packages"],
                            "tip_link": "tool0", "sha256": digest}
    assert cfg.robot["urdf"] == str(folder / "arms" / "ur5_robot.urdf")
    assert cfg.robot["package_dirs"] == [str(folder / "arms" / "packages")]
    robot = arm(cfg.robot)
    want = load_urdf(folder / "arms" / "ur5_robot.urdf", tip_link="tool0")
    q = np.full(6, 0.3)
    np.testing.assert_allclose(robot.fk(q), want.fk(q), atol=1e-12)
    assert cfg.quick()["robot"] == cfg["robot"] and cfg.quick().robot == cfg.robot


def test_a_quick_run_stores_which_urdf_and_the_report_names_it(folder, tmp_path_factory):
    cfg = load_config(folder / "ur5_arm.toml")
    out = tmp_path_factory.mktemp("runs") / "ur5-arm"
    summary = run_experiment(cfg, out=out, quick=True, workers=1)
    assert summary.failed == 0
    store = ResultStore.open(out)
    assert all(r["status"] == "ok" for r in store.records())
    meta = json.loads((out / "meta.json").read_text())
    assert meta["robot"] == cfg.robot and meta["config"]["robot"] == cfg["robot"]
    assert stored_robot(meta) == cfg.robot
    report = make_report(out, figures=False).path.read_text()
    assert f"robot URDF `arms/ur5_robot.urdf` (SHA-256 {cfg['robot']['sha256'][:12]}" in report
    assert str(folder) not in report  # no path of this machine in a report


def test_resuming_with_a_changed_urdf_is_refused(folder, tmp_path_factory):
    out = tmp_path_factory.mktemp("runs") / "ur5-arm"
    run_experiment(load_config(folder / "ur5_arm.toml"), out=out, quick=True, workers=1,
                   limit=1)
    same = load_config(folder / "ur5_arm.toml")
    assert run_experiment(same, out=out, quick=True, workers=1, resume=True).failed == 0
    urdf = folder / "arms" / "ur5_robot.urdf"
    urdf.write_text(urdf.read_text().replace('name="shoulder_pan_joint"',
                                             'name="shoulder_pan_joint"  ', 1))
    changed = load_config(folder / "ur5_arm.toml")
    assert changed.fingerprint() != same.fingerprint()
    # the stored config pins the former file: the folder is not taken for this config
    with pytest.raises(ResultsError, match=r"has SHA-256 .*the URDF changed.*nothing was "
                                           r"changed. Cannot adopt them"):
        run_experiment(changed, out=out, quick=True, workers=1, resume=True)
    assert (out / "results.jsonl").read_text().count("\n") == 2  # left as it was


def test_a_urdf_changed_after_the_check_is_refused_where_it_is_loaded(folder):
    cfg = load_config(folder / "ur5_arm.toml")
    urdf = folder / "arms" / "ur5_robot.urdf"
    urdf.write_text(urdf.read_text() + "\n")
    with pytest.raises(ConfigError, match="changed since the experiment was checked"):
        arm(cfg.robot)
    meta = {"config": cfg.raw, "robot": {**cfg.robot, "sha256": "0" * 64}}
    with pytest.raises(ResultsError, match="does not record that file"):
        stored_robot(meta)


@pytest.mark.parametrize("robot, match", [
    ('{ urdf = "arms/ur5_robot.urdf", tip = "tool0" }',
     r"unknown key\(s\) 'tip' of a URDF robot; expected: urdf, package_dirs, base_link, "
     r"tip_link, sha256"),
    ('{ package_dirs = ["arms"] }', r"a URDF robot needs 'urdf'"),
    ('{ urdf = "arms/nope.urdf" }', r"robot.urdf: cannot read URDF file .*nope.urdf.* it does "
                                    r"not exist \(a relative path is read from the config's "
                                    r"folder"),
    ('{ urdf = "arms" }', r"it is not a regular file"),
    ('{ urdf = 3 }', r"robot.urdf must be a non-empty string, got 3"),
    ('{ urdf = "arms/ur5_robot.urdf", package_dirs = ["missing"] }',
     r"package_dirs\[0\]: 'missing' is not a folder"),
    ('{ urdf = "arms/ur5_robot.urdf", package_dirs = "arms" }',
     r"package_dirs must be a list of folders or a table \{package = folder\}"),
    ('{ urdf = "arms/ur5_robot.urdf", sha256 = "abc" }',
     r"robot.sha256: the file .* has SHA-256 [0-9a-f]{64}, not 'abc'"),
    ('{ urdf = "arms/ur5_robot.urdf", tip_link = "nope" }', r"robot: unknown link 'nope'"),
])
def test_bad_urdf_entries_are_config_errors_naming_the_key(folder, robot, match):
    with pytest.raises(ConfigError, match=match):
        load_config(_with_robot(folder, robot))


def test_a_targets_own_robot_stays_a_catalog_name(folder):
    data = load_config(folder / "ur5_arm.toml").raw
    data["targets"] = {"kind": "fixed", "points": [
        {"name": "a", "robot": {"urdf": "arms/ur5_robot.urdf"}, "position": [0.3, 0.1, 0.4]}]}
    with pytest.raises(ConfigError, match=r"points\[0\].robot must be a catalog robot's name"):
        ExperimentConfig.from_dict(data, folder=folder)


def test_a_collision_experiment_checks_the_urdfs_meshes(folder, tmp_path_factory):
    cfg = load_config(folder / "ur5_scene.toml")
    robot = arm(cfg.robot)
    checker = checker_of(robot, cfg["problem"])
    solver = collision_guard(robot, scene=checker.scene, self_collision=True).checker
    assert checker.model is solver.model  # the solver's own geometry, built once
    # the seven mesh links as compounds (convex hulls of the meshes), the URDF's one box
    assert sum(isinstance(s, Compound) for _, s in checker.model.items) == 7
    assert {type(s).__name__ for _, s in checker.model.items} == {"Compound", "Box"}
    out = tmp_path_factory.mktemp("runs") / "ur5-scene"
    assert run_experiment(cfg, out=out, workers=1).failed == 0
    store = ResultStore.open(out)
    [rec] = store.records()
    X = store.load_arrays(rec["trial"])["front_X"]
    d = solver.min_distance_batch(X)
    assert rec["n_feasible"] == int((d >= 0).sum()) and rec["min_distance"] == d.min()
    assert "Collision-free members" in make_report(out, figures=False).path.read_text()


def test_a_link_without_geometry_is_refused_or_left_unchecked_by_the_config(folder):
    """The URDF's forearm_link without its <collision>: refused, naming the config key;
    with ``missing_geometry = "ignore"`` checked without it, and a trial records it."""
    urdf = folder / "arms" / "ur5_robot.urdf"
    text = urdf.read_text()
    start = text.index("<collision>", text.index('<link name="forearm_link"'))
    end = text.index("</collision>", start) + len("</collision>")
    urdf.write_text(text[:start] + text[end:])
    config = folder / "ur5_scene.toml"
    with pytest.raises(ConfigError, match=r"\['forearm_link'\] have no <collision>.*"
                                          r'missing_geometry = "ignore" in the problem'):
        load_config(config)
    config.write_text(COLLISION.replace("self_collision = true",
                                        'self_collision = true\nmissing_geometry = "ignore"'))
    cfg = load_config(config)
    robot = arm(cfg.robot)
    checker = checker_of(robot, cfg["problem"])
    assert checker.model.unchecked_links == ("forearm_link",)
    problem = CollisionIK(BiObjectiveIK(robot, robot.fk(np.zeros(6))), checker=checker)
    record: dict = {}
    feasibility(problem, np.zeros((2, 6)), record)
    assert record["unchecked_links"] == ["forearm_link"]
    config.write_text(COLLISION.replace("self_collision = true",
                                        'self_collision = true\nmissing_geometry = "skip"'))
    with pytest.raises(ConfigError, match="missing_geometry"):
        load_config(config)


def test_an_srdf_is_read_from_the_configs_folder_pinned_and_given_to_the_arm(folder):
    """``srdf`` (the robot's MoveIt SRDF): read relative to the config, its SHA-256 recorded
    and checked where the arm is loaded; the arm's default model leaves its pairs out."""
    srdf = folder / "arms" / "ur5.srdf"
    srdf.write_text('<robot name="ur5"><disable_collisions link1="base_link" '
                    'link2="wrist_3_link" reason="Never"/></robot>')
    path = _with_robot(folder, '{ urdf = "arms/ur5_robot.urdf", package_dirs = '
                               '["arms/packages"], tip_link = "tool0", srdf = "arms/ur5.srdf" }')
    cfg = load_config(path)
    assert cfg.robot["srdf"] == str(srdf)
    assert cfg.robot["srdf_sha256"] == hashlib.sha256(srdf.read_bytes()).hexdigest()
    assert Path(arm(cfg.robot).description.srdf) == srdf.resolve()
    srdf.write_text(srdf.read_text() + "\n")
    with pytest.raises(ConfigError, match="SRDF .* changed since the experiment was checked"):
        arm(dict(cfg.robot, tip_link="wrist_3_link"))  # not loaded before: checked now
    with pytest.raises(ConfigError, match=r"robot.srdf: .*missing.srdf"):
        load_config(_with_robot(folder, '{ urdf = "arms/ur5_robot.urdf", '
                                        'srdf = "arms/missing.srdf" }'))
