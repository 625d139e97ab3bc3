"""Robot model and batched FK: reference values, conventions, properties, bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.exceptions import LimitsError, NonFiniteError, ParameterError, ShapeError
from moik.robots import Robot, available_robots, fk_reference, get_robot

DEG = np.pi / 180


def test_eosma7_reference_pose():
    """EOSMA paper, Simulation section: (45,0,45,0,45,0,0) deg ->
    P1 = (-24.748737, 100.961941, 50.000000) cm (also in reference-facts.md)."""
    T = get_robot("eosma7").fk(np.array([45, 0, 45, 0, 45, 0, 0]) * DEG)
    np.testing.assert_allclose(T[:3, 3], [-24.748737, 100.961941, 50.0], atol=5e-7)


def test_rokbani5_reference_position():
    """MO-m-PSO paper Section 4.1 / Eq. 16:
    (30,60,45,60,60) deg -> (25.1441, 9.5735, 18.0927) cm."""
    T = get_robot("rokbani5").fk(np.array([30, 60, 45, 60, 60]) * DEG)
    np.testing.assert_allclose(T[:3, 3], [25.1441, 9.5735, 18.0927], atol=5e-5)


@pytest.mark.parametrize("name", available_robots())
def test_fast_fk_equals_reference(name):
    robot = get_robot(name)
    Q = robot.random_q(200, rng=np.random.default_rng(3))
    scale = max(1.0, robot.reach)
    np.testing.assert_allclose(robot.fk(Q), fk_reference(robot, Q), rtol=0, atol=1e-12 * scale)


@pytest.mark.parametrize("name", available_robots())
def test_catalog_limits_and_finite_fk(name):
    robot = get_robot(name)
    assert robot.lower.shape == robot.upper.shape == (robot.dof,)
    assert np.all(robot.lower <= robot.upper)
    corners = np.stack([robot.lower, robot.upper, (robot.lower + robot.upper) / 2])
    Q = np.vstack([corners, robot.random_q(100, rng=np.random.default_rng(0))])
    assert np.all(np.isfinite(robot.fk(Q)))
    assert robot.source


def test_single_and_batch_shapes():
    robot = get_robot("puma560")
    q = np.zeros(6)
    assert robot.fk(q).shape == (4, 4)
    assert robot.fk(np.zeros((5, 6))).shape == (5, 4, 4)
    assert robot.frames(q).shape == (7, 4, 4)
    F = robot.frames(np.zeros((3, 6)))
    assert F.shape == (3, 7, 4, 4)
    np.testing.assert_array_equal(F[:, 0], np.broadcast_to(np.eye(4), (3, 4, 4)))


def test_frames_are_prefix_chains():
    """Frame j of the full robot equals the end pose of the first-j-joints robot."""
    robot = get_robot("irb2600")
    q = robot.random_q(4, rng=np.random.default_rng(1))
    frames = robot.frames(q)
    for j in range(1, robot.dof + 1):
        sub = Robot(name="sub", a=robot.a[:j], alpha=robot.alpha[:j], d=robot.d[:j],
                    theta=robot.theta[:j], lower=robot.lower[:j], upper=robot.upper[:j],
                    convention=robot.convention, unit=robot.unit)
        np.testing.assert_allclose(frames[:, j], sub.fk(q[:, :j]), atol=1e-9)


def test_modified_and_standard_dh_agree():
    """A 3-R arm written both ways. Standard rows (a_i, alpha_i, d_i) become
    modified rows (a_{i-1}, alpha_{i-1}, d_i) shifted by one, plus a fixed tool
    transform Tx(a_n) Rx(alpha_n) for the last standard row; choose a_3 = alpha_3 = 0
    so both describe the same end frame."""
    std = Robot(name="std", a=[0.1, 0.4, 0.0], alpha=[np.pi / 2, 0.0, 0.0], d=[0.3, 0.05, 0.2],
                theta=np.zeros(3), lower=-np.pi * np.ones(3), upper=np.pi * np.ones(3))
    mod = Robot(name="mod", a=[0.0, 0.1, 0.4], alpha=[0.0, np.pi / 2, 0.0], d=[0.3, 0.05, 0.2],
                theta=np.zeros(3), lower=-np.pi * np.ones(3), upper=np.pi * np.ones(3),
                convention="modified")
    Q = std.random_q(50, rng=np.random.default_rng(2))
    np.testing.assert_allclose(std.fk(Q), mod.fk(Q), atol=1e-14)


def test_prismatic_joint_moves_along_z():
    robot = get_robot("scara4")
    q = np.array([0.0, 0.0, 0.1, 0.0])
    q2 = q.copy()
    q2[2] = 0.3
    dp = robot.fk(q2)[:3, 3] - robot.fk(q)[:3, 3]
    np.testing.assert_allclose(dp, [0, 0, -0.2], atol=1e-15)  # alpha2 = pi flips z


def test_irb2600_offset_is_applied():
    """theta2 + 90 deg: at q = 0 the upper arm of the IRB-2600 points up."""
    robot = get_robot("irb2600")
    frames = robot.frames(np.zeros(6))
    elbow = frames[3, :3, 3]
    shoulder = frames[2, :3, 3]
    assert abs(abs(elbow[2] - shoulder[2]) - 700.0) < 1e-9


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(available_robots()), st.integers(0, 2**32 - 1))
def test_rotations_are_orthonormal(name, seed):
    robot = get_robot(name)
    R = robot.fk(robot.random_q(20, rng=np.random.default_rng(seed)))[:, :3, :3]
    np.testing.assert_allclose(R @ np.swapaxes(R, 1, 2), np.broadcast_to(np.eye(3), R.shape),
                               atol=1e-12)
    np.testing.assert_allclose(np.linalg.det(R), 1.0, atol=1e-12)


def _robot(**kw):
    base = dict(name="x", a=[1.0, 1.0], alpha=[0.0, 0.0], d=[0.0, 0.0], theta=[0.0, 0.0],
                lower=[-1.0, -1.0], upper=[1.0, 1.0])
    base.update(kw)
    return Robot(**base)


def test_bad_robot_definitions():
    with pytest.raises(LimitsError, match=r"lower limit > upper limit for joint\(s\) \[2\]"):
        _robot(lower=[-1.0, 2.0], upper=[1.0, 1.0])
    with pytest.raises(ShapeError, match=r"alpha must have shape \(2,\)"):
        _robot(alpha=[0.0])
    with pytest.raises(NonFiniteError, match="d must be finite"):
        _robot(d=[np.nan, 0.0])
    with pytest.raises(ParameterError, match="unit must be one of"):
        _robot(unit="inch")
    with pytest.raises(ParameterError, match="convention must be 'standard' or 'modified'"):
        _robot(convention="craig")
    with pytest.raises(ParameterError, match="joint_types must be 2 entries"):
        _robot(joint_types=("revolute", "spherical"))


def test_bad_joint_vectors():
    robot = get_robot("eosma7")
    with pytest.raises(ShapeError, match=r"must have shape \(7,\) or \(n, 7\), got \(6,\)"):
        robot.fk(np.zeros(6))
    with pytest.raises(ShapeError, match=r"got \(2, 2, 7\)"):
        robot.fk(np.zeros((2, 2, 7)))
    with pytest.raises(NonFiniteError, match="NaN or inf"):
        robot.fk(np.array([0, 0, np.nan, 0, 0, 0, 0.0]))


def test_robot_is_frozen():
    robot = get_robot("eosma7")
    with pytest.raises(AttributeError):
        robot.name = "other"
    with pytest.raises(ValueError):
        robot.a[0] = 1.0


@pytest.mark.parametrize("name", ["puma560", "scara4", "irb2600"])
def test_locked_joints_equal_full_robot(name):
    robot = get_robot(name)
    locked = {1: 0.3, robot.dof - 1: -0.2} if name != "scara4" else {2: 0.4}
    sub = robot.with_locked_joints(locked)
    free = [j for j in range(robot.dof) if j not in locked]
    assert sub.dof == len(free) and not sub.is_dh
    Qs = sub.random_q(30, rng=np.random.default_rng(4))
    Q = np.zeros((30, robot.dof))
    Q[:, free] = Qs
    for j, v in locked.items():
        Q[:, j] = v
    np.testing.assert_allclose(sub.fk(Qs), robot.fk(Q), atol=1e-12 * robot.reach)
    np.testing.assert_allclose(fk_reference(sub, Qs), robot.fk(Q), atol=1e-12 * robot.reach)


def test_general_chain_from_dh_origins():
    robot = get_robot("irb2600")
    general = Robot(name="g", origins=robot.chain_origins(), lower=robot.lower,
                    upper=robot.upper, unit="mm")
    Q = robot.random_q(30, rng=np.random.default_rng(5))
    np.testing.assert_allclose(general.fk(Q), robot.fk(Q), atol=1e-9)
    assert general.reach == pytest.approx(robot.reach)


def test_bad_locked_joints():
    robot = get_robot("puma560")
    with pytest.raises(ParameterError, match=r"locked joint indices must be in 0..5, got \[6\]"):
        robot.with_locked_joints({6: 0.0})
    with pytest.raises(ParameterError, match="at least one joint must stay free"):
        robot.with_locked_joints({j: 0.0 for j in range(6)})
    with pytest.raises(ParameterError, match="DH rows or origins, not both"):
        Robot(name="x", origins=np.broadcast_to(np.eye(4), (3, 4, 4)), a=[0, 0],
              alpha=[0, 0], d=[0, 0], theta=[0, 0], lower=[0, 0], upper=[1, 1])


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**32 - 1), st.sampled_from([0.0, 1e-9, np.pi / 2, np.pi / 2 - 2e-9]))
def test_fixed_transform_reproduced_exactly(seed, near):
    """Any constant transform, including ones a hair off axis-aligned (as in real
    URDFs), is reproduced by the kernels: a one-joint chain at q = 0 whose first
    (or last) fixed transform is F has pose F."""
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(seed)
    rotations = [Rotation.random(random_state=seed).as_matrix(),
                 Rotation.from_euler("xyz", [near, 0, 0]).as_matrix(),
                 Rotation.from_euler("zyx", [near, near, 0]).as_matrix()]
    for R in rotations:
        F = np.eye(4)
        F[:3, :3], F[:3, 3] = R, rng.normal(size=3)
        for origins in ([F, np.eye(4)], [np.eye(4), F]):
            robot = Robot(name="F", origins=np.array(origins), lower=[-1.0], upper=[1.0])
            np.testing.assert_allclose(robot.fk(np.zeros(1)), F, atol=1e-15)


def test_a_chain_whose_reach_overflows_is_refused():
    """Finite DH lengths that add up to inf (or whose squares overflow) are refused."""
    zeros = np.zeros(3)
    with pytest.raises(ParameterError, match=r"reach .* is inf m; expected a finite length"):
        Robot(name="huge", a=[1e308, 1e308, 1e308], alpha=zeros, d=zeros, theta=zeros,
              lower=-np.ones(3), upper=np.ones(3))
    with pytest.raises(ParameterError, match=r"reach .* is 3e\+120 cm"):
        Robot(name="huge", a=[1e120] * 3, alpha=zeros, d=zeros, theta=zeros,
              lower=-np.ones(3), upper=np.ones(3), unit="cm")
    ok = Robot(name="big", a=[1e50] * 3, alpha=zeros, d=zeros, theta=zeros,
               lower=-np.ones(3), upper=np.ones(3))
    assert np.isfinite(ok.fk(np.zeros(3))).all()


def test_an_unpickled_robot_keeps_its_arrays_read_only():
    """As the constructor leaves them: an unpickled robot (a worker's, a background
    compile's) is as immutable, and its arrays of the same numba types."""
    import pickle

    import numba

    from moik.robots import get_robot

    robot = get_robot("puma560")
    again = pickle.loads(pickle.dumps(robot))
    for name in ("lower", "upper", "a", "alpha", "d", "theta", "base", "tool"):
        assert not getattr(again, name).flags.writeable, name
        assert numba.typeof(getattr(again, name)) == numba.typeof(getattr(robot, name))
    np.testing.assert_array_equal(again.fk(np.zeros(6)), robot.fk(np.zeros(6)))
