"""A results folder from elsewhere (another machine or person) stays harmless: nothing is
written or deleted outside the folders given, no text becomes markup, and no field it
lacks or mangles ends in a raw exception (store, records, docs, report, explorer)."""

import copy
import json
import os
import shutil

import numpy as np
import pytest

from moik.cli import main
from moik.exceptions import ResultsError
from moik.experiments.config import ExperimentConfig
from moik.experiments.docs import write_docs
from moik.experiments.report import make_report, md
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results
from tests.experiments.conftest import TINY


@pytest.fixture(scope="module")
def stored(tmp_path_factory):
    """One finished run of the tiny experiment (copied by :func:`folder` for each test)."""
    out = tmp_path_factory.mktemp("stored") / "r"
    run_experiment(ExperimentConfig.from_dict(copy.deepcopy(TINY)), out=out)
    return out


@pytest.fixture
def folder(stored, tmp_path):
    out = tmp_path / "work" / "r"
    shutil.copytree(stored, out)
    return out


def _meta(folder):
    return json.loads((folder / "meta.json").read_text())


def _set_meta(folder, meta):
    (folder / "meta.json").write_text(json.dumps(meta))


def _files(root):
    return sorted(str(p.relative_to(root)) for p in root.rglob("*"))


def test_docs_never_write_outside_docs_for_a_hostile_experiment_name(folder, tmp_path):
    """Before: experiment "../../x/y" wrote the page and PNGs outside DOCS and deleted every
    *.png of that folder."""
    meta = _meta(folder)
    meta["experiment"] = "../../x/y"
    _set_meta(folder, meta)
    docs = tmp_path / "site" / "docs"
    docs.mkdir(parents=True)
    outside = tmp_path / "x"
    outside.mkdir()
    (outside / "keep.png").write_bytes(b"png")
    before = _files(tmp_path / "site"), _files(outside)
    with pytest.raises(ResultsError, match="no results folder could be used"):
        write_docs([folder], docs, figures=False)
    assert (_files(tmp_path / "site"), _files(outside)) == before


def test_docs_folder_must_exist(folder, tmp_path):
    """Before: --docs created a mistyped folder tree."""
    with pytest.raises(ResultsError, match="does not exist"):
        write_docs([folder], tmp_path / "dcos", figures=False)
    assert not (tmp_path / "dcos").exists()


def test_docs_figures_folder_as_a_link_is_not_written_through(folder, tmp_path):
    docs = tmp_path / "docs"
    (docs / "results" / "figures").mkdir(parents=True)
    victim = tmp_path / "victim"
    victim.mkdir()
    (victim / "keep.png").write_bytes(b"png")
    os.symlink(victim, docs / "results" / "figures" / "tiny-test")
    with pytest.raises(ResultsError, match="symbolic link"):
        write_docs([folder], docs, figures=False)
    assert _files(victim) == ["keep.png"]


@pytest.mark.parametrize("member", ["results.jsonl", "arrays"])
def test_resume_refuses_links_inside_the_folder(folder, tmp_path, member):
    """Before: results.jsonl -> any file got trial lines appended on --resume; arrays -> any
    folder got its .*.tmp files deleted and .npz files written."""
    victim = tmp_path / "victim"
    if member == "arrays":
        victim.mkdir()
        (victim / ".precious.tmp").write_text("keep")
        shutil.rmtree(folder / "arrays")
    else:
        victim.write_text("keep\n")
        (folder / "results.jsonl").unlink()
    os.symlink(victim, folder / member)
    before = _files(tmp_path / "victim") if victim.is_dir() else victim.read_text()
    with pytest.raises(ResultsError, match="symbolic link"):
        run_experiment(ExperimentConfig.from_dict(copy.deepcopy(TINY)), out=folder, resume=True)
    after = _files(tmp_path / "victim") if victim.is_dir() else victim.read_text()
    assert after == before


@pytest.mark.parametrize("member", ["report.md", "figures"])
def test_report_does_not_write_through_links(folder, tmp_path, member):
    victim = tmp_path / "victim"
    victim.mkdir()
    target = victim / "file" if member == "report.md" else victim
    if member == "report.md":
        target.write_text("keep")
    os.symlink(target, folder / member)
    with pytest.raises(ResultsError, match="symbolic link"):
        make_report(folder, figures=member == "figures")
    assert _files(victim) == (["file"] if member == "report.md" else [])


