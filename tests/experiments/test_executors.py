"""Executors: a process pool and a local Dask cluster give the serial results."""

import pytest
import tomli_w

from moik.exceptions import ParameterError
from moik.experiments import executors
from moik.experiments.executors import Progress, run_dask
from moik.experiments.runner import check_workers, run_experiment
from moik.experiments.store import ResultStore
from moik.experiments.trials import build_trials

from .conftest import stable


def _results(folder):
    return sorted((stable(r) for r in ResultStore.open(folder).records()),
                  key=lambda r: r["trial"])


def _no_worker(records):
    return [{k: v for k, v in r.items() if k != "worker"} for r in records]


def test_pool_of_two_equals_serial(tmp_path, tiny_config):
    run_experiment(tiny_config, out=tmp_path / "serial", workers=1)
    run_experiment(tiny_config, out=tmp_path / "pool", workers=2)
    serial, pool = _results(tmp_path / "serial"), _results(tmp_path / "pool")
    assert serial == pool and len(serial) == 8
    assert ResultStore.open(tmp_path / "pool").meta["sessions"][0]["executor"] == "pool:2"


def test_local_dask_cluster_equals_serial(tmp_path, tiny_config):
    distributed = pytest.importorskip("distributed")
    run_experiment(tiny_config, out=tmp_path / "serial")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster:
        s = run_experiment(tiny_config, out=tmp_path / "dask",
                           dask_scheduler=cluster.scheduler_address)
    assert s.ran == 8 and s.failed == 0
    assert _results(tmp_path / "serial") == _results(tmp_path / "dask")


def test_unreachable_scheduler_is_a_clear_error():
    pytest.importorskip("distributed")
    with pytest.raises(ParameterError, match="cannot connect to the Dask scheduler"):
        list(run_dask([], "tcp://127.0.0.1:1", timeout=1))


def test_workers_are_validated():
    assert check_workers(None) >= 1
    with pytest.raises(ParameterError, match="workers must be an integer >= 1"):
        check_workers(0)


def test_progress_fallback_line(capsys):
    bar = Progress(total=4, done=2, label="x", enabled=True)
    bar._bar = None
    for ok in (True, False, True, True):
        bar.update(ok)
    err = capsys.readouterr().err
    assert "x (+2 resumed): 4/4 trials, 1 failed" in err


def test_each_process_warms_each_algorithm_up_before_timing_it(monkeypatch, tiny_config):
    """The first trial of an algorithm and problem in a process is preceded by an untimed
    one-iteration run of it (so its time excludes the kernel load); later trials are not."""
    calls = []
    monkeypatch.setattr(executors, "run_trial", lambda spec: calls.append(spec) or ({}, {}))
    monkeypatch.setattr(executors, "_WARMED", set())
    specs = [s for s in build_trials(tiny_config) if s.target_index == 0]
    eosma = [s for s in specs if s.label == "eosma"]
    for spec in (*eosma, *specs):
        executors.warm_trial(spec)
    iterations = [(c.label, c.iterations) for c in calls]
    assert iterations[:2] == [("eosma", 1), ("eosma", tiny_config["iterations"])]
    assert iterations.count(("eosma", 1)) == 1 and iterations.count(("pso", 1)) == 1
    assert len(calls) == len(eosma) + len(specs) + 2


# --- signals and orphaned workers (issue 27 item 6) ---

def test_sigterm_raises_terminated_inside_and_is_restored_after():
    import os
    import signal

    from moik.experiments.executors import Terminated, sigterm_as_interrupt
    before = signal.getsignal(signal.SIGTERM)
    with pytest.raises(KeyboardInterrupt) as info, sigterm_as_interrupt():
        os.kill(os.getpid(), signal.SIGTERM)
        for _ in range(1000):  # the handler runs at the next bytecode
            pass
    assert isinstance(info.value, Terminated)
    assert signal.getsignal(signal.SIGTERM) is before


def _slow_run(tmp_path, tiny, workers: int):
    """`moik experiment run` of a config whose trials take a while, started in a subprocess
    and returned once its first trial is stored (with the folder and the workers' pids)."""
    import copy
    import os
    import subprocess
    import sys
    import time
    from pathlib import Path

    if not Path("/proc/self/stat").exists():
        pytest.skip("needs /proc to find the pool's workers")
    config = copy.deepcopy(tiny)
    config.update(name="tiny-slow", iterations=4000, runs=4)
    path = tmp_path / "tiny_slow.toml"
    path.write_text(tomli_w.dumps(config))
    out = tmp_path / "r"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    proc = subprocess.Popen([sys.executable, "-m", "moik", "experiment", "run", "--config",
                             str(path), "--out", str(out), "--workers", str(workers),
                             "--no-progress"], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 300
    while not ((out / "results.jsonl").exists() and (out / "results.jsonl").stat().st_size):
        if proc.poll() is not None or time.monotonic() > deadline:
            proc.kill()
            pytest.fail(f"the run did not store a trial: {proc.communicate()}")
        time.sleep(0.2)
    kids = [int(p.name) for p in Path("/proc").iterdir() if p.name.isdigit()
            and _ppid(p) == proc.pid]
    return proc, out, kids


def _ppid(proc_dir):
    try:
        return int((proc_dir / "stat").read_text().rsplit(")", 1)[1].split()[1])
    except (OSError, IndexError, ValueError):
        return None


def _running(pids):
    from pathlib import Path
    alive = []
    for pid in pids:
        try:
            state = (Path("/proc") / str(pid) / "stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if state != "Z":  # a zombie has stopped; its reaper may be slow
            alive.append(pid)
    return alive


def _wait_gone(pids, seconds: float):
    import time
    deadline = time.monotonic() + seconds
    while _running(pids) and time.monotonic() < deadline:
        time.sleep(0.05)
    return _running(pids)


def test_sigterm_is_handled_like_ctrl_c(tmp_path, tiny):
    """Before: no message, run.lock left behind, the session end not recorded."""
    import json
    import signal
    proc, out, kids = _slow_run(tmp_path, tiny, workers=2)
    assert len(kids) == 2
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert "moik: interrupted; finished trials are stored in" in err and "--resume" in err
    assert "Traceback" not in err
    assert not (out / "run.lock").exists()
    session = json.loads((out / "meta.json").read_text())["sessions"][-1]
    assert session["finished"] and session["trials_run"] >= 1
    assert _wait_gone(kids, 10) == []


def test_the_workers_of_a_killed_run_stop_at_once(tmp_path, tiny):
    """Before: after SIGKILL of the parent its workers computed on for seconds (16.6 s
    measured on a bigger run) and printed BrokenPipeError tracebacks."""
    import signal
    proc, out, kids = _slow_run(tmp_path, tiny, workers=2)
    assert len(kids) == 2
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    assert _wait_gone(kids, 2.0) == []
    _, err = proc.communicate(timeout=30)
    assert "BrokenPipeError" not in err and "Traceback" not in err
