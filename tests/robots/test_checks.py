"""Validation of robot descriptions (moik/robots/checks.py): real numbers only,
joint types and names, and the warning for angles that look like degrees."""

import warnings

import numpy as np
import pytest

from moik.exceptions import DegreesWarning, MoikWarning, ParameterError, ShapeError
from moik.robots import Robot, available_robots, get_robot
from moik.robots.checks import FULL_TURN, LIMIT_TURNS

DH = dict(a=[0.3, 0.2], alpha=[np.pi / 2, 0.0], d=[0.1, 0.0], theta=[0.0, 0.0],
          lower=[-np.pi, -np.pi], upper=[np.pi, np.pi])


def _robot(**kw) -> Robot:
    return Robot(name="arm", **{**DH, **kw})


def test_catalog_robots_do_not_warn():
    """Including the IRB-2600, whose axes 4 and 6 turn +-400 deg (6.98 rad)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", MoikWarning)
        for name in available_robots():
            get_robot(name)
        get_robot("irb2600").with_locked_joints({0: 0.0})


@pytest.mark.parametrize(("kw", "message"), [
    (dict(lower=[-180, -90], upper=[180, 90]), r"revolute lower limits reach 180 \(beyond 2 turns"),
    (dict(lower=[0, 0], upper=[170, 135]), r"revolute upper limits reach 170"),
    (dict(alpha=[90, 0]), r"alpha reaches 90 \(beyond 2 pi\)"),
    (dict(theta=[0, -90]), r"theta reaches 90 \(beyond 2 pi\)"),
    (dict(alpha=[-90, 0], upper=[180, 180], lower=[-180, -180]), r"alpha reaches 90.*limits"),
])
def test_degrees_warn(kw, message):
    with pytest.warns(DegreesWarning, match=message) as record:
        _robot(**kw)
    assert "look like degrees; moik takes angles in radians" in str(record[0].message)
    assert record[0].filename == __file__  # points at the caller's line
    assert issubclass(DegreesWarning, UserWarning)


def test_radians_near_the_thresholds_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error", DegreesWarning)
        _robot(alpha=[2 * np.pi, -2 * np.pi], theta=[FULL_TURN, 0.0])
        _robot(lower=[-LIMIT_TURNS * 2 * np.pi, -1.0], upper=[LIMIT_TURNS * 2 * np.pi, 1.0])
        # prismatic limits are lengths: 500 mm is no angle
        _robot(joint_types=("revolute", "prismatic"), lower=[-1.0, 0.0], upper=[1.0, 500.0])
    with pytest.warns(DegreesWarning, match="upper limits reach"):
        _robot(lower=[-1.0, -1.0], upper=[1.0, 2 * LIMIT_TURNS * np.pi + 0.01])


def test_general_chain_limits_warn():
    with pytest.warns(DegreesWarning, match="revolute upper limits reach 360"):
        Robot(name="g", origins=np.broadcast_to(np.eye(4), (2, 4, 4)), lower=[0.0],
              upper=[360.0])


@pytest.mark.parametrize(("kw", "message"), [
    (dict(a=["0.3", "0.2"]), r"a must be an array of real numbers, got strings"),
    (dict(d=[0.1 + 1j, 0.0]), r"d must be an array of real numbers, got complex numbers"),
    (dict(alpha=[[0.0], [0.0, 1.0]]), r"alpha must be an array of real numbers with rows of "
                                      r"equal length"),
    (dict(lower="-1 -1"), r"lower limits must be an array of real numbers, got a str"),
    (dict(upper={"q1": 1.0}), r"upper must be an array of real numbers, got a dict"),
    (dict(lower=[True, False]), r"lower limits must be an array of real numbers, got booleans"),
])
def test_description_arrays_must_be_real_numbers(kw, message):
    with pytest.raises(ShapeError, match=message):
        _robot(**kw)


@pytest.mark.parametrize(("kw", "message"), [
    (dict(joint_types="revolute"), "joint_types must be a sequence of 2 entries"),
    (dict(joint_types=("revolute",)), "joint_types must be 2 entries"),
    (dict(name=""), "robot name must be a non-empty string"),
    (dict(name=7), "robot name must be a non-empty string, got 7"),
])
def test_bad_types_and_names(kw, message):
    args = {**DH, "name": "arm", **kw}
    with pytest.raises(ParameterError, match=message):
        Robot(**args)


def test_joint_values_that_look_like_degrees_warn_and_name_the_joint():
    arm = get_robot("eosma7")
    with pytest.warns(DegreesWarning, match=r"q for robot 'eosma7': joint 1 \(q1\) = 45 is more "
                                            r"than a turn beyond its limits"):
        arm.fk([45, 0, 45, 0, 45, 0, 0])
    with pytest.warns(DegreesWarning, match="every revolute value is a whole number"):
        arm.fk([7, 0, 0, 0, 0, 0, 0])  # within a turn of the limits, but whole numbers > 2 pi
    irb = get_robot("irb2600")
    with warnings.catch_warnings():
        warnings.simplefilter("error", DegreesWarning)
        arm.fk([0.7, 0.0, 0.7, 0.0, 0.7, 0.0, 0.0])  # radians
        arm.fk([1, 0, 1, 0, 1, 0, 0])  # whole radians, none beyond a turn
        irb.fk(np.radians([0, 0, 0, 390, 0, -390]))  # multi-turn joints within their limits
        get_robot("scara4").fk([0.1, 0.2, 0.3, 0.4])


def test_outside_limits_names_the_joints():
    arm = get_robot("eosma7")
    assert arm.outside_limits(np.zeros(7)) == ""
    assert arm.outside_limits([0, 1, 0, 0, 0, 0, -1]) == (
        "joint 2 (q2) = 1 above its upper limit 0.523599; joint 7 (q7) = -1 below its lower "
        "limit -0.523599")
