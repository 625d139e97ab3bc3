"""TaskPool: per-item work in processes forked through a lead, beside the caller's threads."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

from moik.exceptions import MoikError
from moik.solver import task_pool
from moik.solver.task_pool import TaskPool

pytestmark = pytest.mark.skipif(not task_pool.can_fork(), reason="TaskPool forks")


def _square_plus(shared, item):
    return item * item + shared, os.getpid(), os.getppid()


def _fail_on_three(shared, item):
    if item == 3:
        raise ValueError("item three")
    return item + shared


def _unpicklable(shared, item):
    return lambda: item


def _slow(shared, item):
    time.sleep(shared)
    return os.getpid()


def _ended(pid: int, within: float = 10.0) -> bool:
    """Whether process ``pid`` is gone (or a zombie) within ``within`` seconds."""
    t_end = time.monotonic() + within
    while time.monotonic() < t_end:
        try:
            with open(f"/proc/{pid}/status") as f:
                if any(line.startswith("State:") and "Z" in line for line in f):
                    return True
        except FileNotFoundError:
            return True
        time.sleep(0.05)
    return False


def test_items_as_they_come_each_answered_once_by_the_leads_workers():
    with TaskPool(_square_plus, 1, 2, 10) as pool:
        pool.submit([4, 2])
        pool.submit([])
        pool.submit(np.array([7]))  # numpy integers too
        out = pool.results()
        lead = pool._lead.pid
    assert {k: v for k, (v, _, _) in out.items()} == {4: 17, 2: 5, 7: 50}
    # the caller forked one process, the lead; the workers are the lead's
    assert all(pid not in (os.getpid(), lead) and parent == lead
               for _, pid, parent in out.values())


def test_the_first_error_of_an_item_is_raised_and_the_lead_ends():
    with pytest.raises(ValueError, match="item three"), \
            TaskPool(_fail_on_three, 0, 2, 10) as pool:
        lead = pool._lead
        pool.submit([1, 3])
        pool.results()
    assert lead.exitcode is not None  # ended with the interrupted pool, not left behind


def test_a_result_that_cannot_travel_is_an_error_not_a_hang():
    with pytest.raises(MoikError, match="could not be sent back"), \
            TaskPool(_unpicklable, 0, 2, 10) as pool:
        pool.submit([1])
        pool.results()


def test_a_lead_that_dies_is_an_error_not_a_hang():
    with pytest.raises(MoikError, match="1 of 1 results still to come"), \
            TaskPool(_slow, 30.0, 1, 1) as pool:
        pool.submit([0])
        time.sleep(0.5)
        os.kill(pool._lead.pid, signal.SIGTERM)
        pool.results()


def _die_on_one(shared, item):
    if item == 1:
        os.kill(os.getpid(), signal.SIGKILL)
    return item


def test_a_worker_that_dies_is_an_error_not_a_hang():
    """Before: a multiprocessing.Pool replaced a dead worker and left its item unanswered
    (the caller waited for ever)."""
    with pytest.raises(MoikError, match="died .killed by signal 9"), \
            TaskPool(_die_on_one, 0, 2, 4) as pool:
        pool.submit([0, 1, 2])
        pool.results()


def test_the_caller_does_not_wait_for_the_lead_to_end_its_pool():
    with TaskPool(_slow, 0.0, 2, 4) as pool:
        pool.submit(range(4))
        workers = set(pool.results().values())
        lead = pool._lead
    lead.join(10.0)
    assert lead.exitcode == 0
    assert all(_ended(pid) for pid in workers)


def test_an_interrupted_caller_ends_the_lead_and_its_workers():
    with pytest.raises(KeyboardInterrupt), TaskPool(_slow, 0.0, 2, 4) as pool:
        pool.submit([0, 1])
        workers = set(pool.results().values())
        pool.submit([2])
        raise KeyboardInterrupt
    assert pool._lead.exitcode is not None
    assert all(_ended(pid) for pid in workers)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="PR_SET_PDEATHSIG")
def test_workers_die_with_a_lead_killed_outright():
    """Before: a lead killed while it forked (SIGTERM before the new worker was listed)
    left that worker waiting for ever on the task lock of killed siblings, holding the
    caller's output open (a test run that never ended)."""
    with pytest.raises(MoikError, match="results still to come"), \
            TaskPool(_slow, 0.3, 2, 4) as pool:
        pool.submit([0, 1])
        workers = set(pool.results().values())
        pool.submit([2, 3])
        os.kill(pool._lead.pid, signal.SIGKILL)
        pool.results()
    assert all(_ended(pid) for pid in workers)


def test_a_lead_whose_caller_dies_ends_with_its_workers():
    """The lead reads the caller's end of the task pipe as closed and ends its pool."""
    code = textwrap.dedent("""
        import os, sys, time
        from moik.solver.task_pool import TaskPool
        def _slow(shared, item):  # forked: the function is not pickled
            time.sleep(shared)
            return os.getpid()
        pool = TaskPool(_slow, 0.3, 2, 4)
        pool.submit([0, 1])
        workers = sorted(set(pool.results().values()))
        print(pool._lead.pid, *workers, flush=True)
        os._exit(3)  # no __exit__, no atexit: as if killed
    """)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 3, out.stderr
    pids = [int(p) for p in out.stdout.split()]
    assert len(pids) >= 2 and all(_ended(pid) for pid in pids)  # the lead, its workers


def test_no_more_processes_than_cpus_or_items(monkeypatch):
    monkeypatch.setattr(task_pool, "available_cores", lambda: 3)
    assert task_pool.process_count(10**20, 50) == 3
    assert task_pool.process_count(10**20, 2) == 2
    assert task_pool.process_count(2, 50) == 2
    assert task_pool.process_count(4, 0) == 1
    with TaskPool(_square_plus, 1, 10**20, 10) as pool:
        assert pool.processes == 3
        pool.submit(range(5))
        assert {k: v for k, (v, _, _) in pool.results().items()} == {
            i: i * i + 1 for i in range(5)}
