"""IK experiments (moik.experiments.kinds.ik): robots, problems, targets built once."""

import copy

import numpy as np
import pytest

from moik.exceptions import ConfigError
from moik.experiments.config import ExperimentConfig
from moik.robots import get_robot


def test_ik_config_needs_robot_and_checks_locked_joints_and_point_robots(tiny):
    no_robot = {k: v for k, v in tiny.items() if k != "robot"}
    with pytest.raises(ConfigError, match="needs 'robot' and 'targets'"):
        ExperimentConfig.from_dict(no_robot)
    bad = copy.deepcopy(tiny)
    bad["problem"]["locked_joints_deg"] = [0.0]
    with pytest.raises(ConfigError, match="locked_joints_deg must be a list of 2"):
        ExperimentConfig.from_dict(bad)
    bad = copy.deepcopy(tiny)
    bad["targets"] = {"kind": "fixed", "points": [{"name": "a", "robot": "r2d2",
                                                   "position": [0.1, 0.1, 0]}]}
    with pytest.raises(ConfigError, match="unknown robot 'r2d2'"):
        ExperimentConfig.from_dict(bad)


def test_targets_are_built_once_and_carried_to_the_trials(tiny_config):
    from moik.experiments.kinds.ik import NamedTarget, build_problem, experiment_robot
    from moik.experiments.trials import build_trials
    from moik.problems import Target

    targets = tiny_config.targets
    assert len(targets) == 2 and all(isinstance(t, NamedTarget) for t in targets)
    assert all(isinstance(t.target, Target) for t in targets)
    specs = build_trials(tiny_config)
    assert all(s.target is targets[s.target_index] for s in specs)
    problem = build_problem(experiment_robot("planar2", tiny_config["problem"]),
                            tiny_config["problem"], targets[0])
    assert problem.target is targets[0].target  # not rebuilt from lists
    d = targets[0].as_dict()
    assert d["rotation"] is None and d["position"] == targets[0].position.tolist()


def _pose(tiny, **problem):
    d = copy.deepcopy(tiny)
    d.update(robot="eosma7", problem={"kind": "pose", **problem})
    d["targets"] = {"kind": "random", "n": 2, "seed": 1}
    return d


@pytest.mark.parametrize("problem, match", [
    ({"weights": [-1.0, 1.0]}, r"problem \(at target 'T1'\): weights must be two finite "),
    ({"displacement_weight": 1.0}, r"problem \(at target 'T1'\): displacement_weight > 0 needs"),
    ({"displacement_weight": -1.0}, r"problem \(at target 'T1'\): displacement_weight must be "),
    ({"orientation": "nope"}, r"problem.orientation: unknown orientation metric 'nope'"),
    ({"weights": [1.0, True]}, r"problem.weights\[1\] must be a finite number, got True"),
    ({"q_start_deg": [0] * 6}, r"problem.q_start_deg must be a list of 7 numbers"),
])
def test_errors_of_the_built_problem_name_the_config_key(tiny, problem, match):
    with pytest.raises(ConfigError, match=match):
        ExperimentConfig.from_dict(_pose(tiny, **problem))


def test_locking_every_joint_is_a_config_error(tiny):
    tiny["problem"]["locked_joints_deg"] = [0.0, 0.0]
    with pytest.raises(ConfigError, match=r"problem.locked_joints_deg: at least one joint"):
        ExperimentConfig.from_dict(tiny)


def test_locked_joints_apply_to_the_trials(tiny):
    from moik.experiments.kinds.ik import experiment_robot

    tiny["problem"]["locked_joints_deg"] = [None, 30.0]
    cfg = ExperimentConfig.from_dict(tiny)
    assert experiment_robot("planar2", cfg["problem"]).dof == 1
    assert all(len(t.position) == 3 for t in cfg.targets)


def test_joint_limits_replace_the_catalog_limits(tiny):
    from moik.experiments.kinds.ik import experiment_robot

    tiny["problem"]["joint_limits_deg"] = [[-180, 180], [-90, 45]]
    cfg = ExperimentConfig.from_dict(tiny)
    arm = experiment_robot("planar2", cfg["problem"])
    np.testing.assert_allclose(np.degrees(arm.lower), [-180, -90])
    np.testing.assert_allclose(np.degrees(arm.upper), [180, 45])
    np.testing.assert_array_equal(arm.fk([0.3, 0.2]), get_robot("planar2").fk([0.3, 0.2]))
    tiny["problem"]["locked_joints_deg"] = [None, 30.0]  # limits first, then the lock
    assert experiment_robot("planar2", ExperimentConfig.from_dict(tiny)["problem"]).dof == 1


def test_bad_joint_limits_are_config_errors(tiny):
    tiny["problem"]["joint_limits_deg"] = [[0, 1]]
    with pytest.raises(ConfigError, match=r"joint_limits_deg must be a list of 2 \[lower, upper\]"):
        ExperimentConfig.from_dict(tiny)
    tiny["problem"]["joint_limits_deg"] = [[0, 1], [0, "x"]]
    with pytest.raises(ConfigError, match=r"joint_limits_deg\[1\]\[1\]"):
        ExperimentConfig.from_dict(tiny)
    tiny["problem"]["joint_limits_deg"] = [[0, 1], [1, 0]]
    with pytest.raises(ConfigError, match=r"problem.joint_limits_deg: "):
        ExperimentConfig.from_dict(tiny)
