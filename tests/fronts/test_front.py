"""The reference front against the closed form of a 2-DOF planar arm.

Derivation. The arm ``planar2`` (I-BES Table 2; standard DH rows ``a = (l1, l2)``,
``alpha = d = 0``) has ``T(q) = Rz(q1) Tx(l1) Rz(q2) Tx(l2)``: the tool heading is
``theta = q1 + q2``, its rotation ``Rz(theta)``, its position
``p = l1 u(q1) + l2 u(theta)`` with ``u(a) = (cos a, sin a, 0)``. The joint limits
``[-pi, pi]`` reach every ``(q1, theta)`` modulo ``2 pi``. Take the target position
``p_t = D u(psi)`` with ``D > l1 + l2`` (out of reach) and the rotation ``Rz(phi)``, and
write ``delta = psi - phi`` (here in ``(0, pi/2)``).

Position error at fixed heading: ``p - l2 u(theta)`` runs over the circle of radius
``l1`` about the origin, so the least distance to ``p_t`` over ``q1`` is
``| |p_t - l2 u(theta)| - l1 |``; as ``|p_t - l2 u(theta)| >= D - l2 > l1`` this is
``g(c) = sqrt(D^2 + l2^2 - 2 D l2 cos c) - l1`` with ``c = theta - psi``, increasing in
``|c|`` on ``[0, pi]``.

Orientation error of ``Rz(theta)`` against ``Rz(phi)``, ``a = theta - phi``:
geodesic ``|a|`` (wrapped into ``[0, pi]``); Frobenius ``sqrt(4 (1 - cos a))
= 2 sqrt(2) sin(|a| / 2)``; ZYX Euler (MO-m-PSO Eq. 14) ``|a| / 3`` (angles
``(theta, 0, 0)``, no wrap while ``theta`` stays in ``(-pi, pi)``); EOSMA Eq. 26/30
``|atan(tan theta) - phi|``, which is ``|a|`` for ``theta`` in ``(-pi/2, pi/2)``. Each is
``h(|a|)`` with ``h`` increasing (on the heading range that matters below).

Front. For an orientation error ``h(s)`` the headings are ``phi +- s``; the one towards
``psi`` has ``|theta - psi| = delta - s``, the other ``delta + s`` (or ``2 pi - delta - s``,
never smaller while ``delta <= pi``), so the least position error at that orientation
error is ``g(delta - s)``, decreasing in ``s`` up to ``s = delta``; beyond it both errors
grow. The EOSMA metric's second branch (``theta`` in ``(pi/2, 3 pi/2)``, where
``atan(tan theta) = theta - pi``) has ``|theta - psi| > pi/2 - psi`` and is dominated
for the values here (checked by the test: no point of the computed front may lie off
the first branch). Hence the Pareto front is exactly::

    { (g(delta - s), h(s)) : 0 <= s <= delta },

from ``(g(delta), 0)`` (the target's orientation) to ``(D - l1 - l2, h(delta))`` (the
least position error, pointing at the target).
"""

import numpy as np
import pytest

from moik.exceptions import ParameterError
from moik.fronts import ReferenceFront, bi_objective_front
from moik.robots.catalog import get_robot

L1, L2 = 0.35, 0.30
D, PSI, PHI = 0.9, 0.8, -0.4
DELTA = PSI - PHI

H = {  # orientation error h(s) of a heading offset s, and its inverse
    "geodesic": (lambda s: s, lambda f: f),
    "eosma-euler": (lambda s: s, lambda f: f),
    "zyx-euler": (lambda s: s / 3, lambda f: 3 * f),
    "frobenius": (lambda s: 2 * np.sqrt(2) * np.sin(s / 2),
                  lambda f: 2 * np.arcsin(f / (2 * np.sqrt(2)))),
}


def g(c):
    return np.sqrt(D * D + L2 * L2 - 2 * D * L2 * np.cos(c)) - L1


def _target(psi=PSI, phi=PHI, dist=D):
    c, s = np.cos(phi), np.sin(phi)
    return (np.array([dist * np.cos(psi), dist * np.sin(psi), 0.0]),
            np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]))


@pytest.fixture(scope="module")
def fronts():
    p, R = _target()
    return {m: bi_objective_front(get_robot("planar2"), p, R, metric=m, levels=30,
                                  starts=8, rng=np.random.default_rng(3)) for m in H}


@pytest.mark.parametrize("metric", list(H))
def test_planar_front_is_the_closed_form(fronts, metric):
    front: ReferenceFront = fronts[metric]
    h, h_inv = H[metric]
    F = front.F
    assert not front.reachable and F.shape[1] == 2 and len(F) >= 30
    s = h_inv(F[:, 1])
    assert np.all(s <= DELTA + 1e-9)  # no point beyond the least-position-error end
    np.testing.assert_allclose(F[:, 0], g(DELTA - s), rtol=0, atol=1e-9)
    # both ends reached: the target's orientation, and the least position error
    assert F[:, 1].min() <= 1e-9 and abs(F[np.argmin(F[:, 1]), 0] - g(DELTA)) <= 1e-9
    assert abs(F[:, 0].min() - (D - L1 - L2)) <= 1e-9
    # the front is covered: no gap wider than a twentieth of its extent in either error
    span = F.max(axis=0) - F.min(axis=0)
    assert np.all(np.abs(np.diff(F, axis=0)) <= span / 20)
    # KKT points: the projected residual is small, except at the end levels, where the
    # level sits within tol of the constrained error's own minimum: there the constraint's
    # gradient vanishes (~1e-4), its multiplier is ~1e4 and the residual is SLSQP's rounding
    # times that (measured 1.8e-4 at the position end on an AVX-512 machine, 1e-9 elsewhere);
    # those two points are checked against the closed form above instead
    assert np.nanmax(front.kkt[1:-1]) < 1e-4
    assert front.starts == 8 and front.metric == metric
    assert "local" in front.guarantee


def test_planar_front_is_sorted_and_non_dominated(fronts):
    F = fronts["geodesic"].F
    assert np.all(np.diff(F[:, 0]) > 0) and np.all(np.diff(F[:, 1]) < 0)


def test_reachable_pose_gives_the_ideal_point():
    robot = get_robot("planar2")
    T = robot.fk(np.array([0.3, -1.1]))
    front = bi_objective_front(robot, T[:3, 3], T[:3, :3], metric="geodesic", starts=4,
                               rng=np.random.default_rng(0))
    assert front.reachable
    np.testing.assert_array_equal(front.F, [[0.0, 0.0]])
    assert "reachable" in front.guarantee


@pytest.mark.parametrize("bad", [{"levels": 1}, {"starts": 0}, {"tol": -1.0},
                                 {"rng": 7}])
def test_bad_settings_raise(bad):
    p, R = _target()
    kwargs = {"rng": np.random.default_rng(0), **bad}
    with pytest.raises(ParameterError):
        bi_objective_front(get_robot("planar2"), p, R, **kwargs)
