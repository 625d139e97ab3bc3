"""pymoo 0.6.2's biased-initialization, constraint-handling and termination workflows, run
on every registered algorithm.

Each check is a pymoo documentation example or test with only the algorithm changed
(``get_algorithm(name)``), at a small size (population 10 to 20, a few generations); the
source is named in each docstring (``docs/source/...``, ``examples/...`` and ``tests/...``
of github.com/anyoptimization/pymoo at tag 0.6.2). Single-objective algorithms run the
single-objective problems of those examples, multi-objective ones the multi-objective ones.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from pymoo.constraints.as_obj import ConstraintsAsObjective
from pymoo.constraints.as_penalty import ConstraintsAsPenalty
from pymoo.constraints.eps import AdaptiveEpsilonConstraintHandling
from pymoo.constraints.from_bounds import ConstraintsFromBounds
from pymoo.core.evaluator import Evaluator
from pymoo.core.population import Population
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.problems.single import G1, G4
from pymoo.termination.default import (
    DefaultMultiObjectiveTermination,
    DefaultSingleObjectiveTermination,
)

from moik.algorithms import available, entry, get_algorithm, is_multi_objective
from moik.algorithms.archive import nondominated_mask
from moik.algorithms.array_base import ArrayStateAlgorithm
from moik.exceptions import ToleranceTerminationWarning

NAMES = available()
POP_SIZE = 10


# ---- docs/source/customization/initialization.ipynb (biased initialization) -------------------
def _sample(name: str):
    """initialization.ipynb's problem (ZDT2; the 10-D sphere for single-objective algorithms)
    and its sample: three times the population, uniform in the bounds."""
    problem = get_problem("zdt2", n_var=10) if is_multi_objective(name) else get_problem(
        "sphere", n_var=10)
    rng = np.random.default_rng(0)
    return problem, rng.uniform(problem.xl, problem.xu, (3 * POP_SIZE, problem.n_var))


@pytest.mark.parametrize("form", ["array", "population", "evaluated-population"])
@pytest.mark.parametrize("name", NAMES)
def test_biased_initialization_with_a_larger_sample(name, form):
    """initialization.ipynb: ``sampling=`` 300 points (here 3 x pop_size) as an array, a
    Population or an evaluated Population: every point evaluated once (the evaluated ones not
    again), every point offered to the result (the best of all is in the first generation's
    result), and the run goes on with the algorithm's population."""
    problem, X = _sample(name)
    sampling = X if form == "array" else Population.new("X", X)
    if form == "evaluated-population":
        Evaluator().eval(problem, sampling)
    algorithm = get_algorithm(name, pop_size=POP_SIZE, sampling=sampling)
    first = minimize(problem, algorithm, ("n_gen", 1), seed=1)
    expected = 0 if form == "evaluated-population" else len(X)
    if name == "mopso-cd":  # pymoo's MOPSO_CD evaluates its first swarm in _setup as well
        expected *= 2
    assert first.algorithm.evaluator.n_eval == expected
    F = problem.evaluate(X, return_values_of=["F"])
    if is_multi_objective(name):
        front = F[nondominated_mask(F)]
        assert len(front) <= POP_SIZE  # (the archives keep pop_size members)
        for f in front:  # every non-dominated point of the sample is reported
            assert np.any(np.all(np.isclose(np.atleast_2d(first.F), f), axis=1)), name
    else:
        assert float(np.atleast_1d(first.F)[0]) == pytest.approx(F.min(), rel=1e-12)
    res = minimize(problem, get_algorithm(name, pop_size=POP_SIZE, sampling=sampling),
                   ("n_gen", 3), seed=1)
    assert res.F is not None and np.isfinite(res.F).all()
    if name != "pymoo-de":  # pymoo's own DE keeps every point of its sample
        assert len(res.algorithm.pop) < len(X)


@pytest.mark.parametrize("name", [n for n in NAMES if not is_multi_objective(n)
                                  and n not in ("ga", "pymoo-de")])
def test_a_larger_sample_keeps_the_best_rows(name):
    """A single-objective moik algorithm starts from the pop_size best points of the sample."""
    problem, X = _sample(name)
    res = minimize(problem, get_algorithm(name, pop_size=POP_SIZE, sampling=X), ("n_gen", 1),
                   seed=1)
    F = problem.evaluate(X, return_values_of=["F"])[:, 0]
    kept = np.sort(problem.evaluate(res.algorithm.X, return_values_of=["F"])[:, 0])
    np.testing.assert_array_equal(kept, np.sort(F)[:len(kept)])


# ---- examples/constraints/{eps,as_penalty,as_obj,from_bounds}.py ------------------------------
KNOWN_WRAPPER_FAILURES = {
    "moead-pymoo": "pymoo 0.6.2's own MOEA/D evaluates one Individual at a time; pymoo's "
    "AttachConfigEvaluator calls Population.apply on it (pymoo's MOEAD fails inside the "
    "wrapper too, earlier: its _setup is skipped); moik's moead passes",
}


def _wrapper_cases():
    return [pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=KNOWN_WRAPPER_FAILURES[n]))
            if n in KNOWN_WRAPPER_FAILURES else n for n in NAMES]


def _feasible_or_none(problem, res) -> None:
    if res.X is None:
        return
    G = problem.evaluate(np.atleast_2d(res.X), return_values_of=["G"])
    assert np.all(G <= 0.0)


