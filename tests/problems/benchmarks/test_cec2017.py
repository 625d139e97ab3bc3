"""CEC2017 functions of the I-BES paper (Section 5.2) through minionpy.

Reference: Awad et al. (2016), CEC2017 problem definitions, and the official
``cec17_func.cpp``: F_i(o_i) = 100 i at the shift vector o_i, except F9, whose
Levy component has its minimum at z = 1 (x = o_9 + M_9^{-1} 1). The official
formulas are checked in ``test_cec2017_oracle.py``.
"""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

from moik.exceptions import NonFiniteError, ParameterError, ShapeError, UnknownNameError
from moik.problems.benchmarks import available_benchmarks, get_benchmark
from moik.problems.benchmarks.cec2017 import (
    AVAILABLE_FUNCTIONS,
    CEC2017,
    IBES_FUNCTIONS,
    official_data_dir,
    shift_vector,
)

pytest.importorskip("minionpy")


def test_registry_has_the_ibes_nine():
    assert [n for n in available_benchmarks() if n.startswith("cec2017_")] == [
        f"cec2017_F{i}" for i in (3, 8, 9, 14, 15, 18, 19, 27, 30)
    ]


@pytest.mark.parametrize("number", IBES_FUNCTIONS)
def test_registered_problem_is_d30_on_the_official_box(number):
    problem = get_benchmark(f"cec2017_F{number}")
    assert problem.n_var == 30
    np.testing.assert_allclose(problem.xl, -100.0)
    np.testing.assert_allclose(problem.xu, 100.0)
    assert problem.pareto_front()[0, 0] == 100.0 * number
    assert problem.name() == f"CEC2017-F{number}"


@pytest.mark.parametrize("n_var", [10, 30, 50])
@pytest.mark.parametrize("number", [i for i in AVAILABLE_FUNCTIONS if i != 9])
def test_value_at_shift_is_100_i(number, n_var):
    # o_i read straight from the official data file minionpy ships (o_1 for F21-F30)
    with (official_data_dir() / f"shift_data_{number}.txt").open() as fh:
        o = np.array(fh.readline().split()[:n_var], dtype=float)
    problem = CEC2017(number, n_var=n_var)
    np.testing.assert_array_equal(problem.x_opt, o)
    assert problem.evaluate(o[None])[0, 0] == pytest.approx(100.0 * number, abs=1e-8)


@pytest.mark.parametrize("n_var", [10, 30, 50])
def test_levy_f9_minimum_is_off_its_shift_as_in_the_official_code(n_var):
    problem = CEC2017(9, n_var=n_var)
    o = shift_vector(9, n_var)
    # at o, z = 0 and w = 0.75: F9(o) = 900 + Levy(0) > 900 (901.44 at D = 10)
    assert problem.evaluate(o[None])[0, 0] > 901.0
    assert np.all(np.abs(problem.x_opt) <= 100.0)
    assert problem.evaluate(problem.x_opt[None])[0, 0] == pytest.approx(900.0, abs=1e-10)
    nearby = problem.x_opt + 1e-3 * np.random.default_rng(n_var).standard_normal((6, n_var))
    assert np.all(problem.evaluate(nearby)[:, 0] > 900.0)


@pytest.mark.parametrize("number", IBES_FUNCTIONS)
def test_vectorized_matches_row_by_row_and_exceeds_optimum(number):
    problem = CEC2017(number)
    X = np.random.default_rng(number).uniform(-100.0, 100.0, (8, 30))
    F = problem.evaluate(X)
    assert F.shape == (8, 1)
    rows = [problem.evaluate(x[None])[0, 0] for x in X]
    np.testing.assert_array_equal(F[:, 0], rows)
    assert np.all(F[:, 0] > 100.0 * number)


def test_pickles_and_deep_copies():
    problem = CEC2017(30, n_var=10)
    X = np.random.default_rng(3).uniform(-100.0, 100.0, (4, 10))
    for clone in (pickle.loads(pickle.dumps(problem)), copy.deepcopy(problem)):
        assert clone.number == 30 and clone.n_var == 10
        np.testing.assert_array_equal(clone.x_opt, problem.x_opt)
        np.testing.assert_array_equal(clone.evaluate(X), problem.evaluate(X))


def test_every_dimension_with_official_data_builds():
    for n_var in (10, 30, 50, 100):
        problem = CEC2017(30, n_var=n_var)
        assert problem.x_opt.shape == (n_var,)
        assert problem.evaluate(problem.x_opt[None])[0, 0] == pytest.approx(3000.0, abs=1e-8)


def test_bad_number_and_dimension():
    with pytest.raises(UnknownNameError, match="unknown CEC2017 function 2"):
        CEC2017(2)
    with pytest.raises(UnknownNameError, match="unknown CEC2017 function 31"):
        CEC2017(31)
    with pytest.raises(ParameterError, match="CEC2017 function number must be an integer"):
        CEC2017(3.0)
    with pytest.raises(ParameterError, match="CEC2017 function number must be an integer"):
        CEC2017(True)
    with pytest.raises(ParameterError, match="n_var must be one of"):
        CEC2017(3, n_var=7)
    with pytest.raises(ParameterError, match="n_var must be one of"):
        CEC2017(3, n_var=20)  # minionpy has D = 20 data for some functions; the suite does not
    with pytest.raises(ParameterError, match="n_var must be an integer"):
        CEC2017(3, n_var=30.0)


def test_bad_points_raise_instead_of_reading_past_the_row():
    problem = CEC2017(3, n_var=10)
    # pymoo checks the width of an ndarray only (and only with assertions on): a list goes through
    with pytest.raises(ShapeError, match=r"x must have shape \(n, 10\), got \(2, 7\)"):
        problem.evaluate([[0.0] * 7, [0.0] * 7])
    with pytest.raises(NonFiniteError, match="x must hold finite values only"):
        problem.evaluate(np.full((1, 10), np.nan))
