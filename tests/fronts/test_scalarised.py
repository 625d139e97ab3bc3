"""The epsilon-constraint subproblems (moik.fronts.scalarised): the compiled errors, their
squares, gradients and pose equations, the KKT residual, and SLSQP's solutions, on the
closed forms of planar2 (tests/fronts/test_front.py derives the whole front).

planar2: ``T(q) = Rz(q1) Tx(l1) Rz(q2) Tx(l2)``, ``l1 = 0.35``, ``l2 = 0.30``: heading
``theta = q1 + q2``, tool ``p = l1 u(q1) + l2 u(theta)``, ``u(a) = (cos a, sin a, 0)``;
``dp/dq1 = (-p_y, p_x, 0)``, ``dp/dq2 = l2 (-sin theta, cos theta, 0)``. Against
``Rz(phi)`` the geodesic error is ``|a|``, ``a = theta - phi`` (wrapped), and the skew part
of ``R_t^T R = Rz(a)`` is ``(0, 0, sin a)``. For the target ``p_t = D u(psi)`` out of reach
(``D = 0.9``, ``psi = 0.8``, ``phi = -0.4``, ``delta = psi - phi = 1.2``): at heading
offset ``c`` from ``psi`` the least position error is
``g(c) = sqrt(D^2 + l2^2 - 2 D l2 cos c) - l1``, so
``min f1 s.t. f2 = 0`` is ``g(delta)`` and ``min f2 s.t. f1 <= eps`` is ``delta - g^-1(eps)``.
"""

import math

import numpy as np
import pytest

from moik.fronts.scalarised import ErrorModel, kkt_residual, solve_constrained, solve_sum
from moik.robots import get_robot

ARM = get_robot("planar2")
L1, L2, REACH = 0.35, 0.30, 0.65
D, PSI, PHI = 0.9, 0.8, -0.4
DELTA = PSI - PHI


def _rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _tool(q):
    t = q[0] + q[1]
    return np.array([L1 * math.cos(q[0]) + L2 * math.cos(t),
                     L1 * math.sin(q[0]) + L2 * math.sin(t), 0.0])


def _jp(q):
    """``dp/dq`` (3, 2) by hand (module doc)."""
    p, t = _tool(q), q[0] + q[1]
    return np.array([[-p[1], -L2 * math.sin(t)], [p[0], L2 * math.cos(t)], [0.0, 0.0]])


def g(c):
    return math.sqrt(D * D + L2 * L2 - 2 * D * L2 * math.cos(c)) - L1


def g_inv(f):
    return math.acos((D * D + L2 * L2 - (f + L1) ** 2) / (2 * D * L2))


P_FAR = D * np.array([math.cos(PSI), math.sin(PSI), 0.0])
P_NEAR = np.array([0.3, 0.25, 0.0])
Q = np.array([[0.3, -0.7], [1.2, 0.4], [-2.0, 2.5]])


def _model(position=P_FAR, metric="geodesic", phi=PHI):
    return ErrorModel(ARM, position, _rz(phi), metric)


@pytest.mark.parametrize("metric, h", [
    ("geodesic", abs), ("zyx-euler", lambda a: abs(a) / 3),
    ("frobenius", lambda a: 2 * math.sqrt(2) * math.sin(abs(a) / 2))])
def test_errors_by_hand(metric, h):
    model = _model(metric=metric)
    E = model.errors(Q)
    for q, (f1, f2) in zip(Q, E, strict=True):
        a = (q[0] + q[1] - PHI + math.pi) % (2 * math.pi) - math.pi
        assert f1 == pytest.approx(np.linalg.norm(_tool(q) - P_FAR), abs=1e-15)
        assert f2 == pytest.approx(h(a), abs=1e-12)
    np.testing.assert_array_equal(model.errors(Q[0]), E[:1])


def test_squares_and_gradients_by_hand():
    """Scaled by (reach^2, 1): ``s1 = |p - p_t|^2 / reach^2`` with gradient
    ``2 (p - p_t) . dp/dq / reach^2``; ``s2 = a^2`` with gradient ``2 a (1, 1)``."""
    model = _model()
    for q in Q:
        value, grad = model.squared(q.copy())
        e = _tool(q) - P_FAR
        a = (q[0] + q[1] - PHI + math.pi) % (2 * math.pi) - math.pi
        np.testing.assert_allclose(value, [e @ e / REACH**2, a * a], rtol=1e-12, atol=1e-30)
        np.testing.assert_allclose(grad[0], 2 * e @ _jp(q) / REACH**2, atol=1e-8)
        np.testing.assert_allclose(grad[1], [2 * a, 2 * a], atol=1e-8)
    again = model.squared(Q[0].copy())  # the cached one for the same q
    np.testing.assert_array_equal(again[0], model.squared(Q[0].copy())[0])