def test_report_of_a_parent_does_not_follow_a_linked_results_folder(folder, tmp_path):
    """Before: `moik report PARENT` wrote figures/ into the folder a symlinked sub-folder of
    PARENT points to (overwriting a file there)."""
    victim = tmp_path / "elsewhere"
    shutil.copytree(folder, victim)
    (victim / "figures").mkdir(exist_ok=True)
    (victim / "figures" / "errors.png").write_text("keep")
    before = _files(victim)
    parent = tmp_path / "parent"
    shutil.copytree(folder, parent / "own")
    os.symlink(victim, parent / "linked")
    report = make_report(parent, figures=True)
    assert [f.split(":")[0] for f in report.failed] == [str(parent / "linked")]
    assert "symbolic link" in report.failed[0]
    assert _files(victim) == before and (victim / "figures" / "errors.png").read_text() == "keep"
    assert (parent / "own" / "figures").is_dir()  # the real sub-folder is reported
    os.unlink(parent / "linked")
    os.symlink(victim, tmp_path / "only")
    (tmp_path / "alone").mkdir()
    os.symlink(victim, tmp_path / "alone" / "linked")
    with pytest.raises(ResultsError, match="symbolic link"):
        make_report(tmp_path / "alone", figures=False)
    assert _files(victim) == before


@pytest.mark.parametrize("field, value, says", [
    ("position", None, "'position' is missing"),
    ("position", [1.0, 2.0], "'position' is .*3 finite numbers"),
    ("position", [1.0, "x", 2.0], "'position'"),
    ("rotation", [[1, 2], [3]], "'rotation' is .*3 x 3"),
    ("rotation", [[1, 0, 0], [0, 1, 0], [0, 0, True]], "'rotation'"),
    ("hv_ref_point", "far", "'hv_ref_point'"),
])
def test_a_target_entry_moik_cannot_read_is_named(folder, field, value, says):
    """Before: a target without 'position' (or with a ragged rotation) in meta.json gave
    `KeyError: 'position'` (`ValueError: setting an array element...`) from the report."""
    meta = _meta(folder)
    if value is None:
        del meta["targets"][0][field]
    else:
        meta["targets"][0][field] = value
    _set_meta(folder, meta)
    with pytest.raises(ResultsError, match=f"meta.json has target .* whose {says}"):
        ResultStore.open(folder)
    with pytest.raises(ResultsError, match="no results folder could be reported.*ResultsError"):
        make_report(folder, figures=False)


def test_report_html_as_a_link_is_refused(folder, tmp_path):
    pytest.importorskip("plotly")
    from moik.experiments.explorer import report_explorer

    victim = tmp_path / "victim.html"
    victim.write_text("keep")
    os.symlink(victim, folder / "report.html")
    with pytest.raises(ResultsError, match="symbolic link"):
        report_explorer(folder)
    assert victim.read_text() == "keep"


def test_titles_and_names_are_escaped_in_markdown(folder):
    """Before: a title '<script>...' went into report.md as raw HTML."""
    meta = _meta(folder)
    meta["config"]["title"] = "<script>alert(1)</script> [x](javascript:alert(1))"
    meta["targets"][0]["name"] = "<img src=x onerror=alert(1)>"
    _set_meta(folder, meta)
    text = (make_report(folder, figures=False).path).read_text()
    assert "<script" not in text and "<img" not in text and "](javascript" not in text
    assert "&lt;script>" in text
    assert md("a\nb <b> c](d) p < 0.05") == "a b &lt;b> c]\\(d) p < 0.05"


@pytest.mark.parametrize("drop", ["targets", "title"])
def test_a_meta_without_what_the_report_reads_is_named(folder, drop):
    """Before: --resume passed, then the report failed with a bare KeyError."""
    meta = _meta(folder)
    if drop == "title":
        del meta["config"]["title"]
    else:
        del meta["targets"]
    _set_meta(folder, meta)
    with pytest.raises(ResultsError, match=f"meta.json .*{drop}"):
        ResultStore.open(folder)
    with pytest.raises(ResultsError, match="pass --resume|adopt"):
        run_experiment(ExperimentConfig.from_dict(copy.deepcopy(TINY)), out=folder)


