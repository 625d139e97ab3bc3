"""Marine predators (moik.algorithms.soo.mpa): Eqs. 12-16 on hand-computed arrays, runs."""

import numpy as np
import pytest

from moik.algorithms import MPA, get_algorithm
from moik.algorithms.soo.mpa import fads_effect, mpa_cf, mpa_phase, predator_move
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_mpa_phases_and_moves_eqs_12_to_16():
    assert [mpa_phase(t, 9) for t in (0, 2, 3, 5, 6, 8)] == [1, 1, 2, 2, 3, 3]
    assert mpa_cf(5, 10) == 0.5**1.0 and mpa_cf(0, 10) == 1.0
    prey, elite = np.array([[1.0], [2.0]]), np.array([3.0])
    draws = ([[0.0], [0.0]], [[1.0], [1.0]], [[2.0], [1.0]], [[0.5], [0.5]])  # u, v, RB, R
    out = predator_move(prey, elite, 1, 0.5, P=0.5, rng=ScriptedRng(*draws))
    expected = [1.0 + 0.25 * 2.0 * (3 - 2.0 * 1), 2.0 + 0.25 * (3 - 2)]  # Eq. 12
    np.testing.assert_allclose(out[:, 0], expected)
    out = predator_move(prey, elite, 2, 0.5, P=0.5, rng=ScriptedRng(*draws))
    # Eq. 13 with R_L = 0 for the first half; Eq. 14 for the second
    np.testing.assert_allclose(out[:, 0], [1.0, 3.0 + 0.25 * 1.0 * (1.0 * 3 - 2)])
    rng = ScriptedRng(0.1, [[0.1], [0.5]], [[0.5], [0.5]])  # FADs branch, U draw, R
    out = fads_effect(prey, 0.5, FADs=0.2, xl=np.array([0.0]), xu=np.array([4.0]), rng=rng)
    np.testing.assert_allclose(out, [[1.0 + 0.5 * 2.0], [2.0]])
    rng = ScriptedRng(0.9, 0.5, [1, 0], [0, 1])
    out = fads_effect(prey, 0.5, FADs=0.2, xl=np.array([0.0]), xu=np.array([4.0]), rng=rng)
    np.testing.assert_allclose(out, [[1.0 + 0.6 * 1.0], [2.0 - 0.6 * 1.0]])


def test_deterministic_in_bounds_and_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("mpa", pop_size=20),
                                    sphere(n_var=7, bound=10.0), n_eval=1037, seed=11,
                                    bound=10.0, other_seed=12)


def test_evaluations_per_iteration_as_documented(check, sphere):
    n_eval = check.n_eval_after(lambda: MPA(pop_size=10), sphere(n_var=5), ("n_gen", 4))
    assert n_eval == 10 + 3 * 10 * 2


def test_sphere_10d_below_1e_6_within_30000_evaluations(check):
    check.solves_sphere(lambda: get_algorithm("mpa", pop_size=30), level=1e-6)


def test_constrained_feasibility_first(check):
    check.feasibility_first(lambda: get_algorithm("mpa", pop_size=20))


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("mpa", pop_size=30), ik.Q_GENERAL,
                                  ("n_eval", 3000), level=5.0)


def test_ask_tell_matches_minimize_for_multi_batch_generations(check, sphere):
    res = check.ask_tell_matches_minimize(lambda: MPA(pop_size=12), sphere(n_var=4),
                                          ("n_eval", 500), seed=5)
    assert res.algorithm.evaluator.n_eval == 500


@pytest.mark.parametrize(("params", "message"), [
    ({"P": 0}, r"P must be a number in \(0.0, 2.0\]"),
    ({"FADs": "a"}, r"FADs must be a number"),
])
def test_bad_parameters_raise(params, message):
    with pytest.raises(ParameterError, match=message):
        MPA(**params)
