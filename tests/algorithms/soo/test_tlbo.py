"""Teaching-learning-based optimization (moik.algorithms.soo.tlbo): both phases, runs."""

import numpy as np
import pytest

from moik.algorithms import TLBO, get_algorithm
from moik.algorithms.soo.tlbo import learner_phase, random_partners, teacher_phase
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_tlbo_teacher_and_learner_phases():
    X = np.array([[0.0], [2.0]])  # mean 1
    rng = ScriptedRng([1, 2], [[0.5], [0.25]])  # T_F, r
    out = teacher_phase(X, np.array([0.0]), rng=rng)
    np.testing.assert_allclose(out, [[0.0 + 0.5 * (0 - 1)], [2.0 + 0.25 * (0 - 2)]])
    rng = ScriptedRng([[0.5], [0.5]])
    out = learner_phase(X, np.array([True, False]), np.array([1, 0]), rng=rng)
    np.testing.assert_allclose(out, [[0.0 + 0.5 * (0 - 2)], [2.0 + 0.5 * (0 - 2)]])
    j = random_partners(5, rng=np.random.default_rng(1))
    assert np.all(j != np.arange(5)) and np.all((j >= 0) & (j < 5))


def test_deterministic_in_bounds_and_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("tlbo", pop_size=20),
                                    sphere(n_var=7, bound=10.0), n_eval=1037, seed=11,
                                    bound=10.0, other_seed=12)


def test_evaluations_per_iteration_as_documented(check, sphere):
    n_eval = check.n_eval_after(lambda: TLBO(pop_size=10), sphere(n_var=5), ("n_gen", 4))
    assert n_eval == 10 + 3 * 10 * 2


def test_sphere_10d_below_1e_6_within_30000_evaluations(check):
    check.solves_sphere(lambda: get_algorithm("tlbo", pop_size=30), level=1e-6)


def test_constrained_feasibility_first(check):
    check.feasibility_first(lambda: get_algorithm("tlbo", pop_size=20))


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("tlbo", pop_size=30), ik.Q_GENERAL,
                                  ("n_eval", 3000), level=5.0)


def test_ask_tell_matches_minimize_for_multi_batch_generations(check, sphere):
    res = check.ask_tell_matches_minimize(lambda: TLBO(pop_size=12), sphere(n_var=4),
                                          ("n_eval", 500), seed=5)
    assert res.algorithm.evaluator.n_eval == 500


def test_bad_parameters_raise():
    with pytest.raises(ParameterError, match=r"pop_size must be an integer >= 2"):
        TLBO(pop_size=1)
