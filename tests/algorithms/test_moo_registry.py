"""Every registered multi-objective algorithm: defaults, determinism, bounds, ZDT1 and IK."""

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import available, get_algorithm
from moik.algorithms.archive import nondominated_mask
from moik.algorithms.moo.moead import MOEAD, das_dennis_partitions
from moik.exceptions import ParameterError
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots import get_robot

MO_NAMES = ["moeosma", "mo-m-pso", "nsga2", "moead", "sms-emoa", "mopso-cd"]
OURS = ["moeosma", "mo-m-pso"]


def ik_problem():
    target = Target.from_euler((50, -25, 75), (0, 0, 0), convention="eosma-euler", degrees=True)
    return BiObjectiveIK(get_robot("eosma7"), target, orientation="eosma-euler")


def test_names_registered_and_default_construction():
    assert set(MO_NAMES) <= set(available())
    for name in MO_NAMES:
        get_algorithm(name)
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) zz .*accepted: .*archive"):
        get_algorithm("moeosma", zz=1)


@pytest.mark.parametrize("name", MO_NAMES)
@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_same_seed_bit_identical_within_bounds_nondominated(name, problem_name):
    problem = ik_problem() if problem_name == "ik" else get_problem("zdt1", n_var=10)
    xl, xu = problem.bounds()
    state = np.random.get_state()  # noqa: NPY002
    runs = [minimize(problem, get_algorithm(name, pop_size=20), ("n_eval", 1200), seed=7)
            for _ in range(2)]
    after = np.random.get_state()  # noqa: NPY002
    assert state[0] == after[0] and np.array_equal(state[1], after[1])
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    np.testing.assert_array_equal(runs[0].F, runs[1].F)
    res = runs[0]
    assert res.F.ndim == 2 and res.F.shape[1] == 2 and len(res.F) >= 1
    assert np.array_equal(np.clip(res.X, xl, xu), res.X)
    assert nondominated_mask(res.F).all()
    assert 1200 <= res.algorithm.evaluator.n_eval <= 1200 + 40


@pytest.mark.parametrize("name", OURS)
def test_moik_mo_algorithms_stop_at_exact_n_eval(name):
    res = minimize(get_problem("zdt1", n_var=10), get_algorithm(name, pop_size=20),
                   ("n_eval", 1111), seed=0)
    assert res.algorithm.evaluator.n_eval == 1111


def test_moead_default_reference_directions():
    assert das_dennis_partitions(2, 100) == 99 and das_dennis_partitions(3, 100) == 12
    res = minimize(get_problem("zdt1", n_var=5), MOEAD(pop_size=30), ("n_gen", 3), seed=0)
    assert res.algorithm.ref_dirs.shape == (30, 2)
    res = minimize(get_problem("dtlz2", n_obj=3), MOEAD(), ("n_gen", 2), seed=0)
    assert res.algorithm.ref_dirs.shape == (91, 3)  # C(12 + 2, 2) = 91 <= 100
    with pytest.raises(ParameterError, match="pop_size must be an integer >= 2"):
        MOEAD(pop_size=1)
