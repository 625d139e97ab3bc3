"""run_experiment's trial order (moik.experiments.runner): run by run on request."""

import pytest

from moik.exceptions import ParameterError
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore

from .conftest import stable


def test_by_run_runs_run_0_of_every_algorithm_and_target_first(tmp_path, tiny_config):
    out = tmp_path / "r"
    s = run_experiment(tiny_config, out=out, limit=4, by_run=True)
    assert s.ran == 4
    recs = ResultStore.open(out).records()
    assert {r["run"] for r in recs} == {0}
    assert {(r["algorithm"], r["target"]) for r in recs} == {
        (a, t) for a in ("eosma", "pso") for t in (0, 1)}
    s = run_experiment(tiny_config, out=out, resume=True, by_run=True)
    assert (s.skipped, s.ran) == (4, 4)
    plain = run_experiment(tiny_config, out=tmp_path / "plain")
    assert plain.ran == 8
    by_id = {r["trial"]: stable(r) for r in ResultStore.open(tmp_path / "plain").records()}
    for r in ResultStore.open(out).records():
        got, want = stable(r), by_id[r["trial"]]
        assert {k: v for k, v in got.items() if k != "worker"} == \
            {k: v for k, v in want.items() if k != "worker"}


def test_by_run_must_be_a_flag(tmp_path, tiny_config):
    with pytest.raises(ParameterError, match="by_run"):
        run_experiment(tiny_config, out=tmp_path / "r", by_run=1)
