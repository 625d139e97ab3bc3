"""SearchOptions: solve_ik's options validated and normalised together."""

import numpy as np
import pytest

from moik.exceptions import ParameterError, UnknownNameError
from moik.solver.options import SearchOptions, seed_sequence, start_generator

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
    """Bit for bit ``Generator(PCG64(SeedSequence(seed)))``, reset on every call."""
    for _ in range(2):
        got = start_generator(seed).random(16)
        want = np.random.Generator(np.random.PCG64(np.random.SeedSequence(seed))).random(16)
        assert np.array_equal(got, want)
