"""pymoo 0.6.2's own algorithm tests and documented workflows, run on every registered algorithm.

Each check is a pymoo test or documentation example with only the algorithm changed
(``get_algorithm(name)`` with its defaults); the source is named in each docstring
(``tests/...`` and ``docs/source/...`` of github.com/anyoptimization/pymoo at tag 0.6.2).
Single-objective algorithms run the single-objective problems of those tests, multi-objective
ones ZDT1 with 5 variables (the problems of the docs' examples). A refusal would be fine only
where pymoo's own algorithms refuse too, with a clear ``MoikError``; none is expected here.
Runs are short (a few generations) to keep the suite cheap.
"""

from __future__ import annotations

import pickle

import dill
import numpy as np
import pytest
from pymoo.core.callback import Callback
from pymoo.core.evaluator import Evaluator
from pymoo.core.population import Population
from pymoo.core.problem import ElementwiseProblem, Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from pymoo.problems.static import StaticProblem
from pymoo.termination import get_termination
from pymoo.termination.max_gen import MaximumGenerationTermination
from pymoo.util.display.column import Column
from pymoo.util.display.output import Output

from moik.algorithms import available, entry, get_algorithm, is_multi_objective
from moik.algorithms.array_base import ArrayStateAlgorithm

NAMES = available()

# Cases that fail today, each with what was measured; strict: a case that starts to pass
# fails the run until its entry is removed (issue 26 keeps them open).
KNOWN_FAILURES = {
    ("sphere-default", name): "quality, the method at its paper defaults: ends at 3e-3 to 1e-2 "
    "on pymoo's sphere within its own 1,000-iteration schedule, pymoo's test wants 1e-5 "
    "(MChOA and the other algorithms reach it); the method's, not moik's: the port of the "
    "authors' chimp.m (reference/choa.py) ends at the same order on the same problem "
    "(python -m studies.choa_reference)" for name in ("choa", "cchoa", "ochoa", "wchoa")}
KNOWN_FAILURES[("sphere-default", "fa")] = (
    "quality at the I-BES paper's settings (beta0 = 2, a constant alpha = 0.2): ends near 1e-2 "
    "on pymoo's sphere, pymoo's test wants 1e-5; with the settings of Yang's code (beta0 = 1, "
    "alpha damped by 0.97 per iteration) the same implementation reaches 1e-28 "
    "(test_fa.py::test_yangs_settings_converge_on_pymoos_sphere): the settings', not a bug")
KNOWN_FAILURES.update({
    ("ask-tell", "moead-pymoo"): "pymoo 0.6.2's own MOEA/D: ask() returns one Individual "
    "(moik's moead passes)",
    ("checkpoint-dill", "moead-pymoo"): "pymoo 0.6.2's own MOEA/D holds a generator: dill "
    "cannot serialise it mid-run (moik's moead passes)",
})


def cases(test: str, names) -> list:
    """``names`` as pytest params, the known failures of ``test`` marked strict xfail."""
    return [pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=KNOWN_FAILURES[test, n]))
            if (test, n) in KNOWN_FAILURES else n for n in names]
N_GEN = 5


def problem_for(name: str) -> Problem:
    """ZDT1 (5 variables) for multi-objective algorithms, the 10-D sphere otherwise."""
    return get_problem("zdt1", n_var=5) if is_multi_objective(name) else get_problem("sphere")


class NoFeasible(Problem):
    """tests/algorithms/test_algorithms.py::test_no_feasible_solution_found's problem (G = 1),
    with a second objective for multi-objective algorithms."""

    def __init__(self, n_obj: int):
        super().__init__(n_var=2, n_obj=n_obj, n_ieq_constr=1, xl=[0, 0], xu=[100, 100])

    def _evaluate(self, x, out, *args, **kwargs):
        f1 = x[:, 0] + x[:, 1]
        out["F"] = np.column_stack([f1] if self.n_obj == 1 else [f1, x[:, 0]])
        out["G"] = np.ones(len(x))


class Elementwise(ElementwiseProblem):
    """tests/algorithms/test_algorithms.py::test_thread_pool's problem (elementwise)."""

    def __init__(self, n_obj: int):
        super().__init__(n_var=2, n_obj=n_obj, xl=np.array([0, 0]), xu=np.array([100, 100]))

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = [x[0] + x[1]] if self.n_obj == 1 else [x[0] + x[1], 100 - x[0]]


