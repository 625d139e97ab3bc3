"""MO-m-PSO (moik.algorithms.moo.mo_modified_pso): evaluation count, the shared archive and
the compromise."""

import hashlib

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOMPSO
from moik.algorithms.archive import nondominated_mask
from moik.algorithms.moo.objective_swarms import swarm_best, utopia_closest
from moik.exceptions import ParameterError, UnknownNameError
from moik.metrics import closest_to_utopia, compromise


@pytest.mark.parametrize(("switch", "per_iteration"), [("mean-position", 22), ("mean-fitness", 20)])
def test_one_swarm_per_objective_evaluation_count(switch, per_iteration):
    alg = MOMPSO(pop_size=10, switch=switch)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 6), seed=0)
    assert res.algorithm.evaluator.n_eval == 20 + 5 * per_iteration
    assert res.algorithm.X.shape == (20, 5)
    np.testing.assert_array_equal(res.algorithm.swarm, np.repeat([0, 1], 10))


def test_swarms_reach_both_ends_and_compromise_is_closest_to_utopia():
    res = minimize(get_problem("zdt1", n_var=10), MOMPSO(pop_size=30), ("n_eval", 20_000), seed=3)
    assert nondominated_mask(res.F).all() and len(res.F) <= 30
    assert res.F[:, 0].min() < 1e-6  # the f1 swarm drives x1 to its bound 0
    x, f = compromise(res)
    i = closest_to_utopia(res.F)
    np.testing.assert_array_equal(f, res.F[i])
    np.testing.assert_array_equal(x, res.X[i])
    assert np.all((res.X >= 0.0) & (res.X <= 1.0))


def _recording_guides(alg):
    """Wrap ``_social_guide`` to record (archive X, archive F, guide) at every call."""
    calls, inner = [], alg._social_guide

    def record():
        g = inner()
        calls.append((alg.pareto_archive.X.copy(), alg.pareto_archive.F.copy(),
                      alg.pbest_X.copy(), alg.pbest_S.copy(), np.array(g)))
        return g

    alg._social_guide = record
    return calls


def test_compromise_guide_is_the_archive_member_closest_to_utopia_every_iteration():
    alg = MOMPSO(pop_size=10)
    assert alg.guide == "compromise"
    calls = _recording_guides(alg)
    minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 8), seed=1, copy_algorithm=False)
    assert len(calls) == 7  # one per iteration after the initial population
    for AX, AF, _, _, g in calls:
        np.testing.assert_array_equal(g, AX[closest_to_utopia(AF)])
        assert utopia_closest(AF) == closest_to_utopia(AF)
    assert len({g.tobytes() for *_, g in calls}) > 1  # recomputed, it moves


def test_own_best_guide_is_each_swarms_best_on_its_objective():
    alg = MOMPSO(pop_size=10, guide="own-best")
    calls = _recording_guides(alg)
    minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 5), seed=1, copy_algorithm=False)
    for *_, P, S, g in calls:
        np.testing.assert_array_equal(g, swarm_best(P, S, 2))


def test_own_best_guide_keeps_the_independent_swarms_result_bit_for_bit():
    # the fingerprint of MOMPSO (ZDT1, 6 variables, 600 evaluations, seed 3) before the
    # compromise guide became the default
    res = minimize(get_problem("zdt1", n_var=6), MOMPSO(guide="own-best"), ("n_eval", 600), seed=3)
    h = hashlib.sha256()
    for a in (res.X, res.F):
        a = np.ascontiguousarray(np.atleast_1d(np.asarray(a, dtype=float)))
        h.update(str(a.shape).encode())
        h.update(a.tobytes())
    assert h.hexdigest()[:20] == "a5b9e095e32fc8f9d643"


def test_bad_values():
    with pytest.raises(ParameterError, match=r"w must be a number in \[0.0, 1.5\]"):
        MOMPSO(w=2)
    with pytest.raises(ParameterError, match="switch must be one of mean-position, mean-fitness"):
        MOMPSO(switch="median")
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        MOMPSO(pop_size=1.5)
    with pytest.raises(UnknownNameError, match="compromise, own-best"):
        MOMPSO(guide="global")
