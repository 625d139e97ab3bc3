"""Executors: a process pool and a local Dask cluster give the serial results."""

import pytest

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
