"""The compiled start streams against numpy's SeedSequence + PCG64 + Generator.random."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.solver import start_streams as start_streams_module
from moik.solver.options import STARTS_KEY
from moik.solver.start_streams import (
    draw_rows,
    numpy_state,
    seed_state,
    start_streams,
    streams,
    streams_match,
    uint32_words,
)

entropy = st.one_of(st.integers(0, 2**200), st.lists(st.integers(0, 2**40), min_size=1,
                                                      max_size=9))
spawn = st.lists(st.integers(0, 2**40), max_size=3)


@settings(max_examples=60, deadline=None)
@given(entropy, spawn, st.integers(4, 9), st.integers(0, 2**32 - 1), st.integers(1, 5),
       st.integers(1, 4))
def test_streams_equal_numpy_generators(ent, key, pool, stream_key, k, dof):
    root = np.random.SeedSequence(ent, spawn_key=key, pool_size=pool)
    n = 4
    states = streams(root, stream_key, n)
    lower, upper = -np.arange(1.0, dof + 1), np.linspace(0.5, 3.0, dof)
    first = draw_rows(states, np.arange(n), k, lower, upper)
    then = draw_rows(states, np.array([1, 3]), k + 1, lower, upper)  # the streams go on
    for i in range(n):
        seq = np.random.SeedSequence(ent, spawn_key=(*key, i, stream_key), pool_size=pool)
        g = np.random.Generator(np.random.PCG64(seq))
        assert np.array_equal(first[i], lower + (upper - lower) * g.random((k, dof)))
        if i in (1, 3):
            assert np.array_equal(then[(i - 1) // 2],
                                  lower + (upper - lower) * g.random((k + 1, dof)))


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 2**130), st.sampled_from([STARTS_KEY, 0, 1, 2**32 - 1, 2**33 + 5]))
def test_seed_state_equals_numpy_pcg64(seed, key):
    """solve_ik's starts generator seeded in compiled code, bit for bit as numpy seeds it."""
    expected = np.random.PCG64(np.random.SeedSequence(seed, spawn_key=(key,))).state
    assert seed_state(seed, key) == expected


def test_seeding_equals_numpy_and_is_checked():
    root = np.random.SeedSequence(12345, spawn_key=(7,))
    states = start_streams(root, STARTS_KEY, 3)
    for i in range(3):
        assert np.array_equal(states[i], numpy_state(root, STARTS_KEY, i))


def test_a_compiled_stream_that_differs_from_numpy_is_replaced_by_numpy(monkeypatch):
    root = np.random.SeedSequence(99, spawn_key=(3,))
    expected = np.array([numpy_state(root, STARTS_KEY, 5 + i) for i in range(4)])
    assert streams_match(root, STARTS_KEY, 5)
    assert np.array_equal(start_streams(root, STARTS_KEY, 4, 5, checked=True), expected)
    monkeypatch.setattr(start_streams_module, "batch_streams",  # should numpy ever seed otherwise
                        lambda base, spawn, rows, states: states.fill(1))
    assert not streams_match(root, STARTS_KEY, 5)
    for checked in (None, False):  # checked here, or by the caller once for its chunks
        assert np.array_equal(start_streams(root, STARTS_KEY, 4, 5, checked=checked), expected)


def test_uint32_words_as_numpy():
    from numpy.random.bit_generator import _coerce_to_uint32_array  # the reference
    for x in (0, 1, 2**32 - 1, 2**32, 2**100 + 3, [5, 2**33, 0], (), [0]):
        assert uint32_words(x) == [int(w) for w in _coerce_to_uint32_array(x)]
