"""URDF loading: a file written here for the EOSMA arm, the real URDFs in shared/data."""

from pathlib import Path

import numpy as np
import pytest

from moik.exceptions import MoikError, UnknownNameError
from moik.robots import fk_reference, get_robot
from moik.robots.urdf import URDFError, load_urdf

URDF_DIR = Path(__file__).resolve().parents[3] / "shared" / "data" / "urdf"

# EOSMA Table 1 (standard DH, here in metres): joint i+1's origin is
# Tz(d_i) Tx(a_i) Rx(alpha_i) = xyz (a_i, 0, d_i), rpy (alpha_i, 0, 0).
EOSMA_ROWS = [(0.0, -np.pi / 2, 0.50), (0.20, np.pi / 2, 0.0), (0.25, -np.pi / 2, 0.0),
              (0.30, np.pi / 2, 0.0), (0.20, -np.pi / 2, 0.0), (0.20, 0.0, 0.0),
              (0.10, 0.0, 0.05)]
EOSMA_LIMITS = [(-np.pi, np.pi), (-np.pi / 2, np.pi / 6), (-np.pi / 2, 2 * np.pi / 3),
                (-np.pi / 2, np.pi / 2), (-np.pi / 2, np.pi / 2), (-np.pi / 2, np.pi / 2),
                (-np.pi / 6, np.pi / 2)]


def _eosma_urdf() -> str:
    parts = ['<robot name="eosma7_urdf">'] + [f'<link name="l{i}"/>' for i in range(9)]
    prev = (0.0, 0.0, 0.0)
    for i in range(7):
        a, alpha, d = prev
        lo, hi = EOSMA_LIMITS[i]
        parts.append(
            f'<joint name="j{i + 1}" type="revolute"><parent link="l{i}"/>'
            f'<child link="l{i + 1}"/><origin xyz="{a!r} 0 {d!r}" rpy="{alpha!r} 0 0"/>'
            f'<axis xyz="0 0 1"/><limit lower="{lo!r}" upper="{hi!r}" effort="1" '
            f'velocity="1"/></joint>')
        prev = EOSMA_ROWS[i]
    a, alpha, d = prev
    parts.append(f'<joint name="tool" type="fixed"><parent link="l7"/><child link="l8"/>'
                 f'<origin xyz="{a!r} 0 {d!r}" rpy="{alpha!r} 0 0"/></joint></robot>')
    return "\n".join(parts)


def test_eosma7_urdf_matches_dh(tmp_path):
    path = tmp_path / "eosma7.urdf"
    path.write_text(_eosma_urdf())
    robot = load_urdf(path)
    dh = get_robot("eosma7")
    assert robot.dof == 7 and robot.unit == "m"
    np.testing.assert_allclose(robot.lower, dh.lower)
    Q = dh.random_q(100, rng=np.random.default_rng(0))
    T_urdf, T_dh = robot.fk(Q), dh.fk(Q)
    T_urdf[:, :3, 3] *= 100.0  # m -> cm
    np.testing.assert_allclose(T_urdf, T_dh, atol=1e-12 * dh.reach)


@pytest.mark.parametrize(("file", "dof", "tip"), [
    ("lbr_iiwa_14_r820.urdf", 7, "tool0"),
    ("puma560_robot.urdf", 6, None),
    ("ur5_robot.urdf", 6, "wrist_3_link"),
])
def test_real_urdfs_load(file, dof, tip):
    robot = load_urdf(URDF_DIR / file)
    assert robot.dof == dof
    if tip is not None:
        assert robot.source.endswith(f"-> {tip}")
    Q = robot.random_q(50, rng=np.random.default_rng(1))
    T = robot.fk(Q)
    assert np.all(np.isfinite(T))
    np.testing.assert_allclose(T, fk_reference(robot, Q), atol=1e-12)


def test_panda_needs_a_tip():
    with pytest.raises(URDFError, match="branches at link 'panda_hand'; pass tip_link="):
        load_urdf(URDF_DIR / "panda.urdf")
    robot = load_urdf(URDF_DIR / "panda.urdf", tip_link="panda_hand_tcp")
    assert robot.dof == 7
    robot = load_urdf(URDF_DIR / "panda.urdf", tip_link="panda_leftfinger")
    assert robot.dof == 8 and robot.joint_types[-1] == "prismatic"


def test_iiwa_known_pose():
    """At q = 0 the iiwa is straight up: flange height 0.36+0.42+0.4+0.126 = 1.306 m
    (KUKA LBR iiwa 14 R820 data sheet link lengths, as in the URDF)."""
    robot = load_urdf(URDF_DIR / "lbr_iiwa_14_r820.urdf")
    np.testing.assert_allclose(robot.fk(np.zeros(7))[:3, 3], [0, 0, 1.306], atol=1e-9)


def test_bad_urdfs(tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot><link name='a'/>")
    with pytest.raises(URDFError, match="cannot read URDF"):
        load_urdf(bad)
    with pytest.raises(UnknownNameError, match="unknown link 'nope'; expected one of"):
        load_urdf(URDF_DIR / "puma560_robot.urdf", tip_link="nope")
    with pytest.raises(MoikError, match="cannot read URDF"):
        load_urdf(tmp_path / "missing.urdf")
