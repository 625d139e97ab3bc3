"""The one array-state base: one schedule rule and one evaluation path for both halves
(moik.algorithms.array_base; the MO specifics are in tests/algorithms/moo/test_schedule.py)."""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.termination.max_gen import MaximumGenerationTermination

from moik.algorithms import EO, MOEOSMA, PSO, ChOA
from moik.algorithms.array_base import ArrayStateAlgorithm
from moik.algorithms.incumbent import BestSoFar, ParetoIncumbent

HALVES = [(ChOA, "sphere"), (EO, "sphere"), (MOEOSMA, "zdt1")]


def _problem(name):
    return get_problem(name, n_var=5)


@pytest.mark.parametrize(("cls", "problem"), HALVES)
def test_both_halves_share_one_base_and_compose_their_incumbent(cls, problem):
    res = minimize(_problem(problem), cls(pop_size=10), ("n_gen", 3), seed=0)
    assert isinstance(res.algorithm, ArrayStateAlgorithm)
    expected = ParetoIncumbent if problem == "zdt1" else BestSoFar
    assert isinstance(res.algorithm.incumbent, expected)


@pytest.mark.parametrize(("cls", "problem"), HALVES)
def test_a_time_budget_is_planned_the_same_way_in_both_halves(cls, problem):
    seen = []
    minimize(_problem(problem), cls(pop_size=10), ("time", 0.4), seed=0,
             callback=lambda a: seen.append((a.t, a.max_iter)))
    assert all(t <= T for t, T in seen) and len(seen) > 10
    assert len({T for _, T in seen}) > 2  # re-planned as the time is spent
    assert seen[-1][0] / seen[-1][1] > 0.5  # the schedule reached the end of the budget


@pytest.mark.parametrize(("cls", "problem"), HALVES)
def test_a_resumed_checkpoint_plans_its_new_termination_in_both_halves(cls, problem):
    first = minimize(_problem(problem), cls(pop_size=10), ("n_gen", 10), seed=3,
                     copy_algorithm=False)
    alg = copy.deepcopy(first.algorithm)
    alg.termination = MaximumGenerationTermination(25)
    seen = []
    alg.callback = lambda a: seen.append((a.t, a.max_iter))
    minimize(_problem(problem), alg)
    assert [T for _, T in seen] == [24] * 15 and [t for t, _ in seen] == list(range(10, 25))


@pytest.mark.parametrize(("cls", "problem"), HALVES + [(PSO, "sphere")])
def test_a_verbose_run_pickles_and_resumes_identically(cls, problem, capsys):
    alg = cls(pop_size=10, verbose=True)
    alg.setup(_problem(problem), termination=("n_gen", 8), seed=4)
    for _ in range(4):
        alg.next()
    copy_ = pickle.loads(pickle.dumps(alg))
    while alg.has_next():
        alg.next()
    while copy_.has_next():
        copy_.next()
    np.testing.assert_array_equal(alg.result().F, copy_.result().F)
    capsys.readouterr()
