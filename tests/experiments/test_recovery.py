"""Folders that lost or damaged meta.json: refused with a recovery path, never deleted or
relabelled; adopted on --resume only when every line names the configuration being run."""

import copy
import json
import shutil

import pytest

from moik.exceptions import ResultsError
from moik.experiments.config import ExperimentConfig
from moik.experiments.recovery import stored_fingerprint
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    """One finished run of the tiny experiment (copied by each test)."""
    from tests.experiments.conftest import TINY
    out = tmp_path_factory.mktemp("finished") / "r"
    run_experiment(ExperimentConfig.from_dict(copy.deepcopy(TINY)), out=out, progress=False)
    return out


@pytest.fixture
def folder(tmp_path, finished):
    out = tmp_path / "r"
    shutil.copytree(finished, out)
    return out


def _other(tiny):
    other = copy.deepcopy(tiny)
    other.update(name="other-test", seed=5)
    return ExperimentConfig.from_dict(other)


def test_lines_carry_the_experiment_and_its_fingerprint(folder, tiny_config):
    store = ResultStore.open(folder)
    assert {r["config_fingerprint"] for r in store.records()} == {tiny_config.fingerprint()}
    assert {r["experiment"] for r in store.records()} == {"tiny-test"}
    assert stored_fingerprint(store.meta) == tiny_config.fingerprint()  # same formula


def test_without_meta_a_run_is_refused_and_nothing_is_deleted(folder, tiny_config):
    """Before: a run without --resume deleted results.jsonl silently."""
    (folder / "meta.json").unlink()
    before = (folder / "results.jsonl").read_bytes()
    with pytest.raises(ResultsError, match=r"holds 8 trial record\(s\) in results.jsonl but it "
                                           r"has no meta.json; nothing was changed. To keep them"
                                           r", run the same experiment with --resume"):
        run_experiment(tiny_config, out=folder, progress=False)
    assert (folder / "results.jsonl").read_bytes() == before
    assert not (folder / "meta.json").exists()


def test_without_meta_another_experiment_cannot_adopt_the_trials(folder, tiny, tiny_config):
    """Before: --resume adopted the folder for any experiment (trials relabelled)."""
    (folder / "meta.json").unlink()
    before = (folder / "results.jsonl").read_bytes()
    with pytest.raises(ResultsError, match=r"Cannot adopt them for 'other-test' .*8 line\(s\) "
                                           r"of 'tiny-test' \(configuration "):
        run_experiment(_other(tiny), out=folder, resume=True, progress=False)
    assert (folder / "results.jsonl").read_bytes() == before


def test_without_meta_the_same_experiment_adopts_its_trials(folder, tiny_config):
    (folder / "meta.json").unlink()
    s = run_experiment(tiny_config, out=folder, resume=True, progress=False)
    assert s.skipped == 8 and s.ran == 0
    assert any("adopted 8 stored trial record(s) of 'tiny-test'" in n for n in s.notes)
    store = ResultStore.open(folder)
    assert len(store.records()) == 8 and store.meta["adopted"]["why"] == "it has no meta.json"


def test_lines_of_an_older_moik_are_not_adopted(folder, tiny_config):
    lines = [json.loads(x) for x in (folder / "results.jsonl").read_text().splitlines()]
    for rec in lines:
        del rec["config_fingerprint"]
    (folder / "results.jsonl").write_text("".join(json.dumps(r) + "\n" for r in lines))
    (folder / "meta.json").unlink()
    with pytest.raises(ResultsError, match="no configuration fingerprint"):
        run_experiment(tiny_config, out=folder, resume=True, progress=False)
    assert len((folder / "results.jsonl").read_text().splitlines()) == 8


def test_a_damaged_meta_is_kept_aside_when_the_trials_are_adopted(folder, tiny_config):
    (folder / "meta.json").write_text("{ torn")
    s = run_experiment(tiny_config, out=folder, resume=True, progress=False)
    assert s.skipped == 8
    assert (folder / "meta.json.damaged").read_text() == "{ torn"
    assert any("kept the unusable meta.json as meta.json.damaged" in n for n in s.notes)


@pytest.mark.parametrize("key", ["config_fingerprint", "sessions"])
def test_a_meta_missing_a_rebuildable_field_resumes(folder, tiny_config, key):
    """Before: KeyError tracebacks on --resume."""
    meta = json.loads((folder / "meta.json").read_text())
    del meta[key]
    (folder / "meta.json").write_text(json.dumps(meta))
    s = run_experiment(tiny_config, out=folder, resume=True, progress=False)
    assert s.skipped == 8 and any(f"meta.json had no {key.split('_')[0]}" in n
                                  or "no session list" in n for n in s.notes)
    meta = ResultStore.open(folder).meta
    assert meta["config_fingerprint"] == tiny_config.fingerprint() and meta["sessions"]


def test_a_meta_missing_its_config_is_set_aside_and_the_trials_adopted(folder, tiny_config):
    meta = json.loads((folder / "meta.json").read_text())
    del meta["config"]
    (folder / "meta.json").write_text(json.dumps(meta))
    s = run_experiment(tiny_config, out=folder, resume=True, progress=False)  # adopted by lines
    assert s.skipped == 8 and (folder / "meta.json.damaged").exists()


def test_malformed_lines_are_skipped_with_a_warning_on_resume(folder, tiny_config, capsys):
    """Before: {} and [1,2,3] gave KeyError/TypeError tracebacks; "trial": null counted."""
    with open(folder / "results.jsonl", "ab") as fh:
        fh.write(b'{}\n[1,2,3]\n{"trial": null}\n')
    s = run_experiment(tiny_config, out=folder, resume=True, progress=False)
    assert s.skipped == 8 and s.ran == 0
    err = capsys.readouterr().err
    assert err.count("skipped 3 malformed line(s)") == 1
    assert "line 9: no 'trial' field" in err and "line 10: a JSON list" in err
    assert "line 11: 'trial' is None" in err


def test_deleted_arrays_folder_is_recreated_on_resume(folder, tiny_config):
    """Before: FileNotFoundError writing arrays/.NAME.tmp."""
    shutil.rmtree(folder / "arrays")
    s = run_experiment(tiny_config, out=folder, resume=True, progress=False)
    assert s.ran == 8 and s.rerun_damaged == 8
    assert ResultStore.open(folder, verify=True).damaged == {}


@pytest.mark.parametrize("resume", [False, True])
def test_another_programs_results_jsonl_is_never_written_into(tmp_path, tiny_config, resume):
    """Before: a folder holding someone else's results.jsonl (no trial record, no meta.json)
    got a warning, then moik appended its trials to that file."""
    folder = tmp_path / "theirs"
    folder.mkdir()
    theirs = b'{"epoch": 1, "loss": 0.5}\n{"epoch": 2, "loss": 0.25}\n'
    (folder / "results.jsonl").write_bytes(theirs)
    with pytest.raises(ResultsError, match="no moik trial record .*not moik's.*nothing was "
                                           "changed"):
        run_experiment(tiny_config, out=folder, resume=resume, progress=False)
    assert (folder / "results.jsonl").read_bytes() == theirs
    assert sorted(p.name for p in folder.iterdir()) == ["results.jsonl"]
