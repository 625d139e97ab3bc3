"""Quintic rest-to-rest trajectory: boundary conditions, derivatives, bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.exceptions import NonFiniteError, ParameterError, ShapeError
from moik.kinematics.trajectory import quintic_trajectory

angles = st.lists(st.floats(-3.0, 3.0), min_size=1, max_size=7)


def test_boundary_conditions():
    q0 = np.array([0.1, -0.5, 1.0])
    q1 = np.array([1.2, 0.3, -2.0])
    t, q, qd, qdd = quintic_trajectory(q0, q1, 2.5, 51)
    assert t.shape == (51,) and q.shape == qd.shape == qdd.shape == (51, 3)
    assert t[0] == 0.0 and t[-1] == 2.5
    np.testing.assert_allclose(q[0], q0, atol=1e-15)
    np.testing.assert_allclose(q[-1], q1, atol=1e-15)
    np.testing.assert_allclose(qd[[0, -1]], 0.0, atol=1e-15)
    np.testing.assert_allclose(qdd[[0, -1]], 0.0, atol=1e-15)
    # Symmetric profile: midpoint halfway, peak velocity 15/8 * dq / T there.
    np.testing.assert_allclose(q[25], (q0 + q1) / 2)
    np.testing.assert_allclose(qd[25], 15 / 8 * (q1 - q0) / 2.5)
    np.testing.assert_allclose(qdd[25], 0.0, atol=1e-12)


@settings(max_examples=25, deadline=None)
@given(angles, st.floats(0.2, 10.0))
def test_derivatives_match_finite_differences(a, duration):
    rng = np.random.default_rng(len(a))
    q0 = np.array(a)
    q1 = q0 + rng.uniform(-2, 2, size=q0.shape)
    t, q, qd, qdd = quintic_trajectory(q0, q1, duration, 2001)
    dt = t[1] - t[0]
    scale = np.abs(q1 - q0).max() + 1e-12
    fd_v = np.gradient(q, dt, axis=0, edge_order=2)
    fd_a = np.gradient(qd, dt, axis=0, edge_order=2)
    assert np.abs(fd_v - qd).max() <= 1e-4 * scale / duration
    assert np.abs(fd_a - qdd).max() <= 1e-4 * scale / duration**2
    # Monotone between the ends (no overshoot): each joint stays within [q0, q1].
    lo, hi = np.minimum(q0, q1), np.maximum(q0, q1)
    assert np.all(q >= lo - 1e-12) and np.all(q <= hi + 1e-12)


def test_zero_motion_is_constant():
    q0 = np.array([0.3, 0.4])
    _, q, qd, qdd = quintic_trajectory(q0, q0, 1.0, 5)
    np.testing.assert_array_equal(q, np.tile(q0, (5, 1)))
    assert not qd.any() and not qdd.any()


@pytest.mark.parametrize(
    ("q0", "q1", "duration", "n", "error", "match"),
    [
        ([0, 1], [0, 1, 2], 1.0, 5, ShapeError, "same length"),
        ([[0, 1]], [[0, 1]], 1.0, 5, ShapeError, "1-D"),
        ([0, np.nan], [0, 1], 1.0, 5, NonFiniteError, "finite"),
        ([0, 1], [0, 1], 0.0, 5, ParameterError, "duration"),
        ([0, 1], [0, 1], 1.0, 1, ParameterError, "n must be an integer >= 2"),
        ([0, 1], [0, 1], 1.0, 2.5, ParameterError, "n must be"),
    ],
)
def test_bad_input(q0, q1, duration, n, error, match):
    with pytest.raises(error, match=match):
        quintic_trajectory(q0, q1, duration, n)
