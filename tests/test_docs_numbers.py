"""The performance and solver pages quote only generated tables.

Measured numbers live in files under ``docs/results/`` written by the benchmarks
(``--out``) and the experiment reports; docs/performance.md and docs/solver.md link to
them and type no measurement. These tests check that every link of those pages into
``docs/results/`` names a file that exists there, that their other relative links resolve
too, and that a timing or a speed ratio appears in their prose only as a goal
(``<= 0.5 s``, ``>= 5x``).
"""

import re
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parents[1] / "docs"
RESULTS = DOCS / "results"
PAGES = ("performance.md", "solver.md")

LINK = re.compile(r"\]\((?P<target>[^)\s]+)\)")
# a time (500 ms, 0.08 s, 80 ns, 3 us), a ratio (1.3x, 30x), a share (65 %) or an angle
# (0.1 rad), a range (0.06-0.11 rad) too; exponents (1e-6 rad) are tolerances, not matched
_NUMBER = r"\d[\d,]*(?:\.\d+)?"
MEASURE = re.compile(rf"(?<![\w.\-]){_NUMBER}(?:\s?-\s?{_NUMBER})?"
                     r"(?:\s?(?:ms|us|ns|s|rad)\b|x\b|\s?%)")
GOAL = re.compile(r"(?:<=|>=|<|>)\s*$")


def _text(page: str) -> str:
    return (DOCS / page).read_text(encoding="utf-8")


def _relative_links(page: str) -> list[str]:
    targets = [m.group("target").split("#")[0] for m in LINK.finditer(_text(page))]
    return [t for t in targets if t and "://" not in t]


@pytest.mark.parametrize("page", PAGES)
def test_every_results_link_names_a_file_under_docs_results(page):
    links = [t for t in _relative_links(page) if t.startswith("results/")]
    assert links, f"docs/{page} links to no generated table under docs/results/"
    for target in links:
        path = (DOCS / target).resolve()
        assert path.is_relative_to(RESULTS), f"docs/{page}: {target} leaves docs/results/"
        assert path.is_file() or (target.endswith("/") and path.is_dir()), (
            f"docs/{page} links to {target}, which is not a file under docs/results/")


@pytest.mark.parametrize("page", PAGES)
def test_other_relative_links_resolve(page):
    for target in _relative_links(page):
        assert (DOCS / target).exists(), f"docs/{page} links to {target}, which does not exist"


@pytest.mark.parametrize("page", PAGES)
def test_timings_and_ratios_appear_only_as_goals(page):
    typed = []
    for line in _text(page).splitlines():
        for m in MEASURE.finditer(line):
            if not GOAL.search(line[:m.start()]):
                typed.append(f"{m.group(0)!r} in: {line.strip()}")
    assert not typed, (f"docs/{page} types measured values (expected them only in "
                       "docs/results/ files, or as a goal after <= or >=):\n" + "\n".join(typed))
