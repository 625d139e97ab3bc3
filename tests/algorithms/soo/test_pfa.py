"""Pathfinder (moik.algorithms.soo.pfa): pathfinder and follower moves, runs."""

import math

import numpy as np
import pytest

from moik.algorithms import PFA, get_algorithm
from moik.algorithms.soo.pfa import follower_move, pathfinder_move
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_pfa_pathfinder_and_followers():
    rng = ScriptedRng([0.5], [0.5])
    out = pathfinder_move(np.array([1.0]), np.array([0.0]), 1, 2, rng=rng)
    np.testing.assert_allclose(out, [1.0 + 2 * 0.5 * 1.0 + 0.5 * math.exp(-1.0)])
    X = np.array([[0.0, 0.0], [3.0, 4.0]])  # row 0: pathfinder; D = 5
    rng = ScriptedRng([1], [[0.5, 0.5]], [[0.5, 0.5]], [[0.1, -0.1]])  # j offset, r1, r2, u1
    out = follower_move(X, X[0], 1, 2, 2.0, 1.0, rng=rng)
    eps = 0.5 * np.array([0.1, -0.1]) * 5.0
    np.testing.assert_allclose(out, [[3.0, 4.0] + 1.0 * -X[1] + 0.5 * -X[1] + eps])


def test_deterministic_in_bounds_and_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("pfa", pop_size=20),
                                    sphere(n_var=7, bound=10.0), n_eval=1037, seed=11,
                                    bound=10.0, other_seed=12)


def test_evaluations_per_iteration_as_documented(check, sphere):
    assert check.n_eval_after(lambda: PFA(pop_size=10), sphere(n_var=5), ("n_gen", 4)) == 40


def test_sphere_10d_below_1e_6_within_30000_evaluations(check):
    check.solves_sphere(lambda: get_algorithm("pfa", pop_size=30), level=1e-6)


def test_constrained_feasibility_first(check):
    check.feasibility_first(lambda: get_algorithm("pfa", pop_size=20))


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("pfa", pop_size=30), ik.Q_GENERAL,
                                  ("n_eval", 3000), level=5.0)


def test_ask_tell_matches_minimize_for_multi_batch_generations(check, sphere):
    res = check.ask_tell_matches_minimize(lambda: PFA(pop_size=12), sphere(n_var=4),
                                          ("n_eval", 500), seed=5)
    assert res.algorithm.evaluator.n_eval == 500


def test_bad_parameters_raise():
    with pytest.raises(ParameterError, match=r"max_iter must be a positive integer"):
        PFA(max_iter=0)