@pytest.mark.parametrize("name", _wrapper_cases())
def test_adaptive_epsilon_constraint_handling(name):
    """examples/constraints/eps.py: ``AdaptiveEpsilonConstraintHandling(algorithm,
    perc_eps_until=0.5)`` on G1 (BNH for multi-objective algorithms). moik's algorithms
    keep their feasibility-first comparisons inside the wrapper (docs/algorithms.md,
    Constraints): the wrapped run is the plain run, bit for bit, and reports only feasible
    points."""
    problem = get_problem("bnh") if is_multi_objective(name) else G1()
    wrapped = AdaptiveEpsilonConstraintHandling(get_algorithm(name, pop_size=20),
                                                perc_eps_until=0.5)
    res = minimize(problem, wrapped, ("n_gen", 15), seed=1)
    assert res.algorithm.n_gen == 16
    _feasible_or_none(problem, res)
    if entry(name).cls.__module__.startswith("moik."):
        plain = minimize(problem, get_algorithm(name, pop_size=20), ("n_gen", 15), seed=1)
        for a, b in ((res.X, plain.X), (res.F, plain.F)):
            assert (a is None and b is None) or np.array_equal(a, b)


@pytest.mark.parametrize("name", [n for n in NAMES if not is_multi_objective(n)])
def test_constraints_as_penalty(name):
    """examples/constraints/as_penalty.py: G4 wrapped in ``ConstraintsAsPenalty(penalty=100)``."""
    problem = ConstraintsAsPenalty(G4(), penalty=100.0)
    res = minimize(problem, get_algorithm(name, pop_size=20), ("n_gen", 10), seed=1)
    assert res.F is not None and np.isfinite(res.F).all()


@pytest.mark.parametrize("name", [n for n in NAMES if is_multi_objective(n)])
def test_constraints_as_objective(name):
    """examples/constraints/as_obj.py: G1's violation as a second objective
    (``ConstraintsAsObjective``), solved by a multi-objective algorithm."""
    problem = ConstraintsAsObjective(G1())
    res = minimize(problem, get_algorithm(name, pop_size=20), ("n_gen", 10), seed=1)
    assert res.F is not None and np.atleast_2d(res.F).shape[1] == 2
    assert np.isfinite(res.F).all()


@pytest.mark.parametrize("name", [n for n in NAMES if not is_multi_objective(n)])
def test_constraints_from_bounds(name):
    """examples/constraints/from_bounds.py: the sphere's bounds also given as constraints
    (``ConstraintsFromBounds(remove_bonds=False)``); the result is feasible."""
    problem = ConstraintsFromBounds(get_problem("sphere"), remove_bonds=False)
    res = minimize(problem, get_algorithm(name, pop_size=20), ("n_gen", 10), seed=1)
    assert res.X is not None
    _feasible_or_none(problem, res)


# ---- docs/source/interface/termination.ipynb --------------------------------------------------
MOIK_ARRAY_STATE = [n for n in NAMES if issubclass(entry(n).cls, ArrayStateAlgorithm)]


def _small(name: str):
    return get_problem("zdt1", n_var=3) if is_multi_objective(name) else get_problem(
        "sphere", n_var=3)


@pytest.mark.parametrize("name", MOIK_ARRAY_STATE)
def test_no_termination_counts_generations_as_pymoo(name):
    """termination.ipynb, "Default Termination": without a termination pymoo's algorithms stop
    at 1000 generations at most (``n_gen`` 1001 after the run, the initial population being
    generation 1); moik's run their own schedule over the same count, to the end (no
    tolerance window)."""
    res = minimize(_small(name), get_algorithm(name, pop_size=5), seed=1)
    assert res.algorithm.n_gen == 1001
    assert res.algorithm.t == res.algorithm.max_iter == 999  # t / T reached 1


@pytest.mark.parametrize("name", MOIK_ARRAY_STATE)
def test_a_tolerance_termination_is_run_with_a_warning(name):
    """termination.ipynb: ``DefaultSingleObjectiveTermination(xtol=1e-8, cvtol=1e-6,
    ftol=1e-6, period=20, n_max_gen=..., n_max_evals=100000)`` (the multi-objective one for
    multi-objective algorithms): run as given, and the user is told that its tolerance
    window can stop the method early."""
    multi = is_multi_objective(name)
    cls = DefaultMultiObjectiveTermination if multi else DefaultSingleObjectiveTermination
    termination = cls(xtol=1e-8, cvtol=1e-6, ftol=1e-6 if not multi else 0.0025, period=20,
                      n_max_gen=8, n_max_evals=100000)
    with pytest.warns(ToleranceTerminationWarning, match="tolerance termination"):
        res = minimize(_small(name), get_algorithm(name, pop_size=5), termination, seed=1)
    assert res.algorithm.n_gen <= 9 and res.F is not None


@pytest.mark.parametrize("name", MOIK_ARRAY_STATE)
def test_budget_terminations_do_not_warn(name):
    """termination.ipynb: ``("n_gen", 5)``, ``("n_eval", 60)``, ``("time", 0.02)``."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", ToleranceTerminationWarning)
        for termination in (("n_gen", 5), ("n_eval", 60), ("time", 0.02)):
            minimize(_small(name), get_algorithm(name, pop_size=5), termination, seed=1)
