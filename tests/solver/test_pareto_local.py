"""The local search along a redundant arm's solution set: null spaces (against finite
differences of the reference FK), constrained steepest descent (properties), the weighted
scores and the choice of starts (by hand), and a descent that improves its criterion."""

from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from moik.problems import random_reachable_targets
from moik.problems.pareto_ik import ParetoIK
from moik.problems.targets import Target
from moik.robots import get_robot
from moik.robots.chain import fk_reference
from moik.solver.pareto_local import (
    LIMIT_GAP,
    descent_directions,
    local_search,
    local_search_starts,
    nullspace,
    scaled_scores,
)
from moik.solver.pareto_search import Projector
from tests.solver.planar2_cases import ARM

IIWA = get_robot("iiwa14")
POSE = random_reachable_targets(IIWA, 1, seed=11)[0]


def _velocity(robot, q, n, h=1e-6):
    """First-order change of position (central differences of the reference FK) and of
    rotation (the angle of R(q + h n) R(q - h n)^T) along ``n``, per unit step."""
    T = fk_reference(robot, np.array([q + h * n, q - h * n]))
    dp = (T[0, :3, 3] - T[1, :3, 3]) / (2 * h)
    dR = Rotation.from_matrix(T[0, :3, :3] @ T[1, :3, :3].T).magnitude() / (2 * h)
    return np.linalg.norm(dp), dR


@pytest.mark.parametrize("position_only, dim", [(False, 1), (True, 4)])
def test_nullspace_keeps_the_task_to_first_order(position_only, dim):
    target = Target(POSE.position) if position_only else POSE
    projector = Projector(ParetoIK(IIWA, target, objectives=("manipulability",)))
    assert projector.task_rows == (3 if position_only else 6)
    P = IIWA.random_q(3, rng=np.random.default_rng(0))
    N = nullspace(projector, P)
    assert N.shape == (3, dim, 7)
    for q, basis in zip(P, N, strict=True):
        np.testing.assert_allclose(basis @ basis.T, np.eye(dim), atol=1e-12)  # orthonormal
        for n in basis:
            dp, dR = _velocity(IIWA, q, n)
            assert dp <= 1e-7 and (position_only or dR <= 1e-7)
    # and a direction off it moves the tool (the test can fail)
    off = np.linalg.svd(N[0])[2][-1] if dim < 7 else None
    assert _velocity(IIWA, P[0], off)[0] > 1e-3


def _orthonormal_rows(seed, r, dof):
    Q, _ = np.linalg.qr(np.random.default_rng(seed).normal(size=(dof, dof)))
    return Q[:r]


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 10**6), r=st.integers(1, 4),
       at=st.lists(st.sampled_from([-1, 0, 1]), min_size=6, max_size=6))
def test_descent_holds_the_joints_it_would_push_out(seed, r, at):
    """``d`` is the steepest descent within the null space (``-N^T g``) unless a joint at a
    limit would leave it; then that joint does not move, ``d`` stays in the null space and
    is still a descent (the weighted sum's derivative ``g . (N d) <= 0``)."""
    dof = 6
    robot = SimpleNamespace(lower=-np.ones(dof), upper=np.ones(dof))
    N = _orthonormal_rows(seed, r, dof)[None]
    g = np.random.default_rng(seed + 1).normal(size=(1, r))
    P = np.random.default_rng(seed + 2).uniform(-0.5, 0.5, size=(1, dof))
    P[0, np.array(at) < 0], P[0, np.array(at) > 0] = -1.0, 1.0
    free = -np.einsum("ar,ard->ad", g, N)[0]
    held = ((P[0] <= -1 + LIMIT_GAP) & (free < 0)) | ((P[0] >= 1 - LIMIT_GAP) & (free > 0))
    d = descent_directions(robot, P.copy(), N, g)[0]
    if not held.any():
        np.testing.assert_array_equal(d, free)
        return
    np.testing.assert_allclose(d[held], 0.0, atol=1e-12)
    np.testing.assert_allclose(N[0].T @ (N[0] @ d), d, atol=1e-12)  # in the null space
    assert g[0] @ (N[0] @ d) <= 1e-12


def test_scaled_scores_by_hand():
    F = np.array([[1.0, 2.0], [3.0, -4.0]])
    W = np.array([[0.5, 0.5], [1.0, 0.0]])
    # (0.5 * 1 / 1 + 0.5 * 2 / 4, 1 * 3 / 1 + 0)
    np.testing.assert_allclose(scaled_scores(F, W, np.array([1.0, 4.0])), [0.75, 3.0])


def test_starts_are_each_criterions_best_apart_and_the_mixes():
    """Rows at q1 = 0, 0.1, 1, 2 (joint distances 0.1, 1, 2 from the first). Criterion 0
    (1, 2, 3, 4): row 0, then not row 1 (0.1 < START_DISTINCT = 0.3 away) but row 2.
    Criterion 1 (4, 2.2, 1.5, 1): rows 3 and 2. Scaled by the span (3, 3), the mixes
    (0.25, 0.75), (0.5, 0.5), (0.75, 0.25) are least at rows 3 (0.583), 1 (0.7), 0 (0.583)."""
    projector = Projector(ParetoIK(ARM, Target([0.3, 0.25, 0.0]),
                                   objectives=("manipulability", "limit_margin")))
    P = np.array([[0.0, 0.0], [0.1, 0.0], [1.0, 0.0], [2.0, 0.0]])
    F = np.array([[1.0, 4.0], [2.0, 2.2], [3.0, 1.5], [4.0, 1.0]])
    projector.objectives(P, F)
    starts, weights = local_search_starts(projector, per_extreme=2)
    np.testing.assert_array_equal(starts, P[[0, 2, 3, 2, 3, 1, 0]])
    np.testing.assert_array_equal(weights, [[1, 0], [1, 0], [0, 1], [0, 1], [0.25, 0.75],
                                            [0.5, 0.5], [0.75, 0.25]])


def test_local_search_improves_its_criterion_along_the_solution_set():
    """From one exact iiwa14 solution, the descent of -limit_margin finds exact points with
    a larger margin; every one it archives is exact."""
    problem = ParetoIK(IIWA, POSE, objectives=("limit_margin", "manipulability"))
    projector = Projector(problem)
    start = projector.project(IIWA.random_q(8, rng=np.random.default_rng(3)))
    q0 = start[0][start[1]][:1]
    F0 = projector.objectives(q0.copy())
    n_exact = projector.n_exact
    local_search(projector, q0, np.array([[1.0, 0.0]]), iterations=4, step=0.2)
    X, F = projector.seen()
    assert projector.n_exact > n_exact
    assert F[:, 0].min() < F0[0, 0] - 1e-3  # a larger limit margin was reached
    T = fk_reference(IIWA, X)
    assert np.linalg.norm(T[:, :3, 3] - POSE.position, axis=1).max() <= problem.tol.position
