"""moik/solver/memetic.py: the memetic search fills the archive with exact, mutually
non-dominated points, the same for the same seeds."""

import numpy as np

from moik.algorithms.archive.fronts import nondominated_mask
from moik.problems.pareto_ik import ParetoIK
from moik.robots import get_robot
from moik.solver.memetic import memetic_search
from moik.solver.pareto_search import Projector
from moik.solver.session import pose_errors

SEARCH = {"starts": 8, "method": "moeosma", "pop_size": 10, "generations": 2,
          "local_iterations": 1, "local_step": 0.2, "seed": 1}


def _archive(**search):
    problem = ParetoIK(get_robot("iiwa14"), np.array([0.4, 0.2, 0.5]),
                       objectives=("manipulability", "limit_margin"))
    projector = Projector(problem)
    memetic_search(projector, np.empty((0, 7)), np.random.default_rng(0), **{**SEARCH, **search})
    return problem, projector


def test_the_archive_holds_exact_mutually_non_dominated_points():
    problem, projector = _archive()
    assert len(projector.X) >= 2 and projector.n_exact >= len(projector.X)
    pos, _ = pose_errors(problem.robot, problem.target, projector.X)
    assert (pos <= problem.tol_position).all()
    assert nondominated_mask(projector.F).all()
    np.testing.assert_array_equal(projector.F, projector.criteria(projector.X))


def test_the_same_seeds_give_the_same_archive():
    first, again = _archive()[1], _archive()[1]
    np.testing.assert_array_equal(first.X, again.X)
    only_lm = _archive(generations=0, local_iterations=0)[1]
    assert only_lm.n_eval < first.n_eval  # the search and local search evaluate more
