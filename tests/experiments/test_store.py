"""Results store: atomic writes, torn lines, resume after an interruption."""

import json

import numpy as np
import pytest

import moik.experiments.runner as runner_mod
from moik.exceptions import ResultsError
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore, atomic_write_bytes


def test_atomic_write_replaces_whole_file(tmp_path):
    path = tmp_path / "f.bin"
    atomic_write_bytes(path, b"old")
    atomic_write_bytes(path, b"new content")
    assert path.read_bytes() == b"new content"
    assert [p.name for p in tmp_path.iterdir()] == ["f.bin"]  # no temporary left


def test_store_layout_and_metadata(tmp_path, tiny_config):
    s = run_experiment(tiny_config, out=tmp_path / "r")
    assert s.ran == 8 and s.failed == 0
    store = ResultStore.open(tmp_path / "r")
    meta = store.meta
    assert meta["experiment"] == "tiny-test" and meta["versions"]["pymoo"]
    assert meta["config"]["seed"] == 11 and len(meta["trials"]) == 8
    assert {"hostname", "cpu_count"} <= set(meta["machine"]) and "git_commit" in meta
    assert all("seed" in t and "spawn_key" in t for t in meta["trials"])
    recs = store.records()
    assert len(recs) == 8 and store.finished_ids() == {r["trial"] for r in recs}
    arrays = store.load_arrays(recs[0]["trial"])
    assert set(arrays) == {"convergence", "best_x"} and np.all(np.diff(arrays["convergence"]) <= 0)


def test_torn_last_line_is_ignored_and_repaired(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=3)
    with open(out / "results.jsonl", "ab") as fh:  # a crash in the middle of an append
        fh.write(b'{"trial": "pso/1/1", "sta')
    store = ResultStore.open(out)
    assert len(store.records()) == 3
    s = run_experiment(tiny_config, out=out, resume=True)
    assert s.skipped == 3 and s.ran == 5
    lines = (out / "results.jsonl").read_text().splitlines()
    assert len(lines) == 8 and all(json.loads(line) for line in lines)


def test_resume_skips_finished_trials_after_ctrl_c(tmp_path, tiny_config, monkeypatch):
    out = tmp_path / "r"
    real_execute = runner_mod.execute

    def interrupted(specs, **kw):
        for i, pair in enumerate(real_execute(specs, **kw)):
            if i == 3:
                raise KeyboardInterrupt
            yield pair

    monkeypatch.setattr(runner_mod, "execute", interrupted)
    with pytest.raises(KeyboardInterrupt):
        run_experiment(tiny_config, out=out)
    done = ResultStore.open(out).finished_ids()
    assert len(done) == 3
    monkeypatch.setattr(runner_mod, "execute", real_execute)
    s = run_experiment(tiny_config, out=out, resume=True)
    assert s.skipped == 3 and s.ran == 5
    store = ResultStore.open(out)
    assert len(store.records()) == 8 and len(store.meta["sessions"]) == 2


def test_existing_results_need_resume_and_same_config(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=1)
    with pytest.raises(ResultsError, match="pass --resume"):
        run_experiment(tiny_config, out=out)
    with pytest.raises(ResultsError, match="another configuration"):
        run_experiment(tiny_config, out=out, quick=True, resume=True)
    with pytest.raises(ResultsError, match="not a moik results folder"):
        ResultStore.open(tmp_path / "nothing")


def test_failed_trials_are_stored_and_retried_on_resume(tmp_path, tiny_config, monkeypatch):
    out = tmp_path / "r"
    real = runner_mod.execute

    def failing(specs, **kw):
        for rec, arrays in real(specs, **kw):
            if rec["trial"] == "pso/0/0":
                rec, arrays = dict(rec, status="error", error="boom"), {}
            yield rec, arrays

    monkeypatch.setattr(runner_mod, "execute", failing)
    assert run_experiment(tiny_config, out=out).failed == 1
    monkeypatch.setattr(runner_mod, "execute", real)
    s = run_experiment(tiny_config, out=out, resume=True)
    assert s.ran == 1 and s.failed == 0
    assert all(r["status"] == "ok" for r in ResultStore.open(out).records())
