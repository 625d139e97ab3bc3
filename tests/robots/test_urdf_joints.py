"""Movable joints outside the IK chain placed at stated values (moik/robots/urdf_joints.py)
and the links behind them on the chain's bodies (moik/robots/urdf_geometry.py)."""

import numpy as np
import pytest

from moik import get_robot, load_urdf
from moik.exceptions import ParameterError, URDFError
from moik.robots.catalog import DATA
from moik.robots.urdf_geometry import link_placements, offchain_placement

PANDA = DATA / "panda.urdf"

GRIPPER = """<robot name="g">
  <link name="base"/><link name="arm"/><link name="palm"/><link name="a"/><link name="b"/>
  <link name="wheel"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-2" upper="2"/></joint>
  <joint name="f" type="fixed"><parent link="arm"/><child link="palm"/>
    <origin xyz="0.5 0 0"/></joint>
  <joint name="ja" type="revolute"><parent link="palm"/><child link="a"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 0 1"/><limit lower="0.2" upper="1"/></joint>
  <joint name="jb" type="revolute"><parent link="palm"/><child link="b"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="-0.1"/>
    <mimic joint="ja" multiplier="-1" offset="0.1"/></joint>
  <joint name="jw" type="continuous"><parent link="base"/><child link="wheel"/>
    <axis xyz="0 0 1"/></joint>
</robot>"""


def _gripper():
    return load_urdf(GRIPPER, tip_link="palm")


def test_panda_fingers_ride_on_the_hand_at_their_opening():
    robot = get_robot("panda")
    names, closed = link_placements(PANDA, robot)
    _, opened = link_placements(PANDA, robot, joint_values={"panda_finger_joint1": 0.04})
    hand = names.index("panda_link7")
    for link, sign in (("panda_leftfinger", 1), ("panda_rightfinger", -1)):
        assert closed[link][0] == opened[link][0] == hand
        # along the hand's y axis (the joints' axes, +y and -y), 0.04 apart
        shift = opened[link][1][:3, 3] - closed[link][1][:3, 3]
        y = closed["panda_hand"][1][:3, 1]
        np.testing.assert_allclose(shift, sign * 0.04 * y, atol=1e-12)
    placement = offchain_placement(PANDA, robot)
    assert [p.describe(n) for n, p in placement.items()] == [
        "panda_finger_joint1 = 0 (default: its zero clipped into its limits)",
        "panda_finger_joint2 = 0 (mimics panda_finger_joint1)"]


def test_defaults_clip_zero_and_mimics_follow_with_multiplier_and_offset():
    robot = _gripper()
    placement = offchain_placement(GRIPPER, robot)
    assert list(placement) == ["ja", "jb", "jw"]
    assert placement["ja"].value == 0.2 and placement["ja"].how == "default"  # 0 -> [0.2, 1]
    assert placement["jb"].value == pytest.approx(-0.1) and placement["jb"].leader == "ja"
    assert placement["jw"].value == 0.0
    given = offchain_placement(GRIPPER, robot, {"ja": 0.5, "jw": 3.0})  # continuous: [-pi, pi]
    assert given["jb"].value == pytest.approx(-0.4) and given["jw"].how == "given"
    _, placed = link_placements(GRIPPER, robot, joint_values={"ja": 0.5})
    assert placed["a"][0] == placed["b"][0] == 1 and placed["wheel"][0] == 0
    np.testing.assert_allclose(placed["a"][1][:3, 0], [np.cos(0.5), np.sin(0.5), 0], atol=1e-12)
    np.testing.assert_allclose(placed["b"][1][:3, 0], [np.cos(0.4), -np.sin(0.4), 0],
                               atol=1e-12)


@pytest.mark.parametrize("values, match", [
    ({"nope": 0.0}, r"unknown key\(s\) nope; expected some of: ja, jw"),
    ({"ja": float("nan")}, r"joint_values\['ja'\] must be a number in \[0.2, 1.0\], got nan"),
    ({"ja": 1.5}, r"joint_values\['ja'\] must be a number in \[0.2, 1.0\], got 1.5"),
    ({"ja": "0.5"}, r"must be a number"),
    ({"jb": 0.0}, r"'jb' mimics 'ja' and follows it; give 'ja' instead"),
    ({"j1": 0.0}, r"'j1' is a joint of the IK chain"),
    ([("ja", 0.5)], r"joint_values must be a mapping"),
])
def test_bad_joint_values(values, match):
    with pytest.raises(ParameterError, match=match):
        offchain_placement(GRIPPER, _gripper(), values)


def test_a_mimic_pushed_outside_its_limits():
    urdf = GRIPPER.replace('offset="0.1"', 'offset="-0.5"')  # jb = -ja - 0.5
    assert offchain_placement(urdf, _gripper())["jb"].value == pytest.approx(-0.7)
    with pytest.raises(ParameterError, match=r"'jb' mimics 'ja' .* = -1.5, outside its limits "
                                             r"\[-1, -0.1\]; give 'ja' a value"):
        offchain_placement(urdf, _gripper(), {"ja": 1.0})


@pytest.mark.parametrize("edit, match", [
    (('<mimic joint="ja"', '<mimic joint="j1"'), "mimics 'j1', a joint of the IK chain"),
    (('<mimic joint="ja"', '<mimic joint="f"'), "mimics 'f', which is not a movable joint"),
    (('name="jw" type="continuous"', 'name="jw" type="floating"'), "'jw' is 'floating'"),
    (('offset="0.1"', 'offset="x"'), "multiplier and offset must be numbers"),
])
def test_offchain_joints_that_cannot_be_placed(edit, match):
    urdf = GRIPPER.replace(*edit)
    with pytest.raises(URDFError, match=match):
        link_placements(urdf, load_urdf(urdf, tip_link="palm"))
