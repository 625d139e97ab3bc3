"""URDF loading: a file written here for the EOSMA arm, the real URDFs moik ships."""

from pathlib import Path

import numpy as np
import pytest

import moik.robots
from moik.exceptions import MoikError, UnknownNameError
from moik.robots import fk_reference, get_robot
from moik.robots.urdf import URDFError, load_urdf

URDF_DIR = Path(moik.robots.__file__).with_name("data")  # the URDFs moik ships

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


def _chain(*joints: str, links=("a", "b", "c")) -> str:
    return ("<robot name='t'>" + "".join(f"<link name='{n}'/>" for n in links)
            + "".join(joints) + "</robot>")


def _joint(name, parent, child, extra="", jtype="revolute"):
    return (f"<joint name='{name}' type='{jtype}'><parent link='{parent}'/>"
            f"<child link='{child}'/><axis xyz='0 0 1'/>"
            f"<limit lower='-1' upper='1'/>{extra}</joint>")


def test_urdf_from_a_string_equals_the_file():
    text = (URDF_DIR / "ur5_robot.urdf").read_text()
    a = load_urdf(text, tip_link="tool0")
    b = load_urdf(URDF_DIR / "ur5_robot.urdf", tip_link="tool0")
    Q = a.random_q(20, rng=np.random.default_rng(2))
    np.testing.assert_array_equal(a.fk(Q), b.fk(Q))
    assert a.name == "ur5:tool0"  # the file's robot name and the chain's tip


def test_a_files_default_chain_is_named_after_its_tip_not_the_catalog_arm():
    """ur5_robot.urdf's default chain ends at wrist_3_link, 0.0823 m before the catalog
    ``ur5``'s tool0: the two must not both be called "ur5"."""
    file_arm, catalog = load_urdf(URDF_DIR / "ur5_robot.urdf"), get_robot("ur5")
    assert file_arm.name == "ur5:wrist_3_link" and catalog.name == "ur5"
    assert "-> wrist_3_link" in file_arm.source and "-> tool0" in catalog.source
    q = np.zeros((1, 6))
    gap = np.linalg.norm(file_arm.fk(q)[0, :3, 3] - catalog.fk(q)[0, :3, 3])
    assert gap == pytest.approx(0.0823, abs=1e-4)


def test_a_branching_chain_suggests_every_leaf_even_a_fixed_tcp():
    with pytest.raises(URDFError, match="panda_hand_tcp") as exc:
        load_urdf(URDF_DIR / "panda.urdf")
    assert "panda_leftfinger" in str(exc.value)


def test_cyclic_urdf_is_refused_not_hung():
    text = _chain(_joint("j1", "a", "b"), _joint("j2", "b", "c"), _joint("j3", "c", "b"))
    with pytest.raises(URDFError, match="two parent joints"):
        load_urdf(text)
    ring = _chain(_joint("j1", "a", "b"), _joint("j2", "b", "a"), links=("a", "b"))
    with pytest.raises(URDFError, match="cycle"):
        load_urdf(ring)


def test_absurd_lengths_are_refused_not_solved_with_infinite_reach():
    """Before: 1e200 m origins loaded with reach = inf, and every target came back
    'solved' with position error inf (tolerance 1e-9 x inf)."""
    text = (URDF_DIR / "ur5_robot.urdf").read_text()
    huge = text.replace('xyz="0.0 0.0 0.089159"', 'xyz="1e200 1e200 1e200"')
    assert huge != text
    with pytest.raises(URDFError, match=r"reach .* is inf m; expected a finite length below"):
        load_urdf(huge, tip_link="tool0")
    far = "<origin xyz='1.5e308 0 0'/>"
    with pytest.raises(URDFError, match="to joint 'j2' overflows"):  # 3e308 = inf
        load_urdf(_chain(_joint("j1", "a", "b", far, jtype="fixed"), _joint("j2", "b", "c", far)))
    stroke = _joint("j1", "a", "b", jtype="prismatic").replace("upper='1'", "upper='1e300'")
    with pytest.raises(URDFError, match="reach|limits must lie within"):
        load_urdf(_chain(stroke, links=("a", "b")))


def test_an_axis_whose_norm_overflows_is_normalised_safely():
    """Before: |(1e300, 1e300, 0)| = inf passed the zero check and scipy raised ValueError."""
    for big, unit in (("1e300 1e300 0", "1 1 0"), ("0 -1e308 1e308", "0 -1 1"),
                      ("1e-320 0 0", "1 0 0")):
        a = load_urdf(_chain(_joint("j1", "a", "b").replace("'0 0 1'", f"'{big}'"),
                             links=("a", "b")))
        b = load_urdf(_chain(_joint("j1", "a", "b").replace("'0 0 1'", f"'{unit}'"),
                             links=("a", "b")))
        Q = a.random_q(5, rng=np.random.default_rng(1))
        np.testing.assert_allclose(a.fk(Q), b.fk(Q), rtol=0, atol=1e-15)
    with pytest.raises(URDFError, match="axis must be non-zero"):
        load_urdf(_chain(_joint("j1", "a", "b").replace("'0 0 1'", "'0 0 0'"), links=("a", "b")))


