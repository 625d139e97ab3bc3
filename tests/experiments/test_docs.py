"""``moik report RESULTS --docs DOCS``: pages and blocks generated from stored results."""

import json
import subprocess

import pytest

from moik.cli import main
from moik.experiments import docs as docs_module
from moik.experiments.config import ANALYSES
from moik.experiments.docs import BLOCK, write_docs
from moik.experiments.files import git_commit
from moik.experiments.headlines import HEADLINES
from moik.experiments.store import ResultStore

PAGE = """# Reproducing

Hand-written prose with a number, 42, that stays.

<!-- generated: mpso-single summary -->
old numbers 1.23
<!-- end generated -->

More prose between the blocks.

<!-- generated: eosma-table5 summary -->
_Stamp: not regenerated since commit abc123 (per git log)_

- eosma mean 9.55e-09
<!-- end generated -->

The end.
"""


@pytest.fixture(scope="module")
def quick_run(tmp_path_factory):
    """A results folder of ``mpso-single --quick`` (run once for the module)."""
    out = tmp_path_factory.mktemp("results") / "mpso-single"
    assert main(["experiment", "run", "mpso-single", "--quick", "--workers", "1",
                 "--no-progress", "--out", str(out)]) == 0
    return out


@pytest.fixture
def docs(tmp_path):
    folder = tmp_path / "docs"
    folder.mkdir()
    (folder / "reproducing.md").write_text(PAGE)
    return folder


def _blocks(text):
    return {m["name"]: m["body"] for m in BLOCK.finditer(text)}


def _outside(text):
    return BLOCK.sub("", text)


def test_the_block_is_replaced_with_a_stamp_and_the_prose_kept(quick_run, docs, capsys):
    assert main(["report", str(quick_run), "--docs", str(docs), "--no-figures"]) == 0
    meta = json.loads((quick_run / "meta.json").read_text())
    text = (docs / "reproducing.md").read_text()
    body = _blocks(text)["mpso-single"]
    assert "old numbers" not in body
    commit = meta["sessions"][0]["git_commit"]
    assert (commit[:12] if commit else "unknown commit") in body
    assert f"config fingerprint {meta['config_fingerprint'][:12]}" in body
    assert "3 of 3 trials finished" in body and "(quick size)" in body
    assert f"wall time {meta['sessions'][0]['wall_time_s']:.1f} s (serial)" in body
    assert "| m-pso |" in body  # the headline table of the summary analysis
    assert _outside(text) == _outside(PAGE)  # every byte outside the blocks is kept
    assert _blocks(text)["eosma-table5"] == _blocks(PAGE)["eosma-table5"]
    page = (docs / "results" / "mpso-single-quick.md").read_text()
    assert body.splitlines()[0] in page and "#### Final objective value" in page
    assert "blocks regenerated: mpso-single summary" in capsys.readouterr().out


def test_a_second_run_changes_nothing(quick_run, docs):
    write_docs([quick_run], docs, figures=True)
    first = {p: p.read_bytes() for p in docs.rglob("*") if p.is_file()}
    assert any(p.suffix == ".png" for p in first)
    page = (docs / "results" / "mpso-single-quick.md").read_text()
    assert "](figures/mpso-single-quick/convergence.png)" in page
    write_docs([quick_run], docs, figures=True)
    second = {p: p.read_bytes() for p in docs.rglob("*") if p.is_file()}
    assert second.keys() == first.keys()
    assert all(second[p] == first[p] for p in first if p.suffix != ".png")


def test_a_kept_block_without_a_stamp_is_warned_about(quick_run, docs, capsys):
    (docs / "reproducing.md").write_text(PAGE.replace("_Stamp: not regenerated since commit "
                                                      "abc123 (per git log)_\n", ""))
    update = write_docs([quick_run], docs, figures=False)
    assert update.kept == ["eosma-table5"]
    assert "block 'eosma-table5 summary' is not regenerated and has no stamp" in \
        capsys.readouterr().err


def test_an_absent_folder_is_a_clear_error(tmp_path, docs, capsys):
    assert main(["report", str(tmp_path / "nowhere"), "--docs", str(docs)]) == 2
    err = capsys.readouterr().err
    assert "moik: error: no results folder could be used for the docs" in err
    assert "holds no moik results" in err
    assert "Traceback" not in err and (docs / "reproducing.md").read_text() == PAGE


def test_a_damaged_folder_is_left_out_with_a_warning(quick_run, tmp_path, docs, capsys):
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "meta.json").write_text("{ torn")
    assert main(["report", str(bad), str(quick_run), "--docs", str(docs),
                 "--no-figures"]) == 1
    out, err = capsys.readouterr()
    assert f"{bad} left out: ResultsError" in err and "1 warning(s)" in out
    assert "old numbers" not in (docs / "reproducing.md").read_text()


def test_a_tree_with_uncommitted_changes_is_refused_unless_forced(quick_run, docs,
                                                                   monkeypatch, capsys):
    monkeypatch.setattr(docs_module, "git_commit", lambda: "0123456789abcdef0123-dirty")
    assert main(["report", str(quick_run), "--docs", str(docs), "--no-figures"]) == 2
    assert "uncommitted changes: commit them first" in capsys.readouterr().err
    assert (docs / "reproducing.md").read_text() == PAGE
    assert main(["report", str(quick_run), "--docs", str(docs), "--no-figures",
                 "--force"]) == 0
    assert "generated by `moik report --docs` at commit 0123456789ab (with uncommitted " \
        "changes)" in (docs / "reproducing.md").read_text()
    assert main(["report", str(quick_run), "--force"]) == 2  # --force goes with --docs


def test_the_pages_name_the_results_folder_without_its_path(quick_run, docs):
    write_docs([quick_run], docs, figures=False)
    page = (docs / "results" / "mpso-single-quick.md").read_text()
    assert "- results folder: `mpso-single`" in page
    assert str(quick_run.parent) not in page


def test_stamp_without_git(quick_run, docs, monkeypatch):
    def no_git(*args, **kwargs):
        raise FileNotFoundError("git")

    monkeypatch.setattr(subprocess, "run", no_git)
    assert git_commit() is None
    write_docs([quick_run], docs, figures=False)
    assert "at commit unknown commit" in (docs / "reproducing.md").read_text()


def test_git_commit_only_of_the_checkout_moik_heads(tmp_path):
    assert git_commit(tmp_path) is None  # not the top of a checkout: no commit, no error


def test_sessions_record_their_wall_time(quick_run):
    session = ResultStore.open(quick_run).meta["sessions"][-1]
    assert session["trials_run"] == 3 and session["wall_time_s"] > 0 and session["finished"]


def test_wall_time_of_an_old_folder_comes_from_the_timestamps(quick_run):
    store = ResultStore.open(quick_run)
    for s in store.meta["sessions"]:
        s.pop("wall_time_s")
    seconds, measured = docs_module.wall_time(store, store.records())
    assert not measured and 0 <= seconds < 600


def test_every_analysis_has_a_headline():
    """The docs command summarises every analysis a config may ask for."""
    assert set(ANALYSES) <= set(HEADLINES)


def test_blocks_in_algorithms_md_are_replaced_too(quick_run, docs):
    (docs / "algorithms.md").write_text(PAGE)
    assert main(["report", str(quick_run), "--docs", str(docs), "--no-figures"]) == 0
    for page in ("reproducing.md", "algorithms.md"):
        text = (docs / page).read_text()
        assert "old numbers" not in _blocks(text)["mpso-single"]
        assert _outside(text) == _outside(PAGE)
