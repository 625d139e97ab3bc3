"""moik/kinematics/tolerance.py: one tolerance rule for every entry point."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik import get_robot, solve_ik, solve_ik_pareto
from moik.exceptions import ParameterError
from moik.kinematics.tolerance import MIN_TOL, POLISH_FRACTION, STOP_FRACTION, Tolerance


def test_a_number_scales_by_reach_and_a_pair_is_taken_as_is():
    assert Tolerance.of(1e-6, 2.0) == (2e-6, 1e-6)
    assert Tolerance.of((1e-3, 2e-3), 2.0) == (1e-3, 2e-3)
    assert Tolerance.of(np.float64(1e-9), 1.0) == (1e-9, 1e-9)


@pytest.mark.parametrize("bad", [0.0, -1.0, True, "1e-9", (1e-3, 0.0), float("nan"),
                                 float("inf"), 1e-15, (1e-3, 1e-15), (1e-20, 1e-3)])
def test_refused_values(bad):
    with pytest.raises(ParameterError, match="tol"):
        Tolerance.of(bad, 1.0)


def test_a_ragged_or_long_value_names_the_accepted_forms():
    for bad in ((1.0, 2.0, 3.0), [[1.0], [1.0, 2.0]]):
        with pytest.raises(ParameterError, match="a number or"):
            Tolerance.of(bad, 1.0)


def test_stop_rules_are_fractions():
    tol = Tolerance(2e-6, 1e-6)
    assert tol.stop == (STOP_FRACTION * 2e-6, STOP_FRACTION * 1e-6)
    assert tol.polish_stop == (POLISH_FRACTION * 2e-6, POLISH_FRACTION * 1e-6)
    assert tol.scaled(2.0) == 2e-6 / 2.0 + 1e-6


@settings(max_examples=200, derandomize=True, deadline=None)
@given(st.floats(0, 1e-3), st.floats(0, 1e-3), st.floats(1e-12, 1e-3), st.floats(1e-12, 1e-3))
def test_certifies_is_both_within(p, o, tp, to):
    tol = Tolerance(tp, to)
    assert tol.certifies(p, o) == (p <= tp and o <= to)
    ok = tol.certifies(np.array([p, 2 * tp]), np.array([o, o]))
    assert ok.tolist() == [p <= tp and o <= to, False]


def test_nan_errors_never_certify():
    assert not Tolerance(1.0, 1.0).certifies(float("nan"), 0.0)


def test_solve_ik_and_solve_ik_pareto_refuse_the_same_tolerances():
    robot = get_robot("ur5")
    pose = robot.fk(np.full(robot.dof, 0.3))
    for bad in (1e-15, MIN_TOL / 2, (1e-3, 1e-16)):
        with pytest.raises(ParameterError, match="tol"):
            solve_ik(robot, pose, tol=bad)
        with pytest.raises(ParameterError, match="tol"):
            solve_ik_pareto(robot, pose, objectives=("manipulability", "limit_margin"), tol=bad)
