"""Every registered algorithm, with default arguments: same seed -> the same
result bit for bit, answers within bounds, the global numpy random state
untouched (design.md, "Randomness")."""

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import available, get_algorithm
from moik.algorithms.registry import is_multi_objective


class ShiftedSphere(Problem):
    def __init__(self):
        super().__init__(n_var=5, n_obj=1, xl=-5.0, xu=3.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = ((X - 1.3) ** 2).sum(axis=1)


def _run(name: str, seed: int):
    if is_multi_objective(name):
        problem, budget = get_problem("zdt1", n_var=6), 1200
    else:
        problem, budget = ShiftedSphere(), 1500
    res = minimize(problem, get_algorithm(name), ("n_eval", budget), seed=seed)
    return problem, res


@pytest.mark.parametrize("name", available())
def test_deterministic_within_bounds_global_state_untouched(name):
    state = np.random.get_state()  # noqa: NPY002 (checking the legacy global state)
    problem, a = _run(name, 7)
    _, b = _run(name, 7)
    after = np.random.get_state()  # noqa: NPY002
    assert after[0] == state[0] and np.array_equal(after[1], state[1]) and after[2:] == state[2:]
    np.testing.assert_array_equal(np.atleast_2d(a.X), np.atleast_2d(b.X))
    np.testing.assert_array_equal(np.atleast_2d(a.F), np.atleast_2d(b.F))
    X = np.atleast_2d(a.X)
    assert np.all(problem.xl <= X) and np.all(problem.xu >= X)
    assert np.all(np.isfinite(a.F))


def test_kinds():
    assert is_multi_objective("moeosma") and is_multi_objective("nsga2")
    assert not is_multi_objective("eosma") and not is_multi_objective("pymoo-de")
