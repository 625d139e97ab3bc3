"""The one array-state base: one schedule rule and one evaluation path for both halves
(moik.algorithms.array_base; the MO specifics are in tests/algorithms/moo/test_schedule.py)."""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest
from pymoo.constraints.as_obj import ConstraintsAsObjective
from pymoo.constraints.as_penalty import ConstraintsAsPenalty
from pymoo.core.evaluator import Evaluator
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.termination.max_gen import MaximumGenerationTermination
from pymoo.util.archive import SingleObjectiveArchive

from moik.algorithms import EO, MOEOSMA, PSO, ChOA
from moik.algorithms.array_base import ArrayStateAlgorithm
from moik.algorithms.incumbent import BestSoFar, ParetoIncumbent
from moik.exceptions import ParameterError

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


class _Counting(Evaluator):
    def __init__(self):
        super().__init__()
        self.rows = 0

    def _eval(self, problem, pop, evaluate_values_of, **kwargs):
        self.rows += len(pop)
        super()._eval(problem, pop, evaluate_values_of, **kwargs)


class _NeedsAlgorithm(Problem):
    def __init__(self, n_obj):
        super().__init__(n_var=3, n_obj=n_obj, xl=-1.0, xu=1.0, requires_kwargs=True)
        self.seen = 0

    def _evaluate(self, X, out, *args, algorithm=None, **kwargs):
        assert algorithm is not None
        self.seen += len(X)
        out["F"] = np.stack([((X - k) ** 2).sum(axis=1) for k in range(self.n_obj)], axis=1)


@pytest.mark.parametrize(("cls", "problem"), HALVES)
def test_an_attached_evaluator_sees_every_batch_and_gives_the_same_run(cls, problem):
    plain = minimize(_problem(problem), cls(pop_size=10), ("n_eval", 500), seed=2)
    res = minimize(_problem(problem), cls(pop_size=10, evaluator=_Counting()), ("n_eval", 500),
                   seed=2, copy_algorithm=False)
    ev = res.algorithm.evaluator
    assert ev.rows == ev.n_eval == 500
    np.testing.assert_array_equal(res.F, plain.F)
    calls: list[int] = []
    res = minimize(_problem(problem), cls(pop_size=10, evaluator=Evaluator(
        callback=lambda pop: calls.append(len(pop)))), ("n_eval", 500), seed=2,
        copy_algorithm=False)
    assert sum(calls) == 500
    np.testing.assert_array_equal(res.F, plain.F)


@pytest.mark.parametrize(("cls", "n_obj"), [(PSO, 1), (EO, 1), (MOEOSMA, 2)])
def test_requires_kwargs_problems_receive_the_algorithm(cls, n_obj):
    problem = _NeedsAlgorithm(n_obj)
    res = minimize(problem, cls(pop_size=10), ("n_eval", 300), seed=0, copy_algorithm=False)
    assert problem.seen == res.algorithm.evaluator.n_eval == 300


@pytest.mark.parametrize("cls", [PSO, EO, ChOA])
def test_the_archive_option_holds_every_batch(cls):
    res = minimize(get_problem("sphere", n_var=4),
                   cls(pop_size=10, archive=SingleObjectiveArchive()), ("n_eval", 300), seed=0)
    first = res.algorithm.incumbent.history_f[0]  # the best of the initial population
    assert res.F[0] < first  # the run improved on it, and the archive saw that batch
    assert res.archive.get("F").min() == res.F[0]


@pytest.mark.parametrize("wrap", [ConstraintsAsPenalty, ConstraintsAsObjective])
def test_pymoo_constraint_wrappers_run(wrap):
    make = (lambda: PSO(pop_size=20)) if wrap is ConstraintsAsPenalty else \
        (lambda: MOEOSMA(pop_size=20))
    res = minimize(wrap(get_problem("g1")), make(), ("n_gen", 5), seed=1)
    assert res.F is not None and np.isfinite(res.F).all()


@pytest.mark.parametrize(("cls", "problem"), HALVES)
def test_the_default_termination_is_the_algorithms_own_schedule(cls, problem):
    res = minimize(_problem(problem), cls(pop_size=10, max_iter=40), seed=1)
    explicit = minimize(_problem(problem), cls(pop_size=10, max_iter=40), ("n_gen", 41), seed=1)
    assert res.algorithm.t == res.algorithm.max_iter == 40  # t / T reached 1
    np.testing.assert_array_equal(res.F, explicit.F)
    alg = cls(pop_size=10)
    alg.setup(_problem(problem), seed=1)
    assert alg.termination.n_max_gen == 1000 and alg.max_iter == 999  # pymoo's count
    res = minimize(_problem(problem), cls(pop_size=10), seed=1)
    assert res.algorithm.n_gen == 1001  # as pymoo's own algorithms end under their default


@pytest.mark.parametrize("termination", [("n_gen", 0), ("n_gen", -3), ("n_eval", 0)])
@pytest.mark.parametrize(("cls", "problem"), HALVES)
def test_a_limit_below_one_is_a_clear_error(cls, problem, termination):
    with pytest.raises(ParameterError, match=f"an '{termination[0]}' termination needs a limit"):
        minimize(_problem(problem), cls(pop_size=10), termination, seed=1)


def test_n_received_counts_the_evaluations_under_every_driver():
    """minimize(): equal to evaluator.n_eval; ask/tell with an outside Evaluator (which
    leaves algorithm.evaluator at 0): the rows told."""
    from pymoo.problems import get_problem

    from moik.algorithms import get_algorithm

    problem = get_problem("sphere", n_var=4)
    res = minimize(problem, get_algorithm("pso", pop_size=10), ("n_eval", 95), seed=1)
    assert res.algorithm.n_received == res.algorithm.evaluator.n_eval == 95
    algorithm = get_algorithm("pso", pop_size=10)
    algorithm.setup(problem, termination=("n_gen", 4), seed=1)
    told = 0
    while algorithm.has_next():
        pop = algorithm.ask()
        Evaluator().eval(problem, pop)
        algorithm.tell(infills=pop)
        told += len(pop)
    assert algorithm.n_received == told and algorithm.evaluator.n_eval == 0
