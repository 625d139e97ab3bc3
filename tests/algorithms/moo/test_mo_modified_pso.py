"""MO-m-PSO (moik.algorithms.moo.mo_modified_pso): evaluation count, the shared archive and
the compromise."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOMPSO
from moik.algorithms.archive import nondominated_mask
from moik.exceptions import ParameterError
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


def test_bad_values():
    with pytest.raises(ParameterError, match=r"w must be a number in \[0.0, 1.5\]"):
        MOMPSO(w=2)
    with pytest.raises(ParameterError, match="switch must be one of mean-position, mean-fitness"):
        MOMPSO(switch="median")
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        MOMPSO(pop_size=1.5)
