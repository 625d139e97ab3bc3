"""The EOSMA paper's solving protocol (moik.experiments.protocol)."""

import numpy as np
import pytest
from pymoo.core.problem import Problem

from moik.algorithms import EO, PSO
from moik.exceptions import ParameterError
from moik.experiments.protocol import solve_until_success


class Sphere(Problem):
    def __init__(self):
        super().__init__(n_var=7, n_obj=1, xl=-10.0, xu=10.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = (X * X).sum(axis=1)


def test_solved_on_first_run():
    out = solve_until_success(Sphere(), lambda: EO(pop_size=30), ("n_gen", 300), seed=4)
    assert out.solved and out.attempts == 1 and out.best_f < 1e-6
    assert out.total_time > 0 and out.run_f == [out.best_f]
    assert out.best.F[0] == out.best_f


def test_unsolvable_runs_until_max_failures_and_keeps_best():
    out = solve_until_success(Sphere(), lambda: PSO(pop_size=5), ("n_gen", 2), seed=4,
                              threshold=1e-12, max_failures=4)
    assert not out.solved and out.attempts == 4 and len(set(out.seeds)) == 4
    assert out.best_f == min(out.run_f) and out.best.F[0] == out.best_f


def test_reproducible_from_one_seed():
    runs = [solve_until_success(Sphere(), lambda: PSO(pop_size=5), ("n_gen", 3), seed=9,
                                threshold=1e-12, max_failures=3) for _ in range(2)]
    assert runs[0].seeds == runs[1].seeds and runs[0].run_f == runs[1].run_f
    np.testing.assert_array_equal(runs[0].best.X, runs[1].best.X)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"threshold": 0.0}, "threshold must be a finite number > 0"),
    ({"max_failures": 0}, "max_failures must be an integer >= 1"),
])
def test_bad_arguments(kwargs, message):
    with pytest.raises(ParameterError, match=message):
        solve_until_success(Sphere(), lambda: EO(), ("n_gen", 2), seed=0, **kwargs)


def test_factory_must_return_algorithm():
    with pytest.raises(ParameterError, match="must return a pymoo Algorithm"):
        solve_until_success(Sphere(), lambda: "eo", ("n_gen", 2), seed=0)
