"""The search machinery of solve_ik_pareto: the Projector and its archive, the projected
criteria, the seeded sampling, branch enumeration, mo_search and spread_subset.

Hand cases on planar2 (tests/solver/planar2_cases.py: a position target has exactly two
solutions); the projection's 2 pi copies on ur5, whose joints span [-2 pi, 2 pi].
"""

import numpy as np
import pytest
from pymoo.core.problem import Problem

from moik.problems import random_reachable_targets
from moik.problems.pareto_ik import ParetoIK
from moik.problems.targets import Target
from moik.robots import get_robot
from moik.robots.chain import fk_reference
from moik.solver.pareto_search import (
    ProjectedCriteria,
    Projector,
    SeededSampling,
    enumerate_branches,
    mo_search,
    spread_subset,
)
from tests.solver.planar2_cases import ARM, branches, elbow_distance, elbow_guard, wrapped

XY = (0.3, 0.25)
SOLS = branches(*XY)
OBJECTIVES = ("manipulability", "limit_margin")


def _planar(objectives=OBJECTIVES):
    return ParetoIK(ARM, Target([*XY, 0.0]), objectives=objectives)


def test_projected_ends_are_exact_and_within_the_limits():
    projector = Projector(_planar())
    X = ARM.random_q(12, rng=np.random.default_rng(0))
    P, ok, cost = projector.project(X)
    assert P.shape == X.shape and ok.sum() >= 6 and projector.n_eval >= 12
    assert np.all(ARM.within_limits(P))
    miss = np.linalg.norm(fk_reference(ARM, P[ok])[:, :3, 3] - [*XY, 0.0], axis=1)
    assert np.all(miss <= projector.problem.tol.stop[0])  # a converged end meets the stop
    # cost = 0.5 (miss / reach)^2 (position target), up to the two FKs' rounding
    np.testing.assert_allclose(np.sqrt(2 * cost[ok]) * ARM.reach, miss, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(X, ARM.random_q(12, rng=np.random.default_rng(0)))
    assert len(projector.X) == 0  # projecting archives nothing


def test_projection_moves_to_the_copies_nearest_q_current():
    ur5 = get_robot("ur5")
    target = random_reachable_targets(ur5, 1, seed=4)[0]
    q_current = np.zeros(6)
    raw = Projector(ParetoIK(ur5, target, objectives=OBJECTIVES))
    near = Projector(ParetoIK(ur5, target, objectives=OBJECTIVES, q_current=q_current))
    X = ur5.random_q(10, rng=np.random.default_rng(1))
    P_raw, ok_raw, _ = raw.project(X)
    P, ok, _ = near.project(X)
    np.testing.assert_array_equal(ok, ok_raw)
    np.testing.assert_allclose(wrapped(P, P_raw), 0.0, atol=1e-12)  # the same ends...
    assert np.all(np.abs(P) <= np.pi + 1e-12)  # ...each joint's copy nearest 0
    assert np.any(np.abs(P_raw) > np.pi)  # (some raw ends were elsewhere)


def test_the_archive_keeps_the_mutually_nondominated_distinct_points():
    """Minimisation form: (3, 3) is dominated by (1, 2); the second (1, 2) is a repeat."""
    projector = Projector(_planar())
    P = np.array([[0.0, 0.1], [0.2, 0.3], [0.4, 0.5], [0.6, 0.7]])
    F = np.array([[1.0, 2.0], [2.0, 1.0], [3.0, 3.0], [1.0, 2.0]])
    out = projector.objectives(P, F.copy())
    np.testing.assert_array_equal(out, F)
    np.testing.assert_array_equal(projector.X, P[:2])
    np.testing.assert_array_equal(projector.F, F[:2])
    np.testing.assert_array_equal(projector.worst, [3.0, 3.0])
    assert projector.n_exact == 4
    X_seen, F_seen = projector.seen()
    np.testing.assert_array_equal(X_seen, P)  # every exact point, dominated ones too
    projector.objectives(P[2:3], np.array([[0.5, 0.5]]))  # a newcomer dominating both
    np.testing.assert_array_equal(projector.F, [[0.5, 0.5]])
    assert len(projector.seen()[0]) == 5


def test_a_point_below_the_clearance_is_scored_worse_than_every_exact_point():
    """With branch 0 0.1 deep in contact: the penalty ``worst + (1 + |worst|)(1 + depth)``
    with ``depth = clearance - d = 0.1``; only branch 1 enters the archive."""
    guard = elbow_guard(SOLS[0])
    projector = Projector(_planar(), guard=guard)
    F_true = projector.criteria(SOLS)
    F = projector.objectives(SOLS.copy())
    worst = projector.worst
    assert np.all(worst >= F_true.max(axis=0))
    np.testing.assert_allclose(F[0], worst + (1.0 + np.abs(worst)) * 1.1, rtol=1e-12)
    np.testing.assert_array_equal(F[1], F_true[1])
    assert np.all(F[0] > F_true.max(axis=0))
    np.testing.assert_array_equal(projector.X, SOLS[1:])
    assert elbow_distance(SOLS[1], SOLS[0]) > 0


def test_evaluate_scores_unconverged_starts_below_every_exact_point():
    iiwa = get_robot("iiwa14")
    target = random_reachable_targets(iiwa, 1, seed=11)[0]
    projector = Projector(ParetoIK(iiwa, target, objectives=OBJECTIVES))
    X = iiwa.random_q(40, rng=np.random.default_rng(2))
    _, ok, _ = Projector(ParetoIK(iiwa, target, objectives=OBJECTIVES)).project(X)
    assert ok.any() and not ok.all()
    F = projector.evaluate(X)
    assert np.all(F[~ok] > projector.worst)  # every exact point dominates them
    assert len(projector.X) and np.all(projector.worst >= projector.F)


def test_projected_criteria_doubles_a_single_criterion():
    projector = Projector(_planar(("manipulability",)))
    criteria = ProjectedCriteria(projector)
    assert criteria.n_obj == 2 and criteria.n_var == 2
    out = criteria.evaluate(SOLS.copy(), return_as_dictionary=True)
    np.testing.assert_array_equal(out["F"][:, 0], out["F"][:, 1])


def test_seeded_sampling_puts_the_seeds_first():
    problem = Problem(n_var=2, n_obj=2, xl=np.array([-1.0, 0.0]), xu=np.array([1.0, 5.0]))
    X0 = np.array([[0.5, 4.0], [-0.5, 1.0]])
    draw = SeededSampling(X0)._do(problem, 6, random_state=np.random.default_rng(3))
    np.testing.assert_array_equal(draw[:2], X0)
    assert draw.shape == (6, 2) and np.all((draw >= [-1, 0]) & (draw <= [1, 5]))
    again = SeededSampling(X0)._do(problem, 6, random_state=np.random.default_rng(3))
    np.testing.assert_array_equal(draw, again)
    one = SeededSampling(X0)._do(problem, 1, random_state=np.random.default_rng(3))
    np.testing.assert_array_equal(one, X0[:1])


def test_enumerate_branches_archives_both_planar_solutions():
    projector = Projector(_planar())
    enumerate_branches(projector, ARM.random_q(64, rng=np.random.default_rng(4)))
    X, _ = projector.seen()
    assert len(X) == 2 and projector.n_exact == 2 and projector.n_eval > 0
    for s in SOLS:
        assert min(wrapped(x, s).max() for x in X) < 1e-6


@pytest.mark.parametrize("method", ["nsga2"])
def test_mo_search_is_deterministic_and_archives_exact_points(method):
    runs = []
    for _ in range(2):
        projector = Projector(_planar())
        mo_search(projector, method, SOLS.copy(), pop_size=8, generations=3, seed=5)
        runs.append(projector)
    a, b = runs
    assert len(a.X) and a.n_exact > 0
    np.testing.assert_array_equal(a.X, b.X)
    miss = np.linalg.norm(fk_reference(ARM, a.X)[:, :3, 3] - [*XY, 0.0], axis=1)
    assert np.all(miss <= a.problem.tol.position)


def test_spread_subset_by_hand():
    """Each column's minimum first (rows 0 and 1), then the row farthest from them: row 2
    (0.71 from each in the scaled plane) before row 3 (0.14 from row 0). A row that is
    both minima is taken once."""
    F = np.array([[0.0, 1.0], [1.0, 0.0], [0.5, 0.5], [0.1, 0.9]])
    np.testing.assert_array_equal(spread_subset(F, 3), [0, 1, 2])
    np.testing.assert_array_equal(spread_subset(F, 2), [0, 1])
    G = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]])
    # scaled: (0, 0), (1/3, 1), (1, 1/2): row 1 at 1.054, row 2 at 1.118 from row 0
    np.testing.assert_array_equal(spread_subset(G, 2), [0, 2])
