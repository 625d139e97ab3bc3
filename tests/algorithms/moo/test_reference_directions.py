"""Default Das-Dennis directions (moik.algorithms.moo.reference_directions); one objective
is refused, not looped on forever (issue 26)."""

import subprocess
import sys
from math import comb

import pytest
from hypothesis import given
from hypothesis import strategies as st

from moik.algorithms.moo.reference_directions import das_dennis_partitions, default_ref_dirs
from moik.exceptions import ParameterError


@given(st.integers(2, 6), st.integers(1, 400))
def test_partitions_are_the_most_that_fit(n_obj, pop_size):
    p = das_dennis_partitions(n_obj, pop_size)
    assert p >= 1
    assert p == 1 or comb(p + n_obj - 1, n_obj - 1) <= pop_size
    assert comb(p + 1 + n_obj - 1, n_obj - 1) > pop_size


def test_two_objectives_give_pop_size_directions():
    assert default_ref_dirs(2, 30).shape == (30, 2)
    assert default_ref_dirs(3, 100).shape == (91, 3)


@pytest.mark.parametrize("n_obj", [1, 0, -2])
def test_fewer_than_two_objectives_are_refused(n_obj):
    with pytest.raises(ParameterError, match="n_obj >= 2"):
        das_dennis_partitions(n_obj, 100)


SCRIPT = """
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from moik.algorithms import get_algorithm
from moik.exceptions import ParameterError
for name in ("mompa", "moead", "moead-pymoo"):
    try:
        minimize(get_problem("sphere"), get_algorithm(name), ("n_gen", 2), seed=1)
    except ParameterError as e:
        assert "n_obj=1" in str(e), e
        print(name, "refused")
"""


def test_decomposition_algorithms_refuse_one_objective_without_hanging():
    out = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["mompa", "refused", "moead", "refused",
                                  "moead-pymoo", "refused"]
