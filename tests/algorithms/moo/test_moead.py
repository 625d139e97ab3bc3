"""moik's MOEA/D (moik.algorithms.moo.moead): directions, seeds, budget, quality, checkpoints,
ask/tell, constraints."""

import copy
import pickle

import numpy as np
import pytest
from pymoo.core.evaluator import Evaluator
from pymoo.core.population import Population
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOEAD, get_algorithm
from moik.exceptions import ParameterError, ShapeError


def test_registered_as_moead_and_default_directions():
    assert type(get_algorithm("moead")) is MOEAD
    res = minimize(get_problem("zdt1", n_var=5), MOEAD(pop_size=30), ("n_gen", 3), seed=0)
    assert res.algorithm.ref_dirs.shape == (30, 2) and res.algorithm.neighbors.shape == (30, 20)
    assert np.array_equal(res.algorithm.neighbors[:, 0], np.arange(30))  # itself first
    res = minimize(get_problem("dtlz2", n_obj=3), MOEAD(), ("n_gen", 2), seed=0)
    assert res.algorithm.ref_dirs.shape == (91, 3)  # C(12 + 2, 2) = 91 <= 100


@pytest.mark.parametrize(("params", "error", "message"), [
    ({"pop_size": 1}, ParameterError, "pop_size must be an integer >= 2"),
    ({"n_neighbors": 1}, ParameterError, "n_neighbors must be an integer >= 2"),
    ({"delta": 1.5}, ParameterError, r"delta must be a number in \[0.0, 1.0\]"),
    ({"nr": 0}, ParameterError, "nr must be an integer >= 1"),
    ({"eta_c": 0}, ParameterError, "eta_c must be a positive"),
    ({"ref_dirs": [[0.5, -0.5], [1.0, 0.0]]}, ParameterError, "non-negative weights"),
    ({"n_neighbours": 5}, ParameterError, r"unknown parameter\(s\) n_neighbours"),
    ({"batch": "yes"}, ParameterError, "batch must be"),
])
def test_bad_options_are_refused(params, error, message):
    with pytest.raises(error, match=message):
        MOEAD(**params)


def test_directions_of_the_wrong_width_are_refused_at_setup():
    with pytest.raises(ShapeError, match="ref_dirs must have 2 columns"):
        minimize(get_problem("zdt1", n_var=5), MOEAD(ref_dirs=np.full((4, 3), 1 / 3)),
                 ("n_gen", 2), seed=0)


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_reproducible_exact_budget_front(check, problem_name):
    check.mo_reproducible_front(lambda: MOEAD(pop_size=20), check.mo_problem(problem_name),
                                n_eval=1111, seed=4)


def test_zdt1_hypervolume_near_nsga2(check):
    """Measured at seeds 0-2: 0.96-0.99 of NSGA-II's (pymoo's MOEA/D: 0.99); the quality
    comparison with pymoo's MOEA/D is studies/moead_vs_pymoo.py."""
    ours = check.zdt1_hypervolume(lambda: MOEAD(pop_size=50), n_var=10, n_eval=5000)
    nsga2 = check.nsga2_zdt1_hypervolume(n_var=10, n_eval=5000, pop_size=50)
    assert ours > 0.9 * nsga2, (ours, nsga2)


class _Plain(Problem):
    """An IK problem behind a plain pymoo Problem: no compiled writer, so MOEA/D's loop
    runs through the base's evaluation, one row per batch."""

    def __init__(self, inner):
        super().__init__(n_var=inner.n_var, n_obj=inner.n_obj, xl=inner.xl, xu=inner.xu)
        self.inner = inner

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = self.inner.evaluate(X)


def test_the_compiled_loop_equals_the_generic_one(check):
    """The fast path (an IK problem's compiled writer) and the base's evaluation give the
    same run bit for bit, at a budget that ends inside a generation."""
    ik = check.mo_problem("ik")
    fast = minimize(ik, MOEAD(pop_size=20), ("n_eval", 517), seed=3)
    slow = minimize(_Plain(ik), MOEAD(pop_size=20), ("n_eval", 517), seed=3)
    assert fast.algorithm.evaluator.n_eval == slow.algorithm.evaluator.n_eval == 517
    np.testing.assert_array_equal(fast.algorithm.X, slow.algorithm.X)
    np.testing.assert_array_equal(fast.F, slow.F)
    assert fast.algorithm.n_replaced == slow.algorithm.n_replaced


