"""The report of damaged results: warn, count what is there, go on past a bad folder."""

import pytest
import tomli_w

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
    assert "meta.json' is not valid JSON" in text and "meta.json': it does not exist" in text


def test_no_readable_folder_is_an_error(results):
    for name in ("a", "b"):
        (results / name / "meta.json").write_text("[]")
    with pytest.raises(ResultsError, match="no results folder could be reported"):
        write_report(results)
    assert not (results / "report.md").exists()


def test_malformed_lines_do_not_stop_a_report_over_a_parent(results, capsys):
    """The good trials of a folder with malformed lines are reported, the lines named."""
    with open(results / "b" / "results.jsonl", "ab") as fh:
        fh.write(b'{}\n[1,2,3]\n{"trial": null}\n')
    (results / "c").mkdir()
    (results / "c" / "meta.json").write_text("{}")
    report = make_report(results, figures=False)
    assert report.failed == [f"{results / 'c'}: ResultsError: {results / 'c'}/meta.json has "
                             "format None, expected 'moik-results/1'"]
    assert report.warnings == [f"{results / 'b' / 'results.jsonl'}: skipped 3 malformed line(s) "
                               "that are not trial records (line 9: no 'trial' field; line 10: "
                               "a JSON list, not an object; line 11: 'trial' is None, expected "
                               "a str)"]
    text = report.path.read_text()
    assert text.count("- 8 of 8 planned trials finished") == 2
    assert "## c: not reported" in text and "skipped 3 malformed line(s)" in text


def test_the_repair_command_of_a_config_file_run_names_the_file(tmp_path, tiny, capsys):
    """Before: `moik experiment run tiny-test ...`, an experiment that does not exist."""
    from moik.experiments.config import load_config
    path = tmp_path / "tiny_test.toml"
    path.write_text(tomli_w.dumps(tiny))
    run_experiment(load_config(path), out=tmp_path / "r", progress=False)
    trial = ResultStore.open(tmp_path / "r").records()[0]["trial"]
    (tmp_path / "r" / "arrays" / ResultStore.array_name(trial)).unlink()
    text = make_report(tmp_path / "r", figures=False).path.read_text()
    assert f"`moik experiment run --config {path} --out {tmp_path / 'r'} --resume`" in text
