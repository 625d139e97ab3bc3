"""No point any algorithm finds dominates the reference fronts of the paper poses.

The reference fronts are local solutions (:mod:`moik.fronts.front`); these runs are the
check against a better branch they could have missed: pymoo's NSGA-II (a long run) and
moik's MOEOSMA (the EOSMA paper's budget) at EOSMA P1, MO-m-PSO at its Eq. 16 pose. A
found point counts against the front if it beats a reference point in both objectives by
more than ``TOL`` of the front's range in each (:func:`moik.fronts.dominating_points`;
the errors are in different units, cm or m and rad, so the tolerance is relative).
"""

import numpy as np
import pytest
from pymoo.optimize import minimize

from moik.algorithms import get_algorithm
from moik.fronts import dominating_points
from moik.problems import get_problem

TOL = 1e-6  # a share of the reference front's range per objective


def test_dominating_points_rule():
    ref = np.array([[0.0, 2.0], [0.5, 1.0], [1.0, 0.0]])  # ranges 1 and 2
    found = np.array([[0.5 - 2e-6, 1.0 - 3e-6], [0.5 - 2e-6, 1.0 - 1e-6], [0.5 - 2e-6, 1.0],
                      [0.6, 1.2], [0.4, 0.8]])
    np.testing.assert_array_equal(dominating_points(ref, found, 1e-6), found[[0, 4]])
    np.testing.assert_array_equal(dominating_points([[0.0, 0.0]], [[-1e-3, -1e-3]], 1e-6),
                                  [[-1e-3, -1e-3]])  # one point: absolute


@pytest.mark.parametrize(("name", "algorithm", "n_gen"), [
    ("eosma-p1", "nsga2", 400),
    ("eosma-p1", "moeosma", 1001),
    ("mpso-eq16", "nsga2", 300),
    ("mpso-eq16", "mo-m-pso", 501),
])
def test_no_run_dominates_the_reference_front(name, algorithm, n_gen):
    problem = get_problem(name)
    ref = problem.pareto_front()
    res = minimize(problem, get_algorithm(algorithm, pop_size=100), ("n_gen", n_gen), seed=7)
    beating = dominating_points(ref, res.F, TOL)
    assert len(beating) == 0, beating