def test_a_generation_asks_for_one_row_at_a_time():
    """Zhang & Li's loop (and pymoo's MOEAD): each offspring is evaluated and applied before
    the next subproblem mates, so a generation asks for one row at a time."""
    algorithm = MOEAD(pop_size=20)
    algorithm.setup(get_problem("zdt1", n_var=6), termination=("n_gen", 10), seed=2)
    algorithm.tell(infills=_evaluated(algorithm.ask(), algorithm.problem))  # initial population
    sizes = []
    for _ in range(40):
        pop = algorithm.ask()
        sizes.append(len(pop))
        algorithm.tell(infills=_evaluated(pop, algorithm.problem))
    assert set(sizes) == {1} and algorithm.n_received == 20 + 40


def _evaluated(pop, problem):
    return Evaluator().eval(problem, pop)


@pytest.mark.parametrize("problem_name", ["zdt1", "ik"])
def test_batch_generations_ask_once_and_are_reproducible(check, problem_name):
    """batch=True: one batch of N offspring per generation (made from the population at the
    generation's start); seeded, exact budget."""
    algorithm = MOEAD(pop_size=20, batch=True)
    algorithm.setup(get_problem("zdt1", n_var=6), termination=("n_gen", 10), seed=2)
    algorithm.tell(infills=_evaluated(algorithm.ask(), algorithm.problem))
    assert [len(_tell(algorithm)) for _ in range(3)] == [20, 20, 20]
    check.mo_reproducible_front(lambda: MOEAD(pop_size=20, batch=True),
                                check.mo_problem(problem_name), n_eval=1111, seed=4)


def _tell(algorithm):
    pop = algorithm.ask()
    algorithm.tell(infills=_evaluated(pop, algorithm.problem))
    return pop


def test_replacement_limit_nr():
    res = minimize(get_problem("zdt1", n_var=5), MOEAD(pop_size=20, nr=1), ("n_gen", 5), seed=1)
    assert 0 < res.algorithm.n_replaced <= 20
    free = minimize(get_problem("zdt1", n_var=5), MOEAD(pop_size=20), ("n_gen", 5), seed=1)
    assert free.algorithm.n_replaced > res.algorithm.n_replaced


@pytest.mark.parametrize("clone", [copy.deepcopy, lambda a: pickle.loads(pickle.dumps(a))])
def test_checkpoint_mid_run_resumes_the_same_run(clone):
    """pymoo's checkpoint pattern (deepcopy/pickle after a few ``next()``): pymoo's own
    MOEA/D holds a generator there and cannot be copied (issue 26)."""
    algorithm = MOEAD(pop_size=20)
    algorithm.setup(get_problem("zdt1", n_var=6), termination=("n_gen", 12), seed=5)
    for _ in range(4):
        algorithm.next()
    resumed = clone(algorithm)
    for a in (algorithm, resumed):
        while a.has_next():
            a.next()
    np.testing.assert_array_equal(resumed.result().F, algorithm.result().F)


def test_ask_returns_a_population_and_ask_tell_matches_minimize(check):
    algorithm = MOEAD(pop_size=20)
    algorithm.setup(get_problem("zdt1", n_var=6), termination=("n_eval", 400), seed=2)
    assert isinstance(algorithm.ask(), Population)
    check.ask_tell_matches_minimize(lambda: MOEAD(pop_size=20), get_problem("zdt1", n_var=6),
                                    ("n_eval", 400), seed=2)


class _ShiftedFront(Problem):
    """f = (x1, 1 - sqrt(x1) + x2); feasible only for x1 >= 0.4."""

    def __init__(self):
        super().__init__(n_var=3, n_obj=2, n_ieq_constr=1, xl=0.0, xu=1.0)
        self.seen_F, self.seen_G = [], []

    def _evaluate(self, X, out, *args, **kwargs):
        F = np.column_stack([X[:, 0], 1.0 - np.sqrt(X[:, 0]) + X[:, 1:].sum(axis=1)])
        G = 0.4 - X[:, :1]
        self.seen_F.append(F)
        self.seen_G.append(G)
        out["F"], out["G"] = F, G


def test_constraints_the_reference_point_is_the_best_feasible_value():
    problem = _ShiftedFront()
    res = minimize(problem, MOEAD(pop_size=20), ("n_eval", 1000), seed=1)
    F, G = np.vstack(problem.seen_F), np.vstack(problem.seen_G)[:, 0]
    np.testing.assert_array_equal(res.algorithm.z, F[G <= 0.0].min(axis=0))
    assert res.algorithm.z[0] >= 0.4 > F[:, 0].min()
    assert np.all(res.algorithm.CV <= 0.0)  # feasible members replaced the infeasible ones
    assert np.all(problem.evaluate(res.X, return_values_of=["G"]) <= 0.0)