def test_malformed_trees_get_precise_messages():
    with pytest.raises(URDFError, match="link 'ghost', which is not declared"):
        load_urdf(_chain(_joint("j1", "a", "ghost")))
    with pytest.raises(URDFError, match="two joints are named 'j1'"):
        load_urdf(_chain(_joint("j1", "a", "b"), _joint("j1", "b", "c")))
    with pytest.raises(URDFError, match="link 'b' has two parent joints"):
        load_urdf(_chain(_joint("j1", "a", "b"), _joint("j2", "c", "b")))
    unnamed = _chain(_joint("j1", "a", "b").replace(" name='j1'", ""), links=("a", "b"))
    with pytest.raises(URDFError, match="every <joint> needs a name="):
        load_urdf(unnamed)
    # before: a <link> without name= raised TypeError from sorting the root links, and a
    # link declared twice was taken silently (urdfdom refuses both)
    nameless = _chain(_joint("j1", "a", "b")).replace("</robot>",
                                                      "<link><collision/></link></robot>")
    with pytest.raises(URDFError, match="every <link> needs a name="):
        load_urdf(nameless, tip_link="b")
    with pytest.raises(URDFError, match="every <link> needs a name="):
        load_urdf(nameless)
    with pytest.raises(URDFError, match=r"links declared more than once: \['b'\]"):
        load_urdf(_chain(_joint("j1", "a", "b"), links=("a", "b", "b")))


def test_xacro_floating_and_mimic_are_explained(tmp_path):
    xacro = tmp_path / "arm.urdf.xacro"
    xacro.write_text("<robot/>")
    with pytest.raises(URDFError, match="run xacro first"):
        load_urdf(xacro)
    macro = ("<robot name='x' xmlns:xacro='http://www.ros.org/wiki/xacro'>"
             "<xacro:macro name='m'/></robot>")
    with pytest.raises(URDFError, match="run xacro first"):
        load_urdf(macro)
    floating = _chain(_joint("free", "a", "b", jtype="floating"), _joint("j2", "b", "c"))
    with pytest.raises(URDFError, match="'floating'.*pass base_link="):
        load_urdf(floating)
    assert load_urdf(floating, base_link="b").dof == 1
    mimic = _chain(_joint("j1", "a", "b"), _joint("j2", "b", "c", "<mimic joint='j1'/>"))
    with pytest.raises(URDFError, match="'j2' mimics joint 'j1'"):
        load_urdf(mimic)
    with pytest.raises(URDFError, match="file path or an XML string"):
        load_urdf(3)
    for empty in ("", "  \n"):  # before: "cannot read URDF '.': [Errno 21] Is a directory"
        with pytest.raises(URDFError, match="got an empty string"):
            load_urdf(empty)


@pytest.mark.parametrize(("name", "dof", "tip"), [
    ("iiwa14", 7, "tool0"), ("panda", 7, "panda_hand_tcp"), ("ur5", 6, "tool0"),
    ("puma560-urdf", 6, "link7")])
def test_shipped_urdf_arms_are_catalog_robots(name, dof, tip):
    robot = get_robot(name)
    assert robot.dof == dof and robot.unit == "m" and f"-> {tip}" in robot.source
    Q = robot.random_q(20, rng=np.random.default_rng(3))
    np.testing.assert_allclose(robot.fk(Q), fk_reference(robot, Q), atol=1e-12)


def test_the_robot_keeps_its_urdf_and_package_folders(tmp_path, monkeypatch):
    robot = load_urdf(URDF_DIR / "ur5_robot.urdf", tip_link="tool0", package_dirs=[tmp_path])
    assert robot.description.source == (URDF_DIR / "ur5_robot.urdf").resolve()
    assert robot.description.package_dirs == [tmp_path]
    text = (URDF_DIR / "ur5_robot.urdf").read_text()
    assert load_urdf(text, tip_link="tool0").description.source == text
    assert get_robot("ur5").description.package_dirs == [URDF_DIR / "packages"]
    assert robot.with_locked_joints({0: 0.0}).description is None  # another chain
    # before: a relative folder was kept as given, and after os.chdir the meshes were "not
    # found"; kept absolute, as the URDF's own path is
    monkeypatch.chdir(tmp_path.parent)
    relative = load_urdf(URDF_DIR / "ur5_robot.urdf", tip_link="tool0",
                         package_dirs=[tmp_path.name])
    by_name = load_urdf(URDF_DIR / "ur5_robot.urdf", tip_link="tool0",
                        package_dirs={"pkg": tmp_path.name})
    monkeypatch.chdir(URDF_DIR)
    assert relative.description.package_dirs == [tmp_path]
    assert by_name.description.package_dirs == {"pkg": tmp_path}
    with pytest.raises(MoikError, match="description must be"):
        type(robot)(name="x", lower=[0.0], upper=[1.0], a=[1.0], alpha=[0.0], d=[0.0],
                    theta=[0.0], description="panda.urdf")


def test_a_limit_beyond_any_physical_one_is_refused():
    """Before: lower=-1e308 loaded, and solve_ik then raised a misleading NonFiniteError."""
    joint = _joint("j1", "a", "b").replace("lower='-1'", "lower='-1e308'")
    assert "-1e308" in joint
    with pytest.raises(URDFError, match="limits must lie within"):
        load_urdf(_chain(joint, _joint("j2", "b", "c")))


@pytest.mark.parametrize(("package_dirs", "match"), [
    (5, "got int"), (b"/tmp", "got bytes"), ("/no/such/folder", "is not a folder"),
    ({"arm": 3}, "'arm': 3"), ({"arm": "/no/such/folder"}, r"not a folder \(package 'arm'\)"),
    (["/tmp", 4], "got 4"),
])
def test_package_dirs_are_checked_when_given(package_dirs, match):
    """A wrong package_dirs is named at load_urdf, not at the first collision-aware solve."""
    from moik.exceptions import ParameterError
    with pytest.raises(ParameterError, match=match):
        load_urdf(_eosma_urdf(), package_dirs=package_dirs)
