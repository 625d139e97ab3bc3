"""The report of damaged results: warn, count what is there, go on past a bad folder."""

import pytest

from moik.cli import main
from moik.exceptions import ResultsError
from moik.experiments.report import make_report, write_report
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore


@pytest.fixture
def results(tmp_path, tiny_config):
    """``results/`` with two finished runs of the tiny experiment, ``a`` and ``b``."""
    base = tmp_path / "results"
    for name in ("a", "b"):
        run_experiment(tiny_config, out=base / name)
    return base


def test_damaged_and_missing_arrays_are_left_out_with_a_warning(results, capsys):
    trials = [r["trial"] for r in ResultStore.open(results / "a").records()]
    arrays = results / "a" / "arrays"
    (arrays / ResultStore.array_name(trials[0])).write_bytes(b"")
    (arrays / ResultStore.array_name(trials[1])).write_bytes(b"\x93NUMPY garbage")
    (arrays / ResultStore.array_name(trials[2])).unlink()
    report = make_report(results / "a", figures=True)
    assert report.failed == [] and len(report.warnings) == 1
    text = report.path.read_text()
    assert "- 5 of 8 planned trials finished" in text  # never "8 of 8" with 3 lost
    assert "**warning**: 3 trial(s) left out: their arrays are damaged or missing" in text
    assert "an empty file" in text and "is missing" in text
    assert f"--out {results / 'a'} --resume` runs them again" in text
    assert "3 trial(s) left out" in capsys.readouterr().err


def test_a_bad_folder_is_reported_and_the_others_go_on(results, capsys):
    (results / "b" / "meta.json").write_text("{ torn")
    (results / "c").mkdir()
    (results / "c" / "results.jsonl").write_text("")  # results without metadata
    assert main(["report", str(results), "--no-figures"]) == 1
    out, err = capsys.readouterr()
    assert "2 folder(s) could not be reported" in out
    assert f"{results / 'b'} not reported: ResultsError" in err
    text = (results / "report.md").read_text()
    assert "## tiny-test: tiny position experiment (full size)" in text
    assert "## b: not reported" in text and "## c: not reported" in text
    assert "meta.json: JSONDecodeError" in text and "meta.json: FileNotFoundError" in text


def test_no_readable_folder_is_an_error(results):
    for name in ("a", "b"):
        (results / name / "meta.json").write_text("[]")
    with pytest.raises(ResultsError, match="no results folder could be reported"):
        write_report(results)
    assert not (results / "report.md").exists()
