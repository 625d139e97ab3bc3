"""pymoo's MOEA/D with default reference directions (moik.algorithms.moo.moead_pymoo)."""

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms.moo.moead_pymoo import PymooMOEAD
from moik.algorithms.moo.reference_directions import das_dennis_partitions
from moik.exceptions import ParameterError


def test_moead_default_reference_directions():
    assert das_dennis_partitions(2, 100) == 99 and das_dennis_partitions(3, 100) == 12
    res = minimize(get_problem("zdt1", n_var=5), PymooMOEAD(pop_size=30), ("n_gen", 3), seed=0)
    assert res.algorithm.ref_dirs.shape == (30, 2)
    res = minimize(get_problem("dtlz2", n_obj=3), PymooMOEAD(), ("n_gen", 2), seed=0)
    assert res.algorithm.ref_dirs.shape == (91, 3)  # C(12 + 2, 2) = 91 <= 100
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        PymooMOEAD(pop_size=1)


def test_pymoo_options_pass_and_unknown_keywords_are_refused():
    assert PymooMOEAD(n_neighbors=10).n_neighbors == 10
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) n_neighbours for PymooMOEAD; "
                                             r"accepted: .*n_neighbors"):
        PymooMOEAD(n_neighbours=10)


class _ShiftedFront(Problem):
    """f = (x1, 1 - sqrt(x1) + x2); feasible only for x1 >= 0.4: infeasible points have lower f1.

    Records every evaluated row, to check the ideal point against all of them.
    """

    def __init__(self):
        super().__init__(n_var=3, n_obj=2, n_ieq_constr=1, xl=0.0, xu=1.0)
        self.seen_F, self.seen_G = [], []

    def _evaluate(self, X, out, *args, **kwargs):
        F = np.column_stack([X[:, 0], 1.0 - np.sqrt(X[:, 0]) + X[:, 1:].sum(axis=1)])
        G = 0.4 - X[:, :1]
        self.seen_F.append(F)
        self.seen_G.append(G)
        out["F"], out["G"] = F, G


def test_with_constraints_the_decomposition_uses_the_best_feasible_values():
    problem = _ShiftedFront()
    res = minimize(problem, PymooMOEAD(pop_size=20), ("n_eval", 600), seed=1)
    F, G = np.vstack(problem.seen_F), np.vstack(problem.seen_G)[:, 0]
    algorithm = res.algorithm
    np.testing.assert_array_equal(algorithm.feasible_ideal, F[G <= 0.0].min(axis=0))
    assert algorithm.feasible_ideal[0] >= 0.4 > algorithm.ideal[0]  # pymoo's: every point
    assert np.all(problem.evaluate(res.X, return_values_of=["G"]) <= 0.0)
