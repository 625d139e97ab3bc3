"""No point any algorithm finds dominates the reference fronts of the paper poses.

The reference fronts are local solutions (:mod:`moik.fronts.front`); these runs are the
check against a better branch they could have missed: pymoo's NSGA-II (a long run) and
moik's MOEOSMA (the EOSMA paper's budget) at EOSMA P1, MO-m-PSO at its Eq. 16 pose. A
found point counts against the front only if it beats a reference point by more than
``TOL`` somewhere and is nowhere worse by more than ``TOL``
(:func:`moik.fronts.dominating_points`).
"""

import numpy as np
import pytest
from pymoo.optimize import minimize

from moik.algorithms import get_algorithm
from moik.fronts import dominating_points
from moik.problems import get_problem

TOL = 1e-6  # metres / cm (the problem's unit) and radians


def test_dominating_points_rule():
    ref = np.array([[0.0, 1.0], [0.5, 0.5], [1.0, 0.0]])
    found = np.array([[0.5 - 2e-6, 0.5], [0.5 - 2e-6, 0.5 + 2e-6], [0.6, 0.6], [0.4, 0.4]])
    np.testing.assert_array_equal(dominating_points(ref, found, 1e-6), found[[0, 3]])


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
