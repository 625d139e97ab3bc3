"""CEC2017 functions of the I-BES paper (Section 5.2) through opfunu.

Reference: Awad et al. (2016), CEC2017 problem definitions: F_i(o_i) = 100 i
at the shift vector o_i, the global optimum. Skipped without ``moik[cec]``.
"""

from __future__ import annotations

import numpy as np
import pytest

from moik.exceptions import ParameterError, UnknownNameError
from moik.problems.benchmarks import available_benchmarks, get_benchmark
from moik.problems.benchmarks.cec2017 import CEC2017, IBES_FUNCTIONS

pytest.importorskip("opfunu")


def test_registry_has_the_ibes_nine():
    assert [n for n in available_benchmarks() if n.startswith("cec2017_")] == [
        f"cec2017_F{i}" for i in (3, 8, 9, 14, 15, 18, 19, 27, 30)
    ]


@pytest.mark.parametrize("number", IBES_FUNCTIONS)
def test_value_at_shift_is_100_i(number):
    problem = get_benchmark(f"cec2017_F{number}")
    assert problem.n_var == 30
    np.testing.assert_allclose(problem.xl, -100.0)
    np.testing.assert_allclose(problem.xu, 100.0)
    o = np.asarray(problem.function.f_shift, dtype=float)
    o = o[0] if o.ndim == 2 else o  # composition functions: o_1 is the optimum
    np.testing.assert_array_equal(problem.x_opt, o[:30])
    assert problem.evaluate(o[None, :30])[0, 0] == pytest.approx(100.0 * number, abs=1e-8)
    assert problem.pareto_front()[0, 0] == 100.0 * number


@pytest.mark.parametrize("number", IBES_FUNCTIONS)
def test_vectorized_matches_row_by_row_and_exceeds_optimum(number):
    problem = CEC2017(number)
    X = np.random.default_rng(number).uniform(-100.0, 100.0, (8, 30))
    F = problem.evaluate(X)
    assert F.shape == (8, 1)
    rows = [problem.function.evaluate(x) for x in X]
    np.testing.assert_allclose(F[:, 0], rows)
    assert np.all(F[:, 0] > 100.0 * number)


def test_official_numbering_not_opfunu_numbering():
    # official F3 is Zakharov; opfunu calls it F22017 (it dropped F2)
    assert type(CEC2017(3).function).__name__ == "F22017"
    assert type(CEC2017(30).function).__name__ == "F292017"


def test_bad_number_and_dimension():
    with pytest.raises(UnknownNameError, match="unknown CEC2017 function 2"):
        CEC2017(2)
    with pytest.raises(ParameterError, match="n_var must be one of"):
        CEC2017(3, n_var=7)
