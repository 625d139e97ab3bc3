"""Registry: names, parameter errors, and properties every registered algorithm keeps."""

import numpy as np
import pytest
from pymoo.algorithms.soo.nonconvex.de import DE
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import EOSMA, available, get_algorithm, register, registry
from moik.algorithms.registry import accepted_parameters
from moik.exceptions import ParameterError, UnknownNameError

NAMES = ["de", "eo", "eosma", "ga", "m-pso", "pso", "pymoo-de", "sma"]
NAMES += ["mrfo", "mpa", "pfa", "fpa", "gbo", "tlbo"]  # issue 7, first half
NAMES += ["hho", "igwo", "psogsa", "code", "mtde", "sass"]  # issue 7, second half
NAMES += ["bes", "ibes", "fa", "mtsa", "cpso-at", "choa", "cchoa", "oichoa", "ochoa",
          "wchoa", "mchoa", "ssa", "csa", "jaya"]  # issue 8
OURS = ["eo", "eosma", "m-pso", "pso", "sma"]
OURS += ["hho", "igwo", "code", "mtde", "sass"]  # PSOGSA: Rastrigin ~17


class Sphere(Problem):
    def __init__(self):
        super().__init__(n_var=7, n_obj=1, xl=-10.0, xu=10.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = (X * X).sum(axis=1)


def test_available_names():
    assert set(NAMES) <= set(available())
    assert available() == sorted(available())
    assert isinstance(get_algorithm("EOSMA"), EOSMA)


def test_unknown_name_lists_valid_names():
    with pytest.raises(UnknownNameError,
                       match="unknown algorithm 'nsga9'; expected one of: (bes, )?.*de, "):
        get_algorithm("nsga9")


def test_unknown_keyword_names_accepted_ones():
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) zz .*accepted: .*a1"):
        get_algorithm("eosma", zz=1)
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) bogus .*accepted: .*CR"):
        get_algorithm("pymoo-de", bogus=1)
    assert {"pop_size", "q", "z", "seed", "verbose"} <= set(accepted_parameters("eosma"))


@pytest.mark.parametrize(("name", "params", "message"), [
    ("eosma", {"z": 1.5}, r"z must be a number in \[0.0, 1.0\]"),
    ("eosma", {"q": -1}, r"q must be a number in \[0.0, 1.0\]"),
    ("eosma", {"a1": 0}, r"a1 must be a number in \(0.0, 10.0\]"),
    ("eo", {"GP": 2}, r"GP must be a number in \[0.0, 1.0\]"),
    ("eo", {"V": 0}, r"V must be a number in \(0.0, inf\)"),
    ("sma", {"z": "a"}, r"z must be a number"),
    ("pso", {"w": -0.1}, r"w must be a number in \[0.0, 1.5\]"),
    ("m-pso", {"c1": 5}, r"c1 must be a number in \[0.0, 4.0\]"),
    ("m-pso", {"switch": "median"}, r"switch must be one of mean-position, mean-fitness"),
    ("pso", {"vmax_rate": 0}, r"vmax_rate must be a number in \(0.0, 1.0\]"),
    ("pso", {"pop_size": 1}, r"pop_size must be an integer >= 2"),
    ("pymoo-de", {"pop_size": 0}, r"pop_size must be a positive integer"),
    ("de", {"pop_size": 3}, r"pop_size must be an integer >= 4"),
])
def test_bad_values_raise_parameter_error(name, params, message):
    with pytest.raises(ParameterError, match=message):
        get_algorithm(name, **params)


def test_scenarios():
    s1, s2 = EOSMA.scenario(1), EOSMA.scenario(2)
    assert (s1.pop_size, s1.q, s1.a1, s1.a2, s1.z) == (50, 0.0, 1.0, 2.0, 0.5)
    assert (s2.pop_size, s2.q, s2.a1) == (100, 1.0, 2.0)
    assert EOSMA.scenario(1, pop_size=20).pop_size == 20
    with pytest.raises(ParameterError, match="scenario must be 1 or 2"):
        EOSMA.scenario(3)


def test_register_decorator_and_conflict(monkeypatch):
    monkeypatch.setattr(registry, "_REGISTRY", dict(registry._REGISTRY))

    @register("my-de")
    class MyDE(DE):
        pass

    assert "my-de" in available() and isinstance(get_algorithm("my-de"), MyDE)
    with pytest.raises(ParameterError, match="already registered"):
        register("pso", MyDE)


@pytest.mark.parametrize("name", NAMES)
def test_same_seed_bit_identical_in_bounds_global_state_untouched(name):
    problem = Sphere()
    state = np.random.get_state()  # noqa: NPY002
    runs = [minimize(problem, get_algorithm(name, pop_size=20), ("n_gen", 30), seed=11)
            for _ in range(2)]
    after = np.random.get_state()  # noqa: NPY002
    assert state[0] == after[0] and np.array_equal(state[1], after[1]) and state[2:] == after[2:]
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    np.testing.assert_array_equal(runs[0].F, runs[1].F)
    other = minimize(problem, get_algorithm(name, pop_size=20), ("n_gen", 30), seed=12)
    assert not np.array_equal(other.X, runs[0].X)
    X = runs[0].pop.get("X")
    assert np.all((X >= -10) & (X <= 10)) and np.all(np.abs(runs[0].X) <= 10)


@pytest.mark.parametrize("name", NAMES)
def test_n_eval_stops_within_one_population(name):
    res = minimize(Sphere(), get_algorithm(name, pop_size=30), ("n_eval", 1000), seed=0)
    assert 1000 <= res.algorithm.evaluator.n_eval < 1000 + 30


@pytest.mark.parametrize("name", OURS + ["de"])
def test_sphere_below_1e_8_within_100k_evaluations(name):
    res = minimize(Sphere(), get_algorithm(name, pop_size=100), ("n_eval", 100_000), seed=1)
    assert res.F[0] < 1e-8


def test_ga_sphere_honest_level():
    """pymoo's GA (SBX + polynomial mutation, defaults) has no elitist drift toward 1e-8:
    with 100,000 evaluations it reaches about 3e-7 here, so this asserts < 1e-5."""
    res = minimize(Sphere(), get_algorithm("ga", pop_size=100), ("n_eval", 100_000), seed=1)
    assert res.F[0] < 1e-5


@pytest.mark.parametrize("name", OURS)
def test_runs_on_pymoo_rastrigin(name):
    problem = get_problem("rastrigin", n_var=7)
    res = minimize(problem, get_algorithm(name, pop_size=50), ("n_eval", 20_000), seed=1)
    conv = res.algorithm.convergence
    assert np.isfinite(res.F[0]) and res.F[0] < 5.0 and res.F[0] < conv[0]
    assert np.all(np.abs(res.X) <= 5.0)