def test_an_unplanned_trial_line_is_not_counted(folder, capsys):
    """Before: '9 of 8 planned trials finished'."""
    line = json.loads((folder / "results.jsonl").read_text().splitlines()[0])
    line["trial"], line["target"], line["run"] = "eosma/9/9", 9, 9
    with open(folder / "results.jsonl", "a") as fh:
        fh.write(json.dumps(line) + "\n")
    res = Results(ResultStore.open(folder))
    assert res.notes()[0] == "8 of 8 planned trials finished"
    assert "eosma/9/9" in " ".join(res.notes())


def test_a_line_of_another_configuration_is_not_counted(folder, capsys):
    """Before: a line carrying another config fingerprint counted as a finished trial of
    this one (and --resume kept it)."""
    lines = (folder / "results.jsonl").read_text().splitlines()
    first = json.loads(lines[0])
    first["config_fingerprint"] = "0" * 64
    (folder / "results.jsonl").write_text("\n".join([json.dumps(first), *lines[1:]]) + "\n")
    store = ResultStore.open(folder)
    assert first["trial"] not in store.finished_ids()
    assert store.malformed == [(1, f"trial {first['trial']!r} was written by another "
                                   "configuration (its fingerprint)")]
    assert "another configuration" in capsys.readouterr().err
    summary = run_experiment(ExperimentConfig.from_dict(copy.deepcopy(TINY)), out=folder,
                             resume=True)
    assert summary.ran == 1  # that trial is run again for this configuration


@pytest.mark.parametrize("trial", ["a\x00b", "x" * 300, "../../etc/passwd"])
def test_trial_ids_that_cannot_name_a_file_are_malformed_lines(folder, trial):
    """Before: ValueError (embedded null byte) or OSError (name too long) from the store."""
    line = json.loads((folder / "results.jsonl").read_text().splitlines()[0])
    line["trial"] = trial
    with open(folder / "results.jsonl", "a") as fh:
        fh.write(json.dumps(line) + "\n")
    store = ResultStore.open(folder, verify=True)
    assert len(store.records()) == 8 and len(store.malformed) == 1


def test_deep_lines_and_meta_do_not_make_the_folder_unusable(folder):
    """Before: a line or meta.json nested 100,000 deep raised RecursionError."""
    with open(folder / "results.jsonl", "a") as fh:
        fh.write("[" * 100_000 + "]" * 100_000 + "\n")
    store = ResultStore.open(folder)
    assert len(store.records()) == 8 and "nest" in store.malformed[0][1]
    (folder / "meta.json").write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(ResultsError, match="nested deeper"):
        ResultStore.open(folder)


def test_summary_of_a_multi_objective_config_prints_no_float_max(tmp_path):
    """Before: the default summary analysis printed 1.8e308 and an overflow warning."""
    cfg = copy.deepcopy(TINY)
    cfg.update(name="mo-test", problem={"kind": "bi-objective", "orientation": "geodesic"},
               algorithms=[{"name": "moeosma"}], analyses=["summary"], runs=1,
               targets={"kind": "random", "n": 1, "seed": 1, "with_orientation": True})
    cfg.pop("proposed")
    robot_cfg = ExperimentConfig.from_dict(cfg)
    run_experiment(robot_cfg, out=tmp_path / "mo")
    with np.errstate(over="raise"):
        text = make_report(tmp_path / "mo", figures=False).path.read_text()
    assert "1.798e+308" not in text and "e+308" not in text


def test_the_cli_report_of_a_hostile_folder_is_one_line(folder, tmp_path, capsys):
    meta = _meta(folder)
    meta["experiment"] = "../x"
    _set_meta(folder, meta)
    (tmp_path / "docs").mkdir()
    assert main(["report", str(folder), "--docs", str(tmp_path / "docs"), "--no-figures"]) == 2
    err = capsys.readouterr().err
    assert err.count("moik: error:") == 1 and "Traceback" not in err
