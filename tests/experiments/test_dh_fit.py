"""The DH-length fit of I-BES Table 9 (moik.experiments.dh_fit), from the config's paper numbers."""

from pathlib import Path

import numpy as np
import pytest

from moik.exceptions import ConfigError, UnknownNameError
from moik.experiments import load_config
from moik.experiments.dh_fit import fit_dh_lengths, full_q, with_lengths
from moik.robots import get_robot

CONFIG = Path(__file__).resolve().parents[2] / "experiments" / "ibes_table9.toml"
"""This checkout's config (an editable install may map the shipped configs elsewhere)."""


def _paper():
    cfg = load_config(CONFIG)
    return cfg, cfg["paper"], cfg["problem"]["locked_joints_deg"]


def test_fit_to_the_papers_ibes_solutions_gives_the_catalog_lengths():
    cfg, paper, locked = _paper()
    spec, robot = paper["dh_fit"], get_robot("puma560-kalra")
    names = spec["fit_targets"]
    sols = [full_q(robot, [b["paper"] for b in paper["branches"][n]], locked) for n in names]
    fit = fit_dh_lengths(robot, spec["lengths"], spec["start"], sols,
                         [spec["targets"][n] for n in names])
    np.testing.assert_allclose(fit.values, [0.4318, -0.02032, 0.14909, 0.43307], atol=5e-8)
    assert fit.max_residual < 1e-8
    catalog = [getattr(robot, k)[r] for k, r in spec["lengths"]]
    np.testing.assert_allclose(fit.values, catalog, atol=5e-8)
    # T1's solutions land on y = d3, not on the printed 0.15
    t1 = full_q(robot, [b["paper"] for b in paper["branches"]["T1"]], locked)
    p = fit.robot.fk_position(t1)
    np.testing.assert_allclose(p, np.tile([0.6, fit.values[2], 0.2], (4, 1)), atol=1e-8)
    assert cfg["targets"]["points"][0]["position"] == [0.60, 0.14909, 0.20]


def test_fit_starting_from_the_table6_lengths_needs_no_catalog_values():
    _, paper, locked = _paper()
    spec = paper["dh_fit"]
    start_arm = with_lengths(get_robot("puma560-kalra"), spec["lengths"], spec["start"])
    names = spec["fit_targets"]
    sols = [full_q(start_arm, [b["paper"] for b in paper["branches"][n]], locked) for n in names]
    fit = fit_dh_lengths(start_arm, spec["lengths"], spec["start"], sols,
                         [spec["targets"][n] for n in names])
    np.testing.assert_allclose(fit.values, [0.4318, -0.02032, 0.14909, 0.43307], atol=5e-8)


def test_full_q_fills_the_locked_joints():
    robot = get_robot("puma560-kalra")
    q = full_q(robot, [[1.0, 2.0, 3.0]], [None, None, None, 90.0, 0.0, 0.0])
    np.testing.assert_allclose(q, [[1.0, 2.0, 3.0, np.pi / 2, 0.0, 0.0]])


def test_bad_length_entries_are_refused():
    robot = get_robot("puma560-kalra")
    with pytest.raises(UnknownNameError, match="DH length"):
        fit_dh_lengths(robot, [["b", 1]], [0.1], [], [])
    with pytest.raises(ConfigError, match="DH row must be an integer in"):
        fit_dh_lengths(robot, [["a", 6]], [0.1], [], [])
