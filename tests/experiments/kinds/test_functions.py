"""Benchmark-function experiments (moik.experiments.kinds.functions): config, trials, tables."""

import copy

import numpy as np
import pytest

from moik.exceptions import ConfigError
from moik.experiments.config import ExperimentConfig

BENCH = {
    "name": "bench-test",
    "title": "tiny benchmark experiment",
    "source": "test",
    "problem": {"kind": "benchmark", "names": ["F1", {"name": "spring", "label": "spring"}],
                "params": {"n_var": 5}},
    "algorithms": [{"name": "ibes"}, {"name": "pso"}],
    "pop_size": 6,
    "iterations": 4,
    "runs": 3,
    "seed": 3,
    "analyses": ["per-target", "per-target-ranksum"],
    "proposed": "ibes",
}


def _bench(**changes):
    d = copy.deepcopy(BENCH)
    d.update(changes)
    return d


def test_benchmark_config_entries_and_params():
    cfg = ExperimentConfig.from_dict(BENCH)
    names = cfg["problem"]["names"]
    assert names[0] == {"name": "F1", "label": "F1", "params": {"n_var": 5}}
    assert names[1]["params"] == {}  # spring takes no n_var


@pytest.mark.parametrize("change, match", [
    ({"robot": "planar2"}, "takes no 'robot'"),
    ({"problem": {"kind": "benchmark", "names": ["F99"]}}, "unknown benchmark 'F99'"),
    ({"problem": {"kind": "benchmark", "names": [{"name": "F1", "params": {"bad": 1}}]}},
     "unknown key.*bad"),
    ({"problem": {"kind": "benchmark", "names": []}}, "non-empty list"),
    ({"problem": {"kind": "benchmark", "names": ["F1", "F1"]}}, "labels must be unique"),
    ({"problem": {"kind": "benchmark", "names": ["F1"], "params": {"n_var": 1}}}, "n_var"),
    ({"problem": {"kind": "benchmark", "names": ["cec2017_F3"]}}, "requires: \\['cec'\\]"),
    ({"requires": ["gpu"]}, "requires must be a list of: cec"),
])
def test_benchmark_config_errors(change, match):
    with pytest.raises(ConfigError, match=match):
        ExperimentConfig.from_dict(_bench(**change))


def test_missing_extra_is_one_clear_error(monkeypatch, tmp_path):
    from moik.experiments import config, run_experiment

    cfg = ExperimentConfig.from_dict(_bench(requires=["cec"]))
    monkeypatch.setattr(config.importlib.util, "find_spec", lambda name: None)
    with pytest.raises(ConfigError,
                       match=r"needs the optional extra 'cec' .*pip install -e '\.\[cec\]'"):
        run_experiment(cfg, out=tmp_path / "r")


def test_constraint_violation_of_an_infeasible_design():
    from moik.experiments.kinds.functions import constraint_violation
    from moik.problems.benchmarks import get_benchmark

    spring = get_benchmark("spring")
    f, cv = constraint_violation(spring, np.array([0.25, 0.25, 15.0]))  # I-BES Table 14 corner
    assert cv > 0 and f == pytest.approx(0.265625)
    f, cv = constraint_violation(get_benchmark("F1", n_var=3), np.zeros(3))
    assert (f, cv) == (0.0, 0.0)


def test_benchmark_run_records_and_tables(tmp_path):
    from moik.experiments import ResultStore, run_experiment
    from moik.experiments.analysis import analyze

    cfg = ExperimentConfig.from_dict(BENCH)
    summary = run_experiment(cfg, out=tmp_path / "r")
    assert (summary.ran, summary.failed) == (12, 0)
    store = ResultStore.open(tmp_path / "r")
    recs = store.records()
    for r in recs:
        assert r["feasible"] == (r["cv"] == 0.0)
        assert (r["best_f"] is None) == (not r["feasible"])  # never an infeasible best_f
        assert store.load_arrays(r["trial"])["convergence"].size == 5  # initial + 4 iterations
    f1 = [r for r in recs if r["target_name"] == "F1"]
    assert all(r["f_opt"] == 0.0 and r["error"] == r["best_f"] for r in f1)
    _, tables = analyze(store)
    assert [t.title.split(" ")[0] for t in tables] == ["Final", "Wilcoxon"]
    assert {row[0] for row in tables[0].rows} == {"F1", "spring"}
    assert tables[1].header == ["target", "source", "ibes vs pso"]


def test_same_seeds_give_the_same_benchmark_records(tmp_path):
    from moik.experiments import ResultStore, run_experiment

    cfg = ExperimentConfig.from_dict(_bench(runs=1))
    for k in (1, 2):
        run_experiment(cfg, out=tmp_path / f"r{k}")
    a, b = (ResultStore.open(tmp_path / f"r{k}").records() for k in (1, 2))
    assert [r["objective"] for r in a] == [r["objective"] for r in b]
