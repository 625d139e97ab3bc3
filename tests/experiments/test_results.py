"""load_results: the stored trials as records (and as a DataFrame with pandas)."""

import sys

import numpy as np
import pytest

import moik.experiments.runner as runner_mod
from moik.exceptions import ParameterError, ResultsError
from moik.experiments import load_results
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore


@pytest.fixture
def folder(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out)
    return out


def test_records_hold_the_scalars_and_the_arrays(folder):
    rows = load_results(folder)
    stored = ResultStore.open(folder).records()
    assert len(rows) == 8 and [r["trial"] for r in rows] == [r["trial"] for r in stored]
    row = rows[0]
    assert row["experiment"] == "tiny-test" and row["status"] == "ok"
    assert row["target_name"] == ResultStore.open(folder).meta["targets"][row["target"]]["name"]
    assert isinstance(row["best_f"], float) and isinstance(row["run"], int)
    arrays = ResultStore.open(folder).load_arrays(row["trial"])
    np.testing.assert_array_equal(row["convergence"], arrays["convergence"])
    assert isinstance(row["best_x"], np.ndarray) and row["best_x"].dtype == float
    scalars = load_results(folder, arrays=False)
    assert "convergence" not in scalars[0] and scalars[0]["best_f"] == row["best_f"]


def test_failed_trials_are_records_without_arrays(tmp_path, tiny_config, monkeypatch):
    real = runner_mod.execute

    def failing(specs, **kw):
        for rec, arrays in real(specs, **kw):
            if rec["trial"] == "pso/0/0":
                rec, arrays = dict(rec, status="error", error="boom"), {}
            yield rec, arrays

    monkeypatch.setattr(runner_mod, "execute", failing)
    run_experiment(tiny_config, out=tmp_path / "r")
    bad = [r for r in load_results(tmp_path / "r") if r["status"] != "ok"]
    assert len(bad) == 1 and bad[0]["error"] == "boom" and "convergence" not in bad[0]


def test_damaged_trials_are_left_out_with_a_warning(folder):
    trial = ResultStore.open(folder).records()[0]["trial"]
    (folder / "arrays" / ResultStore.array_name(trial)).write_bytes(b"")
    with pytest.warns(UserWarning, match="1 trial.s. left out.*an empty file"):
        rows = load_results(folder)
    assert len(rows) == 7 and trial not in {r["trial"] for r in rows}


def test_frame_needs_pandas(folder, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # as if not installed
    with pytest.raises(ParameterError, match=r"as_frame=True\) needs pandas, which is not"):
        load_results(folder, as_frame=True)
    with pytest.raises(ParameterError, match="as_frame must be True or False"):
        load_results(folder, as_frame="yes")
    with pytest.raises(ResultsError, match="not a moik results folder"):
        load_results(folder / "nothing")


def test_frame_has_one_row_per_trial(folder):
    pytest.importorskip("pandas")
    frame = load_results(folder, as_frame=True)
    assert len(frame) == 8 and {"algorithm", "best_f", "convergence"} <= set(frame.columns)
    assert sorted(frame["algorithm"].unique()) == ["eosma", "pso"]
    assert isinstance(frame["convergence"].iloc[0], np.ndarray)
