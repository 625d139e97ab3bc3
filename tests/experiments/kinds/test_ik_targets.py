"""Targets of IK experiments (moik.experiments.kinds.ik_targets), through the config."""

from pathlib import Path

import numpy as np
import pytest

from moik.exceptions import ConfigError
from moik.experiments.config import ExperimentConfig
from moik.experiments.kinds.ik import check_config
from moik.robots import get_robot


@pytest.mark.parametrize("targets, match", [
    ({"kind": "fixed", "points": [{"name": "far", "position": [1e4, 0, 0]}]},
     r"problem \(at target 'far'\): .*expected a position in"),
    ({"kind": "fixed", "points": [{"name": "q", "fk_q_deg": [1, 2, 3]}]},
     r"targets.points\[0\].fk_q_deg must be a list of 2 numbers"),
    ({"kind": "circle", "center": [0.1, 0, 0], "radius": 0.1, "n_points": 4,
      "euler_deg": [0, 0, 0], "convention": "xyz"}, r"targets: unknown Euler convention 'xyz'"),
    ({"kind": "random", "n": 2, "seed": 1, "with_orientation": 0},
     r"targets.with_orientation must be True or False"),
    ({"kind": "fixed", "points": [{"name": "", "position": [0.1, 0, 0]}]},
     r"targets.points\[0\].name must be a non-empty string"),
])
def test_target_errors_name_the_config_key(tiny, targets, match):
    tiny["targets"] = targets
    with pytest.raises(ConfigError, match=match):
        ExperimentConfig.from_dict(tiny)


def test_random_targets_are_reachable_positions(tiny_config):
    targets = tiny_config.targets
    assert len(targets) == 2 and targets[0].rotation is None


def test_independent_random_orientations_keep_the_reachable_positions():
    base = {"robot": "rokbani5", "problem": {"kind": "bi-objective"},
            "targets": {"kind": "random", "n": 4, "seed": 3}}
    _, reachable = check_config("x", dict(base), Path())
    _, independent = check_config("x", {**base, "targets": {**base["targets"],
                                                           "orientation": "independent"}},
                                 Path())
    arm = get_robot("rokbani5")
    for r, i in zip(reachable, independent, strict=True):
        np.testing.assert_array_equal(r.position, i.position)
        assert r.target.q_source is not None and i.target.q_source is None
        np.testing.assert_allclose(arm.fk(r.target.q_source)[:3, :3], r.rotation, atol=1e-12)
        assert not np.allclose(r.rotation, i.rotation)
        np.testing.assert_allclose(i.rotation @ i.rotation.T, np.eye(3), atol=1e-12)
    with pytest.raises(ConfigError, match="orientation must be one of reachable, independent"):
        check_config("x", {**base, "targets": {**base["targets"], "orientation": "fk"}}, Path())