def test_pose_equations_by_hand():
    model = _model()
    for q in Q:
        value, jac = model.residual(q.copy(), 0)
        np.testing.assert_allclose(value, (_tool(q) - P_FAR) / REACH, atol=1e-15)
        np.testing.assert_allclose(jac, _jp(q) / REACH, atol=1e-8)
        value, jac = model.residual(q.copy(), 1)
        a = q[0] + q[1] - PHI
        np.testing.assert_allclose(value, [0.0, 0.0, math.sin(a)], atol=1e-15)
        np.testing.assert_allclose(jac[2], [math.cos(a)] * 2, atol=1e-8)
    value, jac = _model(metric="zyx-euler-free-gamma").residual(Q[0].copy(), 1)
    assert value.shape == (2,) and jac.shape == (2, 2)  # the free angle has no equation


def test_kkt_residual_is_zero_only_at_a_kkt_point():
    """Unconstrained position error of a reachable target: zero at a solution, the largest
    gradient component elsewhere."""
    model = _model(P_NEAR)
    c2 = (P_NEAR @ P_NEAR - L1**2 - L2**2) / (2 * L1 * L2)
    q2 = math.acos(c2)
    solution = np.array([math.atan2(0.25, 0.3) - math.atan2(L2 * math.sin(q2),
                                                             L1 + L2 * math.cos(q2)), q2])
    assert kkt_residual(model, solution, 0, math.inf) < 1e-10
    q = Q[1]
    assert kkt_residual(model, q, 0, math.inf) == pytest.approx(
        np.abs(model.squared(q)[1][0]).max(), rel=1e-12)
    assert kkt_residual(model, q, 0, math.inf) > 0.1


def test_kkt_residual_on_the_pose_manifold():
    """``min f1 s.t. f2 = 0``: on the heading ``phi`` the tool is ``l1 u(q1) + l2 u(phi)``,
    nearest ``p_t`` at ``q1 = angle(p_t - l2 u(phi))``: a KKT point; a little along the
    manifold it is not."""
    model = _model()
    w = P_FAR - L2 * np.array([math.cos(PHI), math.sin(PHI), 0.0])
    q1 = math.atan2(w[1], w[0])
    best = np.array([q1, PHI - q1])
    assert kkt_residual(model, best, 0, 0.0) < 1e-7
    off = np.array([q1 + 0.1, PHI - q1 - 0.1])
    assert kkt_residual(model, off, 0, 0.0) > 1e-3


def test_a_bound_multiplier_absorbs_the_gradient_at_a_limit():
    """The near target (at angle 0.69, 0.39 away) has its solutions at q1 = -0.13 and 1.52.
    With q1 held to [1.8, pi] the elbow's distance to it, ``sqrt(r^2 + l1^2 - 2 r l1
    cos(q1 - 0.69))``, grows with q1 and exceeds l2: the least position error is on the
    bound q1 = 1.8, where the gradient pushes out of the box; the residual is 0."""
    model = _model(P_NEAR)
    model.lower = np.array([1.8, -math.pi])
    out = solve_constrained(model, np.array([2.5, -1.0]), 0, math.inf)
    assert out.q[0] == pytest.approx(1.8, abs=1e-10)
    assert abs(model.squared(out.q)[1][0][0]) > 1e-3  # the raw gradient is not zero
    assert out.kkt < 1e-7


def test_the_orientation_anchor_of_an_out_of_reach_pose():
    """``min f1 s.t. f2 = 0``: ``g(delta)``, at the target's heading."""
    out = solve_constrained(_model(), np.array([0.5, -0.5]), 0, 0.0)
    assert out.errors[1] < 1e-9 and out.success
    assert out.errors[0] == pytest.approx(g(DELTA), abs=1e-9)
    assert out.kkt < 1e-6


@pytest.mark.parametrize("eps", [0.3, 0.35, 0.45])
def test_least_orientation_error_within_a_position_level(eps):
    """``min f2 s.t. f1 <= eps``: ``delta - g^-1(eps)`` (module doc), the level active."""
    out = solve_constrained(_model(), np.array([PSI, 0.0]), 1, eps)
    assert out.errors[0] <= eps * (1 + 1e-8)
    assert out.errors[1] == pytest.approx(DELTA - g_inv(eps), abs=1e-7)
    assert out.kkt < 1e-5


def test_the_least_position_error_of_an_out_of_reach_target():
    out = solve_constrained(_model(), np.array([0.0, 0.0]), 0, math.inf)
    assert out.errors[0] == pytest.approx(D - REACH, abs=1e-9)


def test_the_weighted_sum_reaches_a_reachable_pose():
    q_true = np.array([0.4, -1.1])
    model = _model(_tool(q_true), phi=q_true.sum())
    out = solve_sum(model, np.array([0.9, -0.5]))
    assert out.errors.max() < 1e-7 and out.kkt < 1e-7
    np.testing.assert_allclose(out.q, q_true, atol=1e-6)
