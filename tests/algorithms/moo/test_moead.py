"""MOEA/D with default reference directions (moik.algorithms.moo.moead)."""

import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms.moo.moead import MOEAD, das_dennis_partitions
from moik.exceptions import ParameterError


def test_moead_default_reference_directions():
    assert das_dennis_partitions(2, 100) == 99 and das_dennis_partitions(3, 100) == 12
    res = minimize(get_problem("zdt1", n_var=5), MOEAD(pop_size=30), ("n_gen", 3), seed=0)
    assert res.algorithm.ref_dirs.shape == (30, 2)
    res = minimize(get_problem("dtlz2", n_obj=3), MOEAD(), ("n_gen", 2), seed=0)
    assert res.algorithm.ref_dirs.shape == (91, 3)  # C(12 + 2, 2) = 91 <= 100
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        MOEAD(pop_size=1)


def test_pymoo_options_pass_and_unknown_keywords_are_refused():
    assert MOEAD(n_neighbors=10).n_neighbors == 10
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) n_neighbours for MOEAD; "
                                             r"accepted: .*n_neighbors"):
        MOEAD(n_neighbours=10)
