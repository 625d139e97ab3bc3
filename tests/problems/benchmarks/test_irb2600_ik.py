"""F24, the MChOA paper's IRB-2600 pose IK objective (Eq. 6).

Independent computation: the pose is rebuilt here from the paper's Eq. 1
(modified DH link matrix) and Table 1, with plain numpy, not moik's FK kernel.
"""

from __future__ import annotations

import numpy as np
import pytest

from moik.exceptions import ParameterError
from moik.problems.benchmarks import available_benchmarks, get_benchmark

# MChOA Table 1: theta offset (deg), d (mm), a_{i-1} (mm), alpha_{i-1} (deg).
_TABLE1 = [(0, 445, 0, 0), (90, 0, 150, -90), (0, 0, -700, 0),
           (0, 795, -115, 90), (0, 0, 0, -90), (0, 85, 0, 90)]


def eq1_pose(q):
    """T_60 = T_1 ... T_6 with the paper's Eq. 1 link matrix."""
    T = np.eye(4)
    for qi, (off, d, a, alpha) in zip(q, _TABLE1, strict=True):
        t, al = qi + np.deg2rad(off), np.deg2rad(alpha)
        ct, st, ca, sa = np.cos(t), np.sin(t), np.cos(al), np.sin(al)
        T = T @ np.array([[ct, -st, 0, a],
                          [st * ca, ct * ca, -sa, -sa * d],
                          [st * sa, ct * sa, ca, ca * d],
                          [0, 0, 0, 1]])
    return T


def f24(q, q_target, alpha=1.0, beta=1000.0):
    T, Tt = eq1_pose(q), eq1_pose(q_target)
    position = np.linalg.norm(T[:3, 3] - Tt[:3, 3])
    return alpha * position + beta * np.linalg.norm(T[:3, :3] - Tt[:3, :3])


def test_registered_with_known_optimum_at_the_preset_joints():
    assert "F24" in available_benchmarks()
    problem = get_benchmark("F24")
    assert problem.n_var == 6 and problem.f_opt == 0.0
    np.testing.assert_allclose(np.rad2deg(problem.x_opt), [30, 20, -40, 45, 60, 30])
    assert problem.evaluate(problem.x_opt[None])[0, 0] < 1e-9
    np.testing.assert_allclose(np.rad2deg(problem.xl), [-180, -95, -180, -400, -120, -400])
    np.testing.assert_allclose(np.rad2deg(problem.xu), [180, 150, 75, 400, 120, 400])


@pytest.mark.parametrize(("alpha", "beta"), [(1.0, 1000.0), (2.0, 0.0), (0.0, 5.0)])
def test_value_matches_eq6_with_eq1_kinematics(alpha, beta):
    problem = get_benchmark("F24", alpha=alpha, beta=beta)
    X = np.random.default_rng(3).uniform(problem.xl, problem.xu, (20, 6))
    expected = [f24(x, problem.x_opt, alpha, beta) for x in X]
    np.testing.assert_allclose(problem.evaluate(X)[:, 0], expected, rtol=1e-10, atol=1e-9)


def test_other_preset_target():
    q_deg = [-60.0, 100.0, 10.0, -300.0, -90.0, 200.0]
    problem = get_benchmark("F24", q_target_deg=q_deg)
    x = np.deg2rad([0.0, 0.0, 0.0, 0.0, 30.0, 0.0])
    assert problem.evaluate(x[None])[0, 0] == pytest.approx(f24(x, np.deg2rad(q_deg)), rel=1e-10)


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"alpha": -1.0}, "alpha and beta"),
    ({"alpha": 0.0, "beta": 0.0}, "alpha and beta"),
    ({"beta": float("nan")}, "alpha and beta"),
    ({"q_target_deg": [0.0] * 5}, "6 finite joint values"),
    ({"q_target_deg": [0, 0, 0, 0, 0, float("nan")]}, "6 finite joint values"),
    ({"q_target_deg": [0, 0, 100, 0, 0, 0]}, "outside the IRB-2600 joint range"),
])
def test_bad_arguments(kwargs, match):
    with pytest.raises(ParameterError, match=match):
        get_benchmark("F24", **kwargs)
