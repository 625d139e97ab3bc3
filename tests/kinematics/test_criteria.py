"""Secondary criteria of IK solutions: hand-computed values, the 2 pi copies, bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from moik.exceptions import NonFiniteError, ParameterError, ShapeError, UnknownNameError
from moik.kinematics.criteria import (
    CRITERIA,
    Criterion,
    build_criteria,
    build_criterion,
    nearest_copies,
)
from moik.kinematics.criteria_kernels import determinant
from moik.robots import Robot, fk_reference, get_robot


def _planar(l1=0.7, l2=0.4, lower=(-np.pi, -np.pi), upper=(np.pi, np.pi)):
    return Robot(name="planar", a=[l1, l2], alpha=[0.0, 0.0], d=[0.0, 0.0], theta=[0.0, 0.0],
                 lower=lower, upper=upper)


def _reference_jacobian(robot, q, h=1e-6):
    """Central differences of the reference FK (independent of the compiled Jacobian)."""
    J = np.zeros((6, robot.dof))
    for j in range(robot.dof):
        dq = np.zeros(robot.dof)
        dq[j] = h
        Tp, Tm = fk_reference(robot, q + dq), fk_reference(robot, q - dq)
        J[:3, j] = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
        J[3:, j] = Rotation.from_matrix(Tp[:3, :3] @ Tm[:3, :3].T).as_rotvec() / (2 * h)
    return J


def test_planar_two_link_manipulability_is_l1_l2_sin_q2():
    robot = _planar()
    Q = np.array([[0.3, 1.1], [-2.0, -0.4], [1.0, 0.0], [0.2, np.pi / 2]])
    m = build_criterion("manipulability", robot, translation_only=True)(Q)
    np.testing.assert_allclose(m, 0.7 * 0.4 * np.abs(np.sin(Q[:, 1])), rtol=1e-12, atol=1e-15)
    # all six rows, fewer joints than rows: sqrt(det(J^T J)), the product of singular values
    full = build_criterion("manipulability", robot)(Q[:2])
    for q, v in zip(Q[:2], full, strict=True):
        assert v == pytest.approx(np.prod(np.linalg.svd(_reference_jacobian(robot, q))[1]),
                                  rel=1e-7)


@pytest.mark.parametrize("name", ["iiwa14", "ur5"])
def test_manipulability_is_yoshikawa_of_the_reference_jacobian(name):
    robot = get_robot(name)
    Q = robot.random_q(4, rng=np.random.default_rng(3))
    m = build_criterion("manipulability", robot)(Q)
    for q, v in zip(Q, m, strict=True):
        J = _reference_jacobian(robot, q)
        assert v == pytest.approx(np.sqrt(np.linalg.det(J @ J.T)), rel=1e-6)
    assert CRITERIA["manipulability"] == "max"


def test_determinant_matches_numpy():
    rng = np.random.default_rng(0)
    for n in (1, 3, 6):
        A = rng.normal(size=(n, n))
        assert determinant(A.copy()) == pytest.approx(np.linalg.det(A), rel=1e-12)
    assert determinant(np.zeros((3, 3))) == 0.0


def test_joint_motion_takes_the_nearest_two_pi_copy_within_the_limits():
    wide = _planar(lower=(-2 * np.pi, -2 * np.pi), upper=(2 * np.pi, 2 * np.pi))
    narrow = _planar()
    q_ref = np.array([-3.0, 0.5])
    Q = np.array([[3.0, 0.5], [-3.0, 0.9]])
    # wide limits: 3.0 - 2 pi = -3.283 is the same configuration, 0.283 away
    np.testing.assert_allclose(build_criterion("joint_motion", wide, q_current=q_ref)(Q),
                               [2 * np.pi - 6.0, 0.4], rtol=1e-12)
    # +-pi limits: the copy is outside, the arm has to turn 6 rad
    np.testing.assert_allclose(build_criterion("joint_motion", narrow, q_current=q_ref)(Q),
                               [6.0, 0.4], rtol=1e-12)
    assert CRITERIA["joint_motion"] == "min"


def test_joint_motion_of_a_prismatic_joint_is_the_plain_difference():
    robot = Robot(name="rp", a=[0.5, 0.0], alpha=[0.0, 0.0], d=[0.0, 0.0], theta=[0.0, 0.0],
                  lower=[-np.pi, 0.0], upper=[np.pi, 10.0],
                  joint_types=("revolute", "prismatic"))
    value = build_criterion("joint_motion", robot, q_current=[0.0, 1.0])(np.array([[0.3, 8.0]]))
    assert value[0] == pytest.approx(np.hypot(0.3, 7.0), rel=1e-14)


def test_limit_margin_is_the_smallest_normalised_distance_to_a_limit():
    robot = _planar(lower=(-1.0, 0.0), upper=(1.0, 4.0))
    Q = np.array([[0.5, 3.9], [0.0, 2.0], [-1.0, 1.0]])
    np.testing.assert_allclose(build_criterion("limit_margin", robot)(Q), [0.025, 0.5, 0.0],
                               atol=1e-15)
    assert CRITERIA["limit_margin"] == "max"


def test_orientation_is_the_geodesic_angle_to_the_preferred_rotation():
    robot = _planar()
    Q = np.array([[0.3, 0.4], [2.5, 1.5], [-0.1, 0.1]])
    R_ref = Rotation.from_euler("z", 0.2).as_matrix()
    angle = np.abs((Q.sum(axis=1) - 0.2 + np.pi) % (2 * np.pi) - np.pi)
    np.testing.assert_allclose(build_criterion("orientation", robot, rotation=R_ref)(Q), angle,
                               atol=1e-12)


def test_user_callables_are_checked_for_shape_and_finiteness():
    robot = _planar()
    Q = np.zeros((3, 2))
    assert Criterion("first", lambda Q: Q[:, 0])(Q).shape == (3,)
    with pytest.raises(ShapeError, match=r"criterion 'bad' must return shape \(3,\).*\(3, 1\)"):
        Criterion("bad", lambda Q: Q[:, :1])(Q)
    with pytest.raises(ShapeError, match="must return 3 real numbers"):
        Criterion("text", lambda Q: ["a"] * len(Q))(Q)
    with pytest.raises(NonFiniteError, match="'nan' returned a non-finite value"):
        Criterion("nan", lambda Q: np.full(len(Q), np.nan))(Q)
    with pytest.raises(ValueError, match="read-only"):
        Criterion("writer", lambda Q: Q.__setitem__((0, 0), 1.0))(Q)
    with pytest.raises(ParameterError, match="must be callable"):
        Criterion("x", 3.0)
    with pytest.raises(UnknownNameError, match="criterion sense"):
        Criterion("x", np.sum, sense="maximise")
    built = build_criteria([lambda Q: Q[:, 0], "limit_margin"], robot)
    assert [c.name for c in built] == ["criterion_1", "limit_margin"]
    assert [c.sign for c in built] == [1.0, -1.0]


def test_build_criteria_refuses_bad_lists():
    robot = _planar()
    with pytest.raises(UnknownNameError, match="unknown criterion 'speed'.*joint_motion"):
        build_criteria(["speed"], robot)
    with pytest.raises(ParameterError, match="'joint_motion' needs q_current"):
        build_criteria(["joint_motion", "manipulability"], robot)
    with pytest.raises(ParameterError, match="'orientation' is for position-only targets"):
        build_criteria(["orientation"], robot, rotation=np.eye(3))
    with pytest.raises(ParameterError, match="'orientation' needs a rotation"):
        build_criteria(["orientation"], robot, position_only=True)
    with pytest.raises(ParameterError, match="more than once: manipulability"):
        build_criteria(["manipulability", "MANIPULABILITY"], robot)
    with pytest.raises(ParameterError, match="at least one criterion"):
        build_criteria([], robot)
    with pytest.raises(ParameterError, match=r"objectives\[1\] must be a criterion name"):
        build_criteria(["manipulability", 3], robot)
    assert [c.name for c in build_criteria("limit_margin", robot)] == ["limit_margin"]


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_nearest_copies_are_the_same_configuration_nearest_the_reference(seed):
    """Each revolute joint moves by a whole number of turns, stays within its limits and
    lands nearest the reference among such copies (enumerated here); a prismatic joint
    stays; the pose is unchanged (reference FK)."""
    rng = np.random.default_rng(seed)
    robot = Robot(name="wide", a=[0.3, 0.2, 0.0], alpha=[0.0, np.pi / 2, 0.0],
                  d=[0.1, 0.0, 0.2], theta=[0.0, 0.0, 0.0], lower=[-7.0, -2.0, 0.0],
                  upper=[7.0, 9.0, 0.5], joint_types=["revolute", "revolute", "prismatic"])
    Q = robot.random_q(5, rng=rng)
    q_ref = rng.uniform(-10.0, 10.0, 3)
    out = nearest_copies(robot, Q, q_ref)
    turns = (out - Q) / (2 * np.pi)
    np.testing.assert_allclose(turns[:, :2], np.round(turns[:, :2]), atol=1e-9)
    np.testing.assert_array_equal(out[:, 2], Q[:, 2])
    assert np.all(out >= robot.lower - 1e-12) and np.all(out <= robot.upper + 1e-12)
    for q, o in zip(Q, out, strict=True):
        for j in range(2):
            copies = q[j] + 2 * np.pi * np.arange(-4, 5)
            inside = copies[(copies >= robot.lower[j]) & (copies <= robot.upper[j])]
            assert abs(o[j] - q_ref[j]) <= np.min(np.abs(inside - q_ref[j])) + 1e-12
        np.testing.assert_allclose(fk_reference(robot, o), fk_reference(robot, q), atol=1e-12)
