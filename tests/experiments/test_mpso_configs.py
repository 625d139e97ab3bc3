"""The MO-m-PSO paper's experiment configs (experiments/mpso_*.toml): both readings of each."""

from pathlib import Path

import numpy as np
import pytest

from moik.experiments.config import load_config
from moik.experiments.kinds.ik import experiment_robot

FOLDER = Path(__file__).resolve().parents[2] / "experiments"


def _load(name: str):
    return load_config(FOLDER / f"{name.replace('-', '_')}.toml")


@pytest.mark.parametrize("name", ["mpso-table2", "mpso-table3", "mpso-table3-independent",
                                  "mpso-circle", "mpso-circle-full-range"])
def test_both_guides_run_and_the_printed_statistics_are_checked(name):
    cfg = _load(name)
    guides = {a.label: a.params.get("guide", "compromise") for a in cfg.algorithms}
    assert guides == {"mo-m-pso": "compromise", "mo-m-pso-own-best": "own-best"}
    assert "paper-consistency" in cfg["analyses"] and cfg["paper"]["n_values"] > 0


def test_circle_with_and_without_the_servo_ranges():
    paper, full = _load("mpso-circle"), _load("mpso-circle-full-range")
    assert [t.name for t in paper.targets] == [t.name for t in full.targets]
    np.testing.assert_allclose(np.degrees(experiment_robot("rokbani5", paper["problem"]).upper),
                               [180, 170, 135, 180, 180])
    arm = experiment_robot("rokbani5", full["problem"])
    np.testing.assert_allclose(np.degrees(arm.lower), -180)
    np.testing.assert_allclose(np.degrees(arm.upper), 180)


def test_table3_reachable_and_independent_orientations_share_the_positions():
    reach, indep = _load("mpso-table3").targets, _load("mpso-table3-independent").targets
    assert len(reach) == len(indep) == 100
    for r, i in zip(reach, indep, strict=True):
        np.testing.assert_array_equal(r.position, i.position)
    assert not np.allclose(reach[0].rotation, indep[0].rotation)
