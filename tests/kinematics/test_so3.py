"""SO(3) maths: exp/log against scipy, the Jacobians against each other and finite differences,
the pose residual; near-zero and near-pi angles included."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from moik.kinematics.so3 import (
    exp,
    inverse_left_jacobian,
    left_jacobian,
    log,
    pose_residual,
    pose_residual_jacobian,
    rotation_angle,
    skew,
)

unit_vectors = st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(
    lambda v: np.linalg.norm(v) > 1e-3)
# generic angles, tiny ones (series branches) and ones within 1e-5 of pi
angles = st.one_of(st.floats(0, np.pi), st.floats(0, 1e-7), st.floats(np.pi - 1e-5, np.pi))
angles_below_pi = st.one_of(st.floats(0, np.pi - 1e-3), st.floats(0, 1e-7))


def _rotvec(axis, angle) -> np.ndarray:
    return np.asarray(axis) / np.linalg.norm(axis) * angle


@settings(max_examples=200, deadline=None)
@given(axis=unit_vectors, angle=angles)
def test_rotation_log_matches_scipy(axis, angle):
    phi = _rotvec(axis, angle)
    M = Rotation.from_rotvec(phi).as_matrix()[None]
    expected = Rotation.from_matrix(M).as_rotvec()
    # at exactly pi the sign of the axis is arbitrary: compare rotations there
    got = log(M)
    if angle > np.pi - 1e-5:
        np.testing.assert_allclose(Rotation.from_rotvec(got).as_matrix(), M, atol=1e-9)
    else:
        np.testing.assert_allclose(got, expected, atol=1e-12)


@settings(max_examples=200, deadline=None)
@given(axis=unit_vectors, angle=angles)
def test_exp_matches_scipy_and_log_inverts_it(axis, angle):
    phi = _rotvec(axis, angle)
    R = exp(phi)
    np.testing.assert_allclose(R, Rotation.from_rotvec(phi).as_matrix(), atol=1e-12)
    np.testing.assert_allclose(exp(log(R)), R, atol=1e-9)  # exp(log R) = R, also at pi
    if angle < np.pi - 1e-5:  # log(exp(phi)) = phi where the log is unique
        np.testing.assert_allclose(log(R), phi, atol=1e-10)
    assert rotation_angle(R) == pytest.approx(angle, abs=1e-10)


@settings(max_examples=100, deadline=None)
@given(quaternions=st.lists(st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(
    lambda v: np.linalg.norm(v) > 1e-2), min_size=1, max_size=6))
def test_batched_round_trip_from_random_rotations(quaternions):
    R = Rotation.from_quat(np.array(quaternions)).as_matrix()
    np.testing.assert_allclose(exp(log(R)), R, atol=1e-9)
    np.testing.assert_allclose(rotation_angle(R), np.linalg.norm(log(R), axis=-1), atol=1e-12)
    np.testing.assert_allclose(rotation_angle(R),
                               Rotation.from_matrix(R).magnitude(), atol=1e-9)


def _inverse_left_jacobian_textbook(phi: np.ndarray) -> np.ndarray:
    """``I - [phi]/2 + (1/t^2 - (1 + cos t) / (2 t sin t)) [phi]^2`` for one vector."""
    t = float(np.linalg.norm(phi))
    K = skew(phi)
    if t < 1e-6:
        coef = 1.0 / 12.0
    elif t > np.pi - 1e-6:
        return np.eye(3)
    else:
        coef = 1.0 / t**2 - (1.0 + np.cos(t)) / (2.0 * t * np.sin(t))
    return np.eye(3) - 0.5 * K + coef * (K @ K)


@settings(max_examples=100, deadline=None)
@given(axis=unit_vectors, angle=st.one_of(st.floats(0, np.pi), st.floats(0, 1e-7)))
def test_batched_inverse_left_jacobian_matches_single(axis, angle):
    phi = _rotvec(axis, angle)
    np.testing.assert_allclose(inverse_left_jacobian(phi[None])[0],
                               _inverse_left_jacobian_textbook(phi), atol=1e-12)
    np.testing.assert_array_equal(inverse_left_jacobian(phi), inverse_left_jacobian(phi[None])[0])


@settings(max_examples=200, deadline=None)
@given(axis=unit_vectors, angle=angles_below_pi)
def test_inverse_left_jacobian_inverts_the_left_jacobian(axis, angle):
    phi = _rotvec(axis, angle)
    np.testing.assert_allclose(inverse_left_jacobian(phi) @ left_jacobian(phi), np.eye(3),
                               atol=1e-10)
    np.testing.assert_allclose(left_jacobian(phi) @ inverse_left_jacobian(phi), np.eye(3),
                               atol=1e-10)


@settings(max_examples=50, deadline=None)
@given(axis=unit_vectors, angle=st.one_of(st.floats(1e-3, np.pi - 1e-2), st.floats(0, 1e-7)))
def test_jacobians_are_the_derivatives_of_exp_and_log(axis, angle):
    """``exp(phi + h e) exp(phi)^T ~ exp(h J_l e)``; ``log(exp(h w) R) ~ log R + h J_l^{-1} w``."""
    phi, h = _rotvec(axis, angle), 1e-6
    R = exp(phi)
    Jl_fd = np.stack([log(exp(phi + h * e) @ R.T) / h for e in np.eye(3)], axis=1)
    np.testing.assert_allclose(Jl_fd, left_jacobian(phi), atol=1e-6)
    Jinv_fd = np.stack([(log(exp(h * w) @ R) - log(exp(-h * w) @ R)) / (2 * h)
                        for w in np.eye(3)], axis=1)
    np.testing.assert_allclose(Jinv_fd, inverse_left_jacobian(phi), atol=1e-6)


def test_near_zero_and_near_pi_branches():
    tiny = np.array([[1e-9, -2e-9, 3e-10], [0.0, 0.0, 0.0]])
    np.testing.assert_allclose(inverse_left_jacobian(tiny), np.eye(3) - 0.5 * skew(tiny),
                               atol=1e-15)
    np.testing.assert_allclose(left_jacobian(tiny), np.eye(3) + 0.5 * skew(tiny), atol=1e-15)
    np.testing.assert_allclose(log(exp(tiny)), tiny, atol=1e-22)
    near_pi = np.array([[0.0, 0.0, np.pi - 1e-7], [np.pi, 0.0, 0.0]])
    np.testing.assert_array_equal(inverse_left_jacobian(near_pi), np.broadcast_to(np.eye(3),
                                                                                  (2, 3, 3)))
    logs = log(exp(near_pi))
    np.testing.assert_allclose(np.linalg.norm(logs, axis=1), [np.pi - 1e-7, np.pi], atol=1e-9)
    np.testing.assert_allclose(exp(logs), exp(near_pi), atol=1e-12)


@settings(max_examples=100, deadline=None)
@given(axis=unit_vectors, angle=angles, p=st.lists(st.floats(-10, 10), min_size=3, max_size=3))
def test_pose_residual_is_zero_at_the_target_and_the_log_elsewhere(axis, angle, p):
    p_t, R_t = np.asarray(p), exp(_rotvec(axis, angle))
    r = pose_residual(p_t[None], R_t[None], p_t, R_t, 2.0)
    assert r.shape == (1, 6)
    np.testing.assert_allclose(r, 0.0, atol=1e-15)
    np.testing.assert_array_equal(pose_residual(p_t[None], None, p_t, None, 2.0), np.zeros((1, 3)))
    dR = exp(np.array([0.1, -0.2, 0.3]))
    r = pose_residual((p_t + [1.0, 0.0, -2.0])[None], (dR @ R_t)[None], p_t, R_t, 2.0)[0]
    np.testing.assert_allclose(r[:3], [0.5, 0.0, -1.0], atol=1e-12)
    np.testing.assert_allclose(r[3:], [0.1, -0.2, 0.3], atol=1e-12)


def test_pose_residual_jacobian_rows():
    rng = np.random.default_rng(0)
    J = rng.normal(size=(4, 6, 7))
    r = np.hstack([rng.normal(size=(4, 3)), 0.5 * rng.normal(size=(4, 3))])
    out = pose_residual_jacobian(J, r, 2.0)
    assert out.shape == (4, 6, 7)
    np.testing.assert_array_equal(out[:, :3], J[:, :3] / 2.0)
    for i in range(4):
        np.testing.assert_allclose(out[i, 3:], inverse_left_jacobian(r[i, 3:]) @ J[i, 3:],
                                   atol=1e-14)
    np.testing.assert_array_equal(pose_residual_jacobian(J, r[:, :3], 2.0), J[:, :3] / 2.0)
