"""Orientation conventions and metrics: paper values and properties."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from moik.exceptions import NonFiniteError, ShapeError, TargetError, UnknownNameError
from moik.kinematics.orientation import (
    available_metrics,
    eosma_euler,
    orientation_error,
    rotation_from_eosma_euler,
    rotation_from_zyx,
    zyx_euler,
)
from moik.robots import get_robot

DEG = np.pi / 180
seeds = st.integers(0, 2**32 - 1)


def test_eosma_euler_of_paper_pose():
    """EOSMA paper, Simulation section: P1 orientation (90, -45, 0) deg by Eq. 26."""
    T = get_robot("eosma7").fk(np.array([45, 0, 45, 0, 45, 0, 0]) * DEG)
    np.testing.assert_allclose(eosma_euler(T[:3, :3]) / DEG, [90, -45, 0], atol=1e-9)


def test_zyx_euler_of_mo_m_pso_eq16():
    """MO-m-PSO Eq. 16 matrix -> (alpha, beta, gamma) = (0, -30, -23.84) deg (Section 4.2)."""
    R = np.array([[0.8660, 0.2021, -0.4574], [0.0, 0.9147, 0.4042], [0.5, -0.35, 0.7921]])
    R = Rotation.from_matrix(R).as_matrix()  # re-orthonormalise the 4-digit print
    np.testing.assert_allclose(zyx_euler(R) / DEG, [0, -30, -23.84], atol=0.02)


def test_euler_round_trips():
    ang = np.array([0.3, -0.2, 0.5])
    np.testing.assert_allclose(eosma_euler(rotation_from_eosma_euler(*ang)), ang, atol=1e-15)
    np.testing.assert_allclose(zyx_euler(rotation_from_zyx(*ang)), ang, atol=1e-15)


def test_eq26_ambiguity_documented():
    """reference-facts.md: with atan, diag(1, -1, -1) has the same angles as I."""
    np.testing.assert_allclose(eosma_euler(np.diag([1.0, -1.0, -1.0])), 0.0, atol=0)
    assert orientation_error(np.diag([1.0, -1.0, -1.0]), np.eye(3), "geodesic") == pytest.approx(
        np.pi)


def test_geodesic_known_angles():
    for angle in (0.0, 1e-9, 0.5, np.pi - 1e-9, np.pi):
        R = Rotation.from_rotvec([0, angle, 0]).as_matrix()
        assert orientation_error(R, np.eye(3), "geodesic") == pytest.approx(angle, abs=1e-15)


def test_frobenius_value():
    R = Rotation.from_rotvec([0, 0, np.pi / 2]).as_matrix()
    # ||R - I||_F = 2 sqrt(2) sin(theta/2) * sqrt(2)... = sqrt(8) sin(theta/2)
    assert orientation_error(R, np.eye(3), "frobenius") == pytest.approx(np.sqrt(8) * np.sin(
        np.pi / 4))


@settings(max_examples=50, deadline=None)
@given(st.sampled_from(available_metrics()), seeds)
def test_metric_nonnegative_and_zero_iff_equal(metric, seed):
    R = Rotation.random(2, random_state=seed).as_matrix()
    assert orientation_error(R[0], R[0], metric) == pytest.approx(0.0, abs=1e-12)
    assert orientation_error(R[0], R[1], metric) >= 0.0
    if metric in ("geodesic", "frobenius"):  # true metrics: 0 only for equal rotations
        assert orientation_error(R[0], R[1], metric) > 1e-9


@settings(max_examples=50, deadline=None)
@given(st.sampled_from(["geodesic", "frobenius"]), seeds)
def test_metric_symmetric(metric, seed):
    R = Rotation.random(2, random_state=seed).as_matrix()
    assert orientation_error(R[0], R[1], metric) == pytest.approx(
        orientation_error(R[1], R[0], metric), abs=1e-12)


@settings(max_examples=50, deadline=None)
@given(seeds)
def test_geodesic_invariant_under_common_rotation(seed):
    R = Rotation.random(3, random_state=seed).as_matrix()
    a = orientation_error(R[0], R[1], "geodesic")
    assert orientation_error(R[2] @ R[0], R[2] @ R[1], "geodesic") == pytest.approx(a, abs=1e-12)
    assert orientation_error(R[0] @ R[2], R[1] @ R[2], "geodesic") == pytest.approx(a, abs=1e-12)


@settings(max_examples=30, deadline=None)
@given(seeds)
def test_geodesic_matches_scipy(seed):
    R = Rotation.random(2, random_state=seed)
    expected = (R[1].inv() * R[0]).magnitude()
    assert orientation_error(R[0].as_matrix(), R[1].as_matrix()) == pytest.approx(expected,
                                                                                  abs=1e-12)


def test_batch_shape():
    R = Rotation.random(5, random_state=0).as_matrix()
    for metric in available_metrics():
        assert orientation_error(R, np.eye(3), metric).shape == (5,)


def test_bad_input():
    with pytest.raises(UnknownNameError, match="unknown orientation metric 'quat'; expected one"):
        orientation_error(np.eye(3), np.eye(3), "quat")
    with pytest.raises(ShapeError, match=r"R_t must have shape \(3, 3\)"):
        orientation_error(np.eye(3), np.eye(4))
    with pytest.raises(NonFiniteError, match="must be finite"):
        orientation_error(np.full((3, 3), np.nan), np.eye(3))
    with pytest.raises(TargetError, match="must be a rotation matrix"):
        orientation_error(np.eye(3), 2 * np.eye(3))
