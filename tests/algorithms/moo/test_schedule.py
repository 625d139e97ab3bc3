"""The t/T schedule of the multi-objective algorithms follows the current termination:
n_gen, n_eval, time, pymoo's default and robust terminations, checkpoints resumed with a
new termination (moik.algorithms.array_state.planned_iterations, MOArrayAlgorithm)."""

from __future__ import annotations

import copy

import numpy as np
import pytest
from pymoo.core.termination import TerminateIfAll, TerminateIfAny
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.termination.default import DefaultMultiObjectiveTermination
from pymoo.termination.ftol import MultiObjectiveSpaceTermination
from pymoo.termination.max_eval import MaximumFunctionCallTermination
from pymoo.termination.max_gen import MaximumGenerationTermination
from pymoo.termination.max_time import TimeBasedTermination
from pymoo.termination.robust import RobustTermination

from moik.algorithms import MOALO, MOEOSMA, MOGWO, MOPSO, MOArrayAlgorithm, available, entry
from moik.algorithms.array_state import planned_iterations
from moik.exceptions import ToleranceTerminationWarning

MOIK_MO = [n for n in available("multi-objective") if issubclass(entry(n).cls, MOArrayAlgorithm)]


def plan(termination, t=1, n_eval=100, elapsed=0.0, per_iteration=100.0, plans=None):
    return planned_iterations(termination, t=t, n_eval=n_eval, elapsed=elapsed,
                              per_iteration=per_iteration, plans={} if plans is None else plans)


def test_planned_iterations_of_each_criterion():
    assert plan(MaximumGenerationTermination(50)) == 49  # the first is initialization
    assert plan(MaximumFunctionCallTermination(25_000), per_iteration=200.0) == 125
    assert plan(MaximumFunctionCallTermination(600), n_eval=100, per_iteration=100.0) == 5
    assert plan(TimeBasedTermination(2.0), t=10, elapsed=0.5) == 40
    assert plan(TimeBasedTermination(2.0), t=10, elapsed=0.0) == np.inf  # not measured yet
    assert plan(MultiObjectiveSpaceTermination()) == np.inf  # a tolerance bounds nothing
    both = [MaximumGenerationTermination(50), MaximumFunctionCallTermination(2100)]
    assert plan(TerminateIfAny(*both)) == 20 and plan(TerminateIfAll(*both)) == 49
    assert plan(RobustTermination(MaximumGenerationTermination(30))) == 29
    assert plan(DefaultMultiObjectiveTermination(n_max_gen=70)) == 69  # min with 100,000 evals
    assert plan(MaximumGenerationTermination(5), t=9) == 9  # always at least t


def test_an_n_eval_plan_is_made_once_per_criterion():
    plans, crit = {}, MaximumFunctionCallTermination(1000)
    assert plan(crit, t=1, n_eval=100, plans=plans) == 9  # 100 initial + 9 x 100
    assert plan(crit, t=3, n_eval=500, plans=plans) == 9  # the rate varied: same plan
    assert plan(MaximumFunctionCallTermination(1000), t=3, n_eval=500, plans=plans) == 7


@pytest.mark.parametrize("name", MOIK_MO)
def test_t_over_T_spans_an_n_gen_and_an_n_eval_budget(name):
    seen = []
    res = minimize(get_problem("zdt1", n_var=5), entry(name).cls(pop_size=10), ("n_gen", 8),
                   seed=0, callback=lambda a: seen.append((a.t, a.max_iter)))
    assert res.algorithm.max_iter == 7 and [s[0] for s in seen] == list(range(8))
    assert seen[-1] == (7, 7)  # t / T reaches 1 on the last iteration
    seen.clear()
    minimize(get_problem("zdt1", n_var=5), entry(name).cls(pop_size=10), ("n_eval", 2000),
             seed=0, callback=lambda a: seen.append((a.t, a.max_iter)))
    t, T = seen[-1]
    assert all(s[0] <= s[1] for s in seen) and t / T > 0.7


def test_time_budget_drives_the_schedule():
    seen = []
    minimize(get_problem("zdt1", n_var=5), MOEOSMA(pop_size=10), ("time", 0.5), seed=0,
             callback=lambda a: seen.append((a.t, a.max_iter)))
    assert all(t <= T for t, T in seen) and len(seen) > 20
    assert seen[-1][0] / seen[-1][1] > 0.5  # the schedule reached the end of the budget
    assert len({T for _, T in seen}) > 2  # re-planned as the time is spent


def test_default_termination_and_a_fixed_max_iter():
    alg = MOEOSMA(pop_size=10, max_iter=33)
    res = minimize(get_problem("zdt1", n_var=5), alg, ("n_gen", 5), seed=0)
    assert res.algorithm.max_iter == 33
    with pytest.warns(ToleranceTerminationWarning, match="MOGWO"):  # said to the user
        res = minimize(get_problem("zdt1", n_var=5), MOGWO(pop_size=10),
                       DefaultMultiObjectiveTermination(n_max_gen=12), seed=0)
    assert res.algorithm.max_iter == 11


@pytest.mark.parametrize("cls", [MOEOSMA, MOALO, MOPSO])
def test_checkpoint_resumed_with_a_new_termination_plans_the_new_budget(cls):
    problem = get_problem("zdt2", n_var=5)
    first = minimize(problem, cls(pop_size=10), ("n_gen", 10), seed=3, copy_algorithm=False)
    alg = copy.deepcopy(first.algorithm)  # a checkpoint, as pymoo's docs make one
    alg.termination = MaximumGenerationTermination(25)
    seen = []
    alg.callback = lambda a: seen.append((a.t, a.max_iter))
    res = minimize(problem, alg)
    assert [T for _, T in seen] == [24] * 15  # generations 11 .. 25: t = 10 .. 24
    assert [t for t, _ in seen] == list(range(10, 25))
    alg = copy.deepcopy(first.algorithm)
    alg.termination = MaximumFunctionCallTermination(first.algorithm.evaluator.n_eval + 900)
    res = minimize(problem, alg)
    assert res.algorithm.evaluator.n_eval == first.algorithm.evaluator.n_eval + 900
    assert res.algorithm.t <= res.algorithm.max_iter


@pytest.mark.parametrize("cls", [MOEOSMA, MOPSO])
def test_a_copy_resumed_with_the_same_budget_is_the_straight_run(cls):
    problem = get_problem("zdt1", n_var=5)
    straight = minimize(problem, cls(pop_size=10), ("n_eval", 1500), seed=5)
    alg = cls(pop_size=10)
    alg.setup(problem, termination=("n_eval", 1500), seed=5)
    for _ in range(6):
        alg.next()
    res = minimize(problem, copy.deepcopy(alg))
    np.testing.assert_array_equal(res.F, straight.F)