class SphereWithConstraints(Problem):
    """tests/algorithms/test_single_objective.py's constrained sphere (optimum 0.1)."""

    def __init__(self, n_var=10):
        super().__init__(n_var=n_var, n_obj=1, n_ieq_constr=1, xl=-0, xu=1, vtype=float)

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = np.sum(np.square(x - 0.5), axis=1)
        out["G"] = 0.1 - out["F"]


def _n_obj(name: str) -> int:
    return 2 if is_multi_objective(name) else 1


# ---- tests/algorithms/test_algorithms.py ------------------------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_same_seed_same_result(name):
    """test_algorithms.py::test_same_seed_same_result: one algorithm object, two minimize calls
    (minimize copies it), the global numpy seed changed in between."""
    problem, algorithm = problem_for(name), get_algorithm(name)
    res1 = minimize(problem, algorithm, ("n_gen", N_GEN), seed=1)
    np.random.seed(200)  # noqa: NPY002 (pymoo's test: the global state must not matter)
    res2 = minimize(problem, algorithm, ("n_gen", N_GEN), seed=1)
    np.testing.assert_almost_equal(res1.X, res2.X)
    np.testing.assert_almost_equal(res1.F, res2.F)


@pytest.mark.parametrize("name", NAMES)
def test_no_pareto_front_given(name, capsys):
    """test_algorithms.py::test_no_pareto_front_given: verbose=True on a problem that knows no
    Pareto front (pymoo's ZDT1 without ``_calc_pareto_front``)."""
    if is_multi_objective(name):
        class NoFront(Problem):
            def __init__(self):
                super().__init__(n_var=5, n_obj=2, xl=0.0, xu=1.0)

            def _evaluate(self, x, out, *args, **kwargs):
                f1 = x[:, 0]
                g = 1 + 9.0 / (self.n_var - 1) * np.sum(x[:, 1:], axis=1)
                out["F"] = np.column_stack([f1, g * (1 - np.power((f1 / g), 0.5))])
    else:
        class NoFront(Problem):  # type: ignore[no-redef]
            def __init__(self):
                super().__init__(n_var=5, n_obj=1, xl=-1.0, xu=1.0)

            def _evaluate(self, x, out, *args, **kwargs):
                out["F"] = np.sum(x * x, axis=1)
    minimize(NoFront(), get_algorithm(name), ("n_gen", N_GEN), seed=1, verbose=True)
    assert "n_gen" in capsys.readouterr().out


@pytest.mark.parametrize("name", NAMES)
def test_no_feasible_solution_found(name):
    """test_algorithms.py::test_no_feasible_solution_found."""
    problem = NoFeasible(_n_obj(name))
    res = minimize(problem, get_algorithm(name), ("n_gen", N_GEN), seed=1)
    assert res.X is None and res.F is None and res.G is None
    res = minimize(problem, get_algorithm(name), ("n_gen", N_GEN), seed=1, verbose=True,
                   return_least_infeasible=True, save_history=True)
    assert np.atleast_1d(res.CV)[0] == 1.0


@pytest.mark.parametrize("name", NAMES)
def test_elementwise_problem(name):
    """test_algorithms.py::test_thread_pool (an ElementwiseProblem, evaluated row by row)."""
    res = minimize(Elementwise(_n_obj(name)), get_algorithm(name), ("n_gen", N_GEN), seed=1)
    assert res.F is not None and np.isfinite(res.F).all()


@pytest.mark.parametrize("name", cases("loop-vs-infill", NAMES))
def test_min_vs_loop_vs_infill(name):
    """test_algorithms.py::test_min_vs_loop_vs_infill: minimize, a next() loop and an
    infill()/Evaluator().eval/advance loop give the same X."""
    problem, termination = problem_for(name), ("n_gen", N_GEN)
    min_res = minimize(problem, get_algorithm(name), termination, seed=1)
    algorithm = get_algorithm(name)
    algorithm.setup(problem, termination=termination, seed=1)
    while algorithm.has_next():
        algorithm.next()
    algorithm.finalize()
    np.testing.assert_allclose(min_res.X, algorithm.result().X)
    algorithm = get_algorithm(name)
    algorithm.setup(problem, termination=termination, seed=1)
    while algorithm.has_next():
        infills = algorithm.infill()
        Evaluator().eval(problem, infills)
        algorithm.advance(infills=infills)
    algorithm.finalize()
    np.testing.assert_allclose(min_res.X, algorithm.result().X)


