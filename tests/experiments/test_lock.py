"""The run lock of a results folder: one live run at a time, stale locks taken over."""

import json
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

import moik
from moik.exceptions import ResultsError
from moik.experiments.lock import LOCK_NAME, LockHolder, RunLock, process_start
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore

ROOT = Path(moik.__file__).resolve().parents[1]

HOLD = """
import sys, time
from moik.experiments.lock import RunLock
lock = RunLock.acquire(sys.argv[1])
print("locked", flush=True)
time.sleep(60)
"""


def _dead_pid() -> int:
    """The PID of a process that has exited (and been reaped)."""
    proc = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True)
    return int(proc.stdout)


def _write_lock(folder: Path, **fields) -> Path:
    info = {"pid": os.getpid(), "host": socket.gethostname(), "started": "earlier",
            "process_start": process_start(os.getpid())} | fields
    path = folder / LOCK_NAME
    path.write_text(json.dumps(info))
    return path


def test_acquire_release_and_a_second_acquire_is_refused(tmp_path):
    lock = RunLock.acquire(tmp_path)
    info = json.loads((tmp_path / LOCK_NAME).read_text())
    assert info["pid"] == os.getpid() and info["host"] == socket.gethostname()
    assert lock.replaced is None
    with pytest.raises(ResultsError, match=rf"in use by another run: PID {os.getpid()} .*"
                                           r"\(this process\)"):
        RunLock.acquire(tmp_path)
    lock.release()
    assert not (tmp_path / LOCK_NAME).exists()
    with RunLock.acquire(tmp_path):
        assert (tmp_path / LOCK_NAME).exists()
    assert not (tmp_path / LOCK_NAME).exists()


def test_release_leaves_a_lock_that_is_not_its_own(tmp_path):
    lock = RunLock.acquire(tmp_path)
    (tmp_path / LOCK_NAME).write_text('{"pid": 1, "host": "other", "started": "now"}')
    lock.release()
    assert (tmp_path / LOCK_NAME).exists()


def test_a_live_run_in_another_process_is_refused_then_its_stale_lock_taken_over(
        tmp_path, tiny_config):
    out = tmp_path / "r"
    out.mkdir()
    holder = subprocess.Popen([sys.executable, "-c", HOLD, str(out)], cwd=ROOT,
                              stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "locked"
        for resume in (False, True):
            with pytest.raises(ResultsError, match=f"PID {holder.pid} on host"):
                run_experiment(tiny_config, out=out, resume=resume)
        assert sorted(p.name for p in out.iterdir()) == [LOCK_NAME]  # nothing touched
    finally:
        holder.kill()
        holder.wait()
    s = run_experiment(tiny_config, out=out)  # the holder crashed: its lock is stale
    assert s.ran == 8
    assert any(f"stale run lock: PID {holder.pid}" in n and "gone" in n for n in s.notes)
    assert not (out / LOCK_NAME).exists()  # released at the end of the run


def test_stale_locks_are_taken_over(tmp_path):
    dead = _write_lock(tmp_path, pid=_dead_pid())
    lock = RunLock.acquire(tmp_path)
    assert "a process that is gone" in lock.replaced
    lock.release()
    if process_start(os.getpid()) is not None:  # /proc: a reused PID is seen through
        _write_lock(tmp_path, process_start="1")
        with RunLock.acquire(tmp_path) as lock:
            assert f"PID {os.getpid()}" in lock.replaced
    dead.write_text("")  # torn by a crash while being written
    old = time.time() - 60
    os.utime(dead, (old, old))
    with RunLock.acquire(tmp_path) as lock:
        assert lock.replaced == "an unreadable lock file"


def test_a_lock_of_another_host_is_never_taken_over(tmp_path):
    path = _write_lock(tmp_path, host="elsewhere", pid=_dead_pid())
    assert LockHolder(pid=1, host="elsewhere", started="x").is_alive()
    with pytest.raises(ResultsError, match=rf"host 'elsewhere'.*delete '{path}'"):
        RunLock.acquire(tmp_path)


def test_a_store_holds_the_lock_until_closed(tmp_path, tiny_config):
    store = ResultStore.create(tmp_path / "r", config=tiny_config, targets=[], trials=[],
                               resume=False, session={})
    with pytest.raises(ResultsError, match="in use by another run"):
        ResultStore.create(tmp_path / "r", config=tiny_config, targets=[], trials=[],
                           resume=True, session={})
    store.close()
    ResultStore.create(tmp_path / "r", config=tiny_config, targets=[], trials=[],
                       resume=True, session={}).close()


@pytest.mark.parametrize("content", [b"[" * 100_000 + b"]" * 100_000,
                                     b'{"pid": ' + b"9" * 400 + b', "host": "h", "started": "s"}',
                                     b'{"pid": -5, "host": "h", "started": "s"}', b"\xff\xfe"])
def test_a_hostile_lock_file_is_an_unreadable_one(tmp_path, content):
    """Before: RecursionError (deep nesting) or OverflowError (os.kill of a 400-digit pid)."""
    (tmp_path / "run.lock").write_bytes(content)
    lock = RunLock.acquire(tmp_path)
    assert lock.replaced == "an unreadable lock file"
    lock.release()
