"""The parallel machinery: chunks, threads over chunks, a process pool, the client check."""

import os
import time

import numpy as np
import pytest

from moik.exceptions import ParameterError
from moik.solver import parallel, task_pool


def test_chunks_cover_the_range_once_in_order():
    for n in (1, 31, 32, 33, 100, 1000, 12345):
        for workers in (1, 2, 3, 16):
            bounds = parallel.chunk_bounds(n, workers)
            assert bounds[0][0] == 0 and bounds[-1][1] == n
            assert all(a[1] == b[0] for a, b in zip(bounds, bounds[1:], strict=False))
            assert all(hi > lo for lo, hi in bounds)
            if workers == 1 or n <= parallel.MIN_CHUNK:
                assert bounds == [(0, n)]
            else:
                sizes = [hi - lo for lo, hi in bounds]
                assert min(sizes) >= parallel.MIN_CHUNK
                # guided: each takes its share of the rows left (the last: the remainder too)
                left = n - np.concatenate([[0], np.cumsum(sizes)])[:-1]
                share = np.maximum(parallel.MIN_CHUNK,
                                   np.ceil(left / (parallel.GUIDE * workers)))
                assert (sizes[:-1] == share[:-1]).all()
                assert share[-1] <= sizes[-1] < share[-1] + parallel.MIN_CHUNK


def test_guided_chunks_shrink_to_the_end():
    sizes = [hi - lo for lo, hi in parallel.chunk_bounds(48000, 16)]
    assert sizes[0] == 48000 // (parallel.GUIDE * 16)
    assert sizes[:-1] == sorted(sizes[:-1], reverse=True)
    assert sizes[-2] == parallel.MIN_CHUNK


def test_then_runs_here_as_each_chunk_ends():
    """``then`` runs in the calling thread once per chunk, after the chunk, and ``busy``
    says whether chunks are still running."""
    import threading

    here, out, seen = threading.get_ident(), np.zeros(1000), []

    def fill(lo, hi):
        time.sleep(0.01 * (lo > 0))
        out[lo:hi] = 1.0

    def then(lo, hi, busy):
        assert threading.get_ident() == here and (out[lo:hi] == 1.0).all()
        seen.append(((lo, hi), busy()))

    parallel.map_chunks(fill, 1000, 2, then=then)
    assert sorted(b for b, _ in seen) == parallel.chunk_bounds(1000, 2)
    assert seen[-1][1] is False  # none left running after the last
    assert seen[0][0] == (0, parallel.chunk_bounds(1000, 2)[0][1]) and seen[0][1] is True
    seen.clear()
    parallel.map_chunks(fill, 100, 2, then=then)  # one chunk: here, nothing else running
    assert seen == [((0, 100), False)]


def test_then_is_not_called_after_a_chunk_failed():
    calls = []

    def fail(lo, hi):
        raise ValueError(f"chunk {lo}")

    with pytest.raises(ValueError, match="chunk 0"):
        parallel.map_chunks(fail, 1000, 2, then=lambda lo, hi, busy: calls.append(lo))
    assert calls == []


def test_threads_write_their_chunks():
    out = np.zeros(1000)

    def fill(lo, hi):
        out[lo:hi] = np.arange(lo, hi) * 2.0

    parallel.map_chunks(fill, 1000, 3)
    np.testing.assert_array_equal(out, np.arange(1000) * 2.0)


def test_a_chunks_error_is_raised():
    def fail(lo, hi):
        if lo > 0:
            raise ValueError(f"chunk {lo}")

    with pytest.raises(ValueError, match="chunk"):
        parallel.map_chunks(fail, 500, 2)


def _square_plus(shared, item):
    return item * item + shared, os.getpid()


def test_process_pool_keeps_the_order_and_runs_elsewhere(monkeypatch):
    monkeypatch.setattr(parallel, "POOL_AFTER_S", 0.0)  # no item runs here first
    items = [5, 3, 9, 1, 7]
    out = parallel.map_processes(_square_plus, 10, items, 2)
    assert [v for v, _ in out] == [i * i + 10 for i in items]
    assert all(pid != os.getpid() for _, pid in out)


def _slow_first(shared, item):
    if item == 0:
        time.sleep(shared)
    return item, os.getpid()


def test_a_tail_that_ends_soon_needs_no_pool_a_long_one_gets_one(monkeypatch):
    out = parallel.map_processes(_square_plus, 0, list(range(6)), 2)  # quick: all here
    assert all(pid == os.getpid() for _, pid in out)
    monkeypatch.setattr(parallel, "POOL_AFTER_S", 0.05)
    out = parallel.map_processes(_slow_first, 0.1, list(range(6)), 2)  # item 0 runs long
    assert [v for v, _ in out] == list(range(6))
    assert out[0][1] == os.getpid() and all(pid != os.getpid() for _, pid in out[1:])


def _steady(shared, item):
    time.sleep(shared)
    return item, os.getpid()


def test_a_tail_of_slow_items_gets_a_pool_after_its_first(monkeypatch):
    """At the first item's pace the 7 left would take 0.35 s here, more than a pool's start
    (0.1 s x 2 / 1): the pool takes them at once, long before POOL_AFTER_S; a tail of quick
    items at the same count stays here."""
    monkeypatch.setattr(parallel, "POOL_AFTER_S", 10.0)
    out = parallel.map_processes(_steady, 0.05, list(range(8)), 2)
    assert [v for v, _ in out] == list(range(8))
    assert out[0][1] == os.getpid() and all(pid != os.getpid() for _, pid in out[1:])
    out = parallel.map_processes(_steady, 0.001, list(range(8)), 2)
    assert all(pid == os.getpid() for _, pid in out)


def test_a_process_pool_never_exceeds_the_cpus_or_the_items(monkeypatch):
    """Before: a collision-aware batch with workers=1000 asked for Pool(processes=1000)
    (`moik batch --workers 99999999999999999999` forked that many)."""
    monkeypatch.setattr(task_pool, "available_cores", lambda: 3)
    sizes = []

    class Pool:  # records the size map_processes asks for, runs the items here
        def __init__(self, processes, initializer, initargs):
            sizes.append(processes)
            initializer(*initargs)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            return False

        def imap_unordered(self, fn, items):
            return map(fn, items)

    class Context:
        Pool = staticmethod(lambda n, initializer, initargs: Pool(n, initializer, initargs))

    monkeypatch.setattr(parallel.multiprocessing, "get_context", lambda method: Context())
    monkeypatch.setattr(parallel, "POOL_AFTER_S", -1.0)  # the pool takes every item
    out = parallel.map_processes(_square_plus, 0, list(range(8)), 10**20)
    assert [v for v, _ in out] == [i * i for i in range(8)] and sizes == [3]


def test_small_or_single_worker_pools_stay_here():
    for items, workers in (([4], 4), ([1, 2, 3], 1)):
        out = parallel.map_processes(_square_plus, 0, items, workers)
        assert [v for v, _ in out] == [i * i for i in items]
        assert all(pid == os.getpid() for _, pid in out)


def test_workers_and_client_are_validated():
    assert parallel.worker_count(None) == parallel.available_cores() >= 1
    assert parallel.worker_count(3) == 3
    for bad in (0, -1, 2.0, True, "2"):
        with pytest.raises(ParameterError, match="workers"):
            parallel.worker_count(bad)
    with pytest.raises(ParameterError, match="dask.distributed.Client"):
        parallel.check_client(object())
