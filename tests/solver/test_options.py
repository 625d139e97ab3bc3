"""SearchOptions: solve_ik's options validated and normalised together."""

import subprocess
import sys
from dataclasses import fields

import numpy as np
import pytest

from moik.algorithms.registry import get_algorithm, is_multi_objective
from moik.exceptions import ParameterError, UnknownNameError
from moik.solver.options import (
    DEFAULT_OPTIONS,
    DEFAULT_POP_SIZES,
    SEARCH_DEFAULTS,
    STARTS_KEY,
    SearchOptions,
    seed_sequence,
    start_generator,
)

DEFAULTS = dict(method="eosma", orientation="geodesic", polish=True, n_solutions=1,
                max_evals=50_000, starts=16, pop_size=None, generations=15,
                candidates_per_round=3, distinct=0.1, patience=30, front_method="moeosma",
                front_evals=10_000)


def test_defaults_are_normalised():
    opts = SearchOptions(**DEFAULTS)
    assert opts.pop_size == 20 and opts.distinct == 0.1 and opts.orientation == "geodesic"
    assert SearchOptions(**{**DEFAULTS, "n_solutions": 3}).pop_size == 40
    assert SearchOptions(**{**DEFAULTS, "orientation": "ZYX-Euler"}).orientation == "zyx-euler"
    with pytest.raises(TypeError):
        SearchOptions("eosma")  # keyword-only


@pytest.mark.parametrize("change, error, message", [
    ({"method": "moeosma"}, ParameterError, "method must be a single-objective"),
    ({"front_method": "eosma"}, ParameterError, "front_method must be a multi-objective"),
    ({"method": "nope"}, UnknownNameError, "unknown algorithm 'nope'"),
    ({"orientation": 3}, UnknownNameError, "unknown orientation metric 3"),
    ({"pop_size": True}, ParameterError, "pop_size must be an integer >= 2, got True"),
    ({"pop_size": 2, "method": "eosma"}, ParameterError, "pop_size must be an integer >= 3"),
    ({"starts": 2.5}, ParameterError, "starts must be an integer >= 0, got 2.5"),
    ({"distinct": -1}, ParameterError, r"distinct must be a (positive )?finite number"),
])
def test_bad_values(change, error, message):
    with pytest.raises(error, match=message):
        SearchOptions(**{**DEFAULTS, **change})


def test_seed_sequence():
    assert seed_sequence(5).entropy == 5
    ss = seed_sequence(None)
    assert seed_sequence(ss) is ss
    with pytest.raises(ParameterError, match="seed must be a non-negative integer"):
        seed_sequence(True)


@pytest.mark.parametrize("seed", [0, 7, 2**40])
def test_start_generator_is_a_fresh_seeded_generator_each_time(seed):
    """Bit for bit ``Generator(PCG64(SeedSequence(seed, spawn_key=(STARTS_KEY,))))``, reset
    on every call, and not the stream of ``default_rng(seed)`` (the targets' stream)."""
    for _ in range(2):
        with start_generator(seed) as g:
            got = g.random(16)
        want = np.random.Generator(np.random.PCG64(
            np.random.SeedSequence(seed, spawn_key=(STARTS_KEY,)))).random(16)
        assert np.array_equal(got, want)
        assert not np.any(got == np.random.default_rng(seed).random(16))


def test_a_nested_start_generator_leaves_the_outer_stream_alone():
    """A stage that re-enters solve_ik gets a generator of its own."""
    want = np.random.Generator(np.random.PCG64(
        np.random.SeedSequence(3, spawn_key=(STARTS_KEY,)))).random(8)
    with start_generator(3) as outer:
        first = outer.random(4)
        with start_generator(5) as inner:
            assert inner is not outer
            inner.random(4)
        rest = outer.random(4)
    assert np.array_equal(np.concatenate([first, rest]), want)


def test_defaults_come_from_search_options():
    """One source: SEARCH_DEFAULTS are the dataclass defaults; a call that changes none
    gets the one validated instance, any other value is validated."""
    assert {f.name: f.default for f in fields(SearchOptions)} == SEARCH_DEFAULTS
    assert SearchOptions.of(**SEARCH_DEFAULTS) is DEFAULT_OPTIONS == SearchOptions()
    assert SearchOptions.of(**{**SEARCH_DEFAULTS, "n_solutions": 2}).pop_size == 40
    with pytest.raises(ParameterError, match="n_solutions must be an integer >= 1, got True"):
        SearchOptions.of(**{**SEARCH_DEFAULTS, "n_solutions": True})  # True == 1, refused


def test_default_algorithms_pass_the_registry_check():
    """The default method / front_method are not looked up in the registry at run time
    (start-up time): this is the check they would get."""
    assert not is_multi_objective(SEARCH_DEFAULTS["method"])
    assert is_multi_objective(SEARCH_DEFAULTS["front_method"])
    for pop_size in DEFAULT_POP_SIZES:
        get_algorithm(SEARCH_DEFAULTS["method"], pop_size=pop_size)


def test_a_first_stage_solve_imports_neither_the_algorithms_nor_scipy_optimize():
    """Start-up time: a pose solved by the first stage loads no metaheuristic, pymoo
    algorithm or scipy.optimize (about 0.3 s of imports)."""
    code = ("import sys, numpy as np, moik\n"
            "r = moik.solve_ik(moik.get_robot('puma560'), np.array([0.4, 0.2, 0.3]))\n"
            "assert r.success\n"
            "print([m for m in ('moik.algorithms.registry', 'scipy.optimize', "
            "'pymoo.algorithms.moo.nsga2') if m in sys.modules])\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]"


def test_public_solver_names_are_the_functions_after_any_import_order():
    """A submodule named like its function must not shadow it on the package."""
    code = ("import moik.solver.solve_ik, moik.solver.batch, moik.solver.pareto, moik.solver.path\n"
            "import moik, moik.solver\n"
            "from moik.solver import solve_ik, solve_ik_batch, solve_ik_pareto, solve_path\n"
            "assert all(callable(f) and not isinstance(f, type(moik)) for f in (solve_ik, "
            "solve_ik_batch, solve_ik_pareto, solve_path, moik.solve_ik, moik.solve_ik_batch))\n")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_counts_are_bounded_above():
    """Before: n_solutions=1000000000 was accepted and asked for 67 GiB up front."""
    with pytest.raises(ParameterError, match="n_solutions must be at most 100000, got 1000000000"):
        SearchOptions(n_solutions=1_000_000_000)
    with pytest.raises(ParameterError, match="starts must be at most"):
        SearchOptions(starts=10**9)
    with pytest.raises(ParameterError, match="pop_size must be at most"):
        SearchOptions(pop_size=10**9)