# ---- tests/algorithms/test_deterministic_{soo,moo}.py -----------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_deterministic_and_seeds_differ(name):
    """test_deterministic_moo.py / test_deterministic_soo.py: two fresh instances with seed 42
    agree; seeds 1, 42 and 123 do not all give the same F."""
    problem = problem_for(name)
    runs = [minimize(problem, get_algorithm(name), ("n_gen", N_GEN), seed=s)
            for s in (42, 42, 1, 123)]
    np.testing.assert_allclose(runs[0].F, runs[1].F, rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(runs[0].X, runs[1].X, rtol=1e-6, atol=1e-6)
    Fs = [np.atleast_2d(r.F) for r in runs[1:]]
    assert any(a.shape != b.shape or not np.array_equal(a, b) for a in Fs for b in Fs)


# ---- tests/algorithms/test_single_objective.py ------------------------------------------------
@pytest.mark.parametrize("name", cases("sphere-default", available("single-objective")))
def test_sphere_with_default_termination(name):
    """test_single_objective.py::test_sphere (seed 2 of its 2-4): pymoo's default termination,
    the 10-D sphere to 5 decimals."""
    problem = get_problem("sphere")
    res = minimize(problem, get_algorithm(name), seed=2)
    np.testing.assert_almost_equal(res.F[0], problem.pareto_front()[0, 0], decimal=5)


@pytest.mark.parametrize("name", available("single-objective"))
def test_sphere_with_constraints(name):
    """test_single_objective.py::test_sphere_with_constraints (default termination, optimum
    0.1 on the constraint's boundary, 4 decimals)."""
    res = minimize(SphereWithConstraints(), get_algorithm(name), seed=1)
    np.testing.assert_almost_equal(res.F[0], 0.1, decimal=4)


# ---- docs/source/interface/callback.md, display.md, result.md, termination.md -----------------
class _Collect(Callback):
    """docs/source/interface/callback.md's callback (the best F of each generation)."""

    def __init__(self) -> None:
        super().__init__()
        self.data["best"] = []

    def notify(self, algorithm):
        self.data["best"].append(algorithm.pop.get("F").min())


@pytest.mark.parametrize("name", NAMES)
def test_callback(name):
    """callback.md: a Callback sees every generation's population."""
    callback = _Collect()
    res = minimize(problem_for(name), get_algorithm(name), ("n_gen", N_GEN), seed=1,
                   callback=callback)
    best = res.algorithm.callback.data["best"]
    assert len(best) == N_GEN and np.isfinite(best).all()


class _MyOutput(Output):
    """docs/source/interface/display.md's output (mean and std of X)."""

    def __init__(self):
        super().__init__()
        self.x_mean = Column("x_mean", width=13)
        self.x_std = Column("x_std", width=13)
        self.columns += [self.x_mean, self.x_std]

    def update(self, algorithm):
        super().update(algorithm)
        self.x_mean.set(np.mean(algorithm.pop.get("X")))
        self.x_std.set(np.std(algorithm.pop.get("X")))


@pytest.mark.parametrize("name", NAMES)
def test_display(name, capsys):
    """display.md: a custom Output prints its columns every generation."""
    minimize(problem_for(name), get_algorithm(name), ("n_gen", N_GEN), seed=1,
             output=_MyOutput(), verbose=True)
    lines = capsys.readouterr().out.splitlines()
    assert "x_mean" in lines[1] and sum("|" in line for line in lines) >= N_GEN + 1


@pytest.mark.parametrize("name", NAMES)
def test_result_and_history(name):
    """result.md: res.X/F/CV/G, exec_time, algorithm, pop and history (save_history=True)."""
    problem = problem_for(name)
    res = minimize(problem, get_algorithm(name), ("n_gen", N_GEN), seed=1, save_history=True)
    assert res.X is not None and res.F is not None and res.exec_time > 0.0
    assert len(res.history) == N_GEN and res.algorithm.n_gen == N_GEN + 1
    assert isinstance(res.pop, Population) and len(res.pop) >= 1
    F = problem.evaluate(np.atleast_2d(res.X), return_values_of=["F"])
    np.testing.assert_allclose(np.atleast_2d(res.F), F)


@pytest.mark.parametrize("name", NAMES)
def test_termination(name):
    """termination.md: ``get_termination("n_eval", k)`` and ``("n_gen", k)``."""
    problem = problem_for(name)
    res = minimize(problem, get_algorithm(name), get_termination("n_eval", 500), seed=1)
    assert 500 <= res.algorithm.evaluator.n_eval < 500 + 200
    res = minimize(problem, get_algorithm(name), get_termination("n_gen", 3), seed=1,
                   save_history=True)
    assert len(res.history) == 3


# ---- docs/source/misc/checkpoint.md -----------------------------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_checkpoint_resume_with_new_termination(name):
    """checkpoint.md, first example: minimize(copy_algorithm=False, verbose=True) for 5
    generations, dill, a new MaximumGenerationTermination(20), minimize again."""
    problem, algorithm = problem_for(name), get_algorithm(name)
    minimize(problem, algorithm, ("n_gen", 5), seed=1, copy_algorithm=False, verbose=True)
    checkpoint = dill.loads(dill.dumps(algorithm))
    checkpoint.termination = MaximumGenerationTermination(20)
    res = minimize(problem, checkpoint, seed=1, copy_algorithm=False, verbose=True)
    assert res.algorithm.n_gen == 21 and res.F is not None


ARRAY_STATE = [n for n in NAMES if issubclass(entry(n).cls, ArrayStateAlgorithm)]


@pytest.mark.parametrize(("name", "module"), [
    *(pytest.param(n, dill, marks=pytest.mark.xfail(
        strict=True, reason=KNOWN_FAILURES["checkpoint-dill", n]))
      if ("checkpoint-dill", n) in KNOWN_FAILURES else (n, dill) for n in NAMES),
    *((n, pickle) for n in ARRAY_STATE)])
def test_checkpoint_mid_run_gives_the_same_run(name, module):
    """checkpoint.md, second example (setup, next() 5 times, serialize, continue), with
    verbose=True as its first example; the resumed run equals the uninterrupted one. The docs
    use dill; plain pickle too for moik's array-state algorithms (pymoo's own GA cannot be
    pickled after verbose=True: its random-state decorator holds a local function)."""
    problem = problem_for(name)
    algorithm = get_algorithm(name)
    algorithm.setup(problem, seed=1, termination=("n_gen", 12), verbose=True)
    for _ in range(5):
        algorithm.next()
    checkpoint = module.loads(module.dumps(algorithm))
    for a in (algorithm, checkpoint):
        while a.has_next():
            a.next()
    np.testing.assert_array_equal(checkpoint.result().F, algorithm.result().F)


# ---- docs/source/algorithms/usage (ask and tell) ----------------------------------------------
@pytest.mark.parametrize("name", cases("ask-tell", NAMES))
def test_ask_and_tell_with_a_static_problem(name):
    """The docs' ask-and-tell interface: ask() gives a Population, evaluated outside the
    algorithm (StaticProblem + Evaluator), told back; minimize's run."""
    problem = problem_for(name)
    ref = minimize(problem, get_algorithm(name), ("n_gen", N_GEN), seed=1)
    algorithm = get_algorithm(name)
    algorithm.setup(problem, termination=("n_gen", N_GEN), seed=1)
    while algorithm.has_next():
        pop = algorithm.ask()
        assert isinstance(pop, Population)
        F = problem.evaluate(pop.get("X"), return_values_of=["F"])
        Evaluator().eval(StaticProblem(problem, F=F), pop)
        algorithm.tell(infills=pop)
    np.testing.assert_allclose(algorithm.result().X, ref.X)


# ---- docs/source/customization/initialization.md, operators/sampling.md ------------------------
@pytest.mark.parametrize("form", ["array", "population"])
@pytest.mark.parametrize("name", NAMES)
def test_initial_population_through_sampling(name, form):
    """initialization.md: ``sampling=`` an array of points or an evaluated Population starts
    the run from them (the first generation holds them)."""
    problem = problem_for(name)
    n = get_algorithm(name).pop_size  # as the docs: one row per member of the population
    X = np.random.default_rng(0).uniform(problem.xl, problem.xu, (n, problem.n_var))
    sampling = X if form == "array" else Population.new("X", X)
    res = minimize(problem, get_algorithm(name, sampling=sampling), ("n_gen", 2), seed=1,
                   save_history=True)
    first = res.history[0].pop.get("X") if res.history[0].pop is not None else None
    assert first is not None
    assert any(np.array_equal(row, x) for x in X for row in first)


# ---- docs/source/constraints/index.md -----------------------------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_constrained_problem(name):
    """constraints/index.md: inequality constraints ``G <= 0``; the result is feasible."""
    problem = get_problem("bnh") if is_multi_objective(name) else SphereWithConstraints()
    res = minimize(problem, get_algorithm(name), ("n_gen", 20), seed=1)
    assert res.X is not None
    G = problem.evaluate(np.atleast_2d(res.X), return_values_of=["G"])
    assert np.all(G <= 0.0)
