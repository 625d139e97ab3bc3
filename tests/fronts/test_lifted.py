"""The lifted epsilon-constraint subproblems of the ZYX Euler metrics, against planar2's
closed forms (tests/fronts/test_scalarised.py's module doc; test_front.py derives them).

With MO-m-PSO's ZYX metric planar2's orientation error is ``|a| / 3``, ``a = theta - phi``
(angles ``(theta, 0, 0)``; no wrap while ``theta`` stays in ``(-pi, pi)``). For the target
``D u(psi)``, ``Rz(phi)`` out of reach: ``min f2 s.t. f1 <= eps`` is
``(delta - g^-1(eps)) / 3`` and ``min f1 s.t. f2 <= eps`` is ``g(delta - 3 eps)``
(``3 eps <= delta``).
"""

import math

import numpy as np
import pytest

from moik.fronts.lifted import is_kinked, solve_lifted
from moik.fronts.scalarised import ErrorModel, solve_constrained
from moik.robots import get_robot

ARM = get_robot("planar2")
L1, L2 = 0.35, 0.30
D, PSI, PHI = 0.9, 0.8, -0.4
DELTA = PSI - PHI
P_FAR = D * np.array([math.cos(PSI), math.sin(PSI), 0.0])


def _rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def g(c):
    return math.sqrt(D * D + L2 * L2 - 2 * D * L2 * math.cos(c)) - L1


def g_inv(f):
    return math.acos((D * D + L2 * L2 - (f + L1) ** 2) / (2 * D * L2))


def _model(metric="zyx-euler", position=P_FAR):
    return ErrorModel(ARM, position, _rz(PHI), metric)


@pytest.mark.parametrize("metric, kinked", [
    ("zyx-euler", True), ("zyx-euler-free-gamma", True), ("geodesic", False),
    ("frobenius", False), ("eosma-euler", False)])
def test_only_the_zyx_metrics_are_kinked(metric, kinked):
    assert is_kinked(_model(metric)) is kinked


@pytest.mark.parametrize("eps", [0.0, math.inf])
def test_no_absolute_value_falls_back_to_the_smooth_form(eps):
    """Least position error with no orientation level, or with ``f2 = 0`` (three smooth
    equations): the same answer as solve_constrained, with its KKT residual."""
    model = _model()
    q0 = np.array([0.5, -0.5])
    lifted, smooth = solve_lifted(model, q0, 0, eps), solve_constrained(model, q0, 0, eps)
    np.testing.assert_array_equal(lifted.q, smooth.q)
    assert lifted.kkt == smooth.kkt and not math.isnan(lifted.kkt)


@pytest.mark.parametrize("eps", [0.3, 0.35, 0.45])
def test_least_orientation_error_within_a_position_level(eps):
    out = solve_lifted(_model(), np.array([PSI, 0.0]), 1, eps)
    assert out.errors[0] <= eps * (1 + 1e-8)
    assert out.errors[1] == pytest.approx((DELTA - g_inv(eps)) / 3, abs=1e-7)
    assert math.isnan(out.kkt)  # not defined for the kinked form
    np.testing.assert_array_equal(out.errors, _model().errors(out.q)[0])


@pytest.mark.parametrize("eps", [0.05, 0.1, 0.3])
def test_least_position_error_within_an_orientation_level(eps):
    out = solve_lifted(_model(), np.array([0.5, -0.9]), 0, eps)
    assert out.errors[1] <= eps + 1e-9
    assert out.errors[0] == pytest.approx(g(DELTA - 3 * eps), abs=1e-7)
    assert math.isnan(out.kkt)


def test_least_orientation_error_on_the_exact_position():
    """A reachable position (0.3, 0.25) of a planar arm (its z equation vanishes identically:
    left out, as solve_constrained does): exact on either branch, whose headings are
    ``q1 + q2`` (law of cosines); the lifted problem finds the branch nearer ``phi``
    from a start near it."""
    p = np.array([0.3, 0.25, 0.0])
    c2 = (p @ p - L1**2 - L2**2) / (2 * L1 * L2)
    headings = []
    for q2 in (math.acos(c2), -math.acos(c2)):
        headings.append(math.atan2(0.25, 0.3) - math.atan2(L2 * math.sin(q2),
                                                            L1 + L2 * math.cos(q2)) + q2)
    out = solve_lifted(_model(position=p), np.array([1.4, -1.7]), 1, 0.0)  # near (1.52, -1.86)
    assert out.errors[0] < 1e-9
    assert out.errors[1] == pytest.approx(min(abs(h - PHI) for h in headings) / 3, abs=1e-7)


def test_least_orientation_error_on_the_exact_position_of_a_spatial_arm():
    """puma560 (no identically-zero position equation): from an exact start the lifted
    problem keeps the position exact and does not end with a larger orientation error."""
    from moik.problems import random_reachable_targets

    robot = get_robot("puma560")
    source = random_reachable_targets(robot, 1, seed=3)[0]
    model = ErrorModel(robot, source.position, _rz(0.3) @ source.rotation, "zyx-euler")
    start = model.errors(source.q_source)[0]
    out = solve_lifted(model, source.q_source, 1, 0.0)
    assert out.success and out.errors[0] < 1e-9
    assert out.errors[1] <= start[1] + 1e-9 and start[1] > 0.01
