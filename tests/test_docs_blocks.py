"""Every code block of README.md and docs/*.md runs, and prints what the page shows.

The collector is ``tests/docs_blocks.py`` (a page's python blocks in one namespace, its
``moik`` commands through :func:`moik.cli.main`); ``python tests/docs_blocks.py --update``
writes the shown outputs and the gallery's figures. A block that prints must show its
output; the commands not run are only those :func:`docs_blocks.not_run` gives a reason
for (installs, the test run itself, full-size experiments, a Dask cluster).
"""

import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import docs_blocks  # noqa: E402

PAGES = [p for p in docs_blocks.PAGES if docs_blocks.blocks(p)]


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_block_runs_and_prints_what_the_page_shows(page, tmp_path):
    if "pareto_explorer" in page.read_text():
        pytest.importorskip("plotly", reason="the explorer examples need plotly (the "
                            "'explorer' extra)")
    for block, printed in docs_blocks.run_page(page, tmp_path):
        where = f"{page.name}:{block.line}"
        if block.shown is None:
            assert not printed.strip(), (f"{where} prints but the page shows no output: "
                                         "run python tests/docs_blocks.py --update after "
                                         "adding an empty ```text block")
        else:
            assert docs_blocks.normalise(printed) == docs_blocks.normalise(block.shown), (
                f"{where} prints other than the page shows (python tests/docs_blocks.py "
                "--update rewrites it)")


def test_the_pages_have_code_to_run():
    names = {p.name for p in PAGES}
    assert {"README.md", "gallery.md", "pareto.md", "explorer.md", "solver.md"} <= names


def test_every_command_not_run_says_why():
    """Only installs, the test run, full-size experiments and the like are not run."""
    skipped = {}
    for page in docs_blocks.PAGES:
        for block in docs_blocks.blocks(page):
            if block.lang == "bash":
                for argv in docs_blocks.commands(block.code):
                    reason = docs_blocks.not_run(argv)
                    if reason is not None:
                        skipped[" ".join(argv[:3])] = reason
    assert all(skipped.values())
    assert not any(r.startswith("not a moik command") for r in skipped.values()), skipped


def test_the_gallery_shows_each_examples_output_and_figures():
    gallery = (docs_blocks.DOCS / "gallery.md").read_text()
    for block in docs_blocks.blocks(docs_blocks.DOCS / "gallery.md"):
        assert block.shown is not None, f"gallery.md:{block.line} shows no output"
    for image in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", gallery):
        assert (docs_blocks.DOCS / image).is_file(), image
    assert re.search(r"!\[[^\]]*\]\(examples/figures/", gallery)


def test_the_collector_reads_chains_and_continuations():
    cmds = docs_blocks.commands("python3 -m venv .venv && .venv/bin/pip install -e . && "
                                ".venv/bin/moik solve eosma7 \\\n  --deg  # a comment\n")
    assert cmds == [["python3", "-m", "venv", ".venv"], ["pip", "install", "-e", "."],
                    ["moik", "solve", "eosma7", "--deg"]]
    assert docs_blocks.not_run(["moik", "experiment", "run", "x"]) is not None
    assert docs_blocks.not_run(["moik", "experiment", "run", "x", "--quick"]) is None
    assert docs_blocks.normalise("took 28.0 ms (compiled 3 kernels in 9.1 s first)\n") == \
        "took <time>"


def test_the_readmes_first_run_times_are_the_stored_tables():
    """README.md's first-run times are generated from benchmarks/startup.py --first-runs's
    stored table (python tests/docs_blocks.py --update README.md), never typed."""
    text = (docs_blocks.ROOT / "README.md").read_text()
    block = docs_blocks.FIRST_RUN_BLOCK.search(text)
    assert block is not None
    assert block["body"] == docs_blocks.first_run_text()
    assert "moik compile" in docs_blocks.first_run_text()
    assert "a few seconds" not in text
