"""The code blocks of README.md and docs/*.md, run as a reader would run them.

A page's ``python`` blocks run in order in one namespace (a later block uses what an
earlier one defined), its ``bash`` blocks' ``moik`` commands run through
:func:`moik.cli.main`, all in one scratch folder. A fenced ``text`` block right after a
code block is what that code prints: the test (``tests/test_docs_blocks.py``) checks it,
and this script writes it::

    python tests/docs_blocks.py --update [PAGE ...]

Gallery pages include their scripts (``--8<-- "examples/NAME.py"``); the figures a
page's code writes are copied to ``docs/examples/figures/`` by ``--update``, where the
page shows them. Times (``28.0 ms``, ``1.2 s``) differ from run to run and machine to
machine: they are compared as ``<time>``. So are the FK evaluation counts of the printed
searches (``38659 FK evaluations``): the same code counted 38646 for explorer.md's
unreachable pose in one session's environment and 38659 in the next's (another machine,
fresh installs of the numerical libraries: the search's last bits differ), a cost figure
as a time is. Commands that are not run are listed by
:func:`not_run`, each with its reason.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shlex
import shutil
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
PAGES = [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]
FIGURES = DOCS / "examples" / "figures"

FENCE = re.compile(r"^```(?P<lang>[\w-]*)[^\n]*\n(?P<body>.*?)^```[ \t]*$", re.M | re.S)
SNIPPET = re.compile(r'^--8<-- "(?P<path>[^"]+)"\s*$', re.M)
TIME = re.compile(r"\d+(?:\.\d+)?\s?(?:ms|s)\b")
COMPILED = re.compile(r" ?\(compiled \d+ kernels? in [^)]*\)")
FK_COUNT = re.compile(r"\b\d+ FK evaluations\b")


@dataclass
class Block:
    """One fenced code block and the ``text`` block after it (its shown output)."""

    page: Path
    lang: str
    code: str
    line: int
    output: tuple[int, int] | None  # span of the shown output's body in the page text
    shown: str | None


def blocks(page: Path) -> list[Block]:
    """The page's ``python`` and ``bash`` blocks, in order, each with its shown output."""
    text = page.read_text(encoding="utf-8")
    fences = list(FENCE.finditer(text))
    out = []
    for k, m in enumerate(fences):
        if m.group("lang") not in ("python", "bash"):
            continue
        code = SNIPPET.sub(lambda s: (DOCS / s.group("path")).read_text(encoding="utf-8"),
                           m.group("body"))
        span, shown = None, None
        nxt = fences[k + 1] if k + 1 < len(fences) else None
        if nxt is not None and nxt.group("lang") == "text" \
                and not text[m.end():nxt.start()].strip():
            span, shown = nxt.span("body"), nxt.group("body")
        out.append(Block(page, m.group("lang"), code, text.count("\n", 0, m.start()) + 1,
                         span, shown))
    return out


def commands(code: str) -> list[list[str]]:
    """The commands of a ``bash`` block: continuation lines joined, ``&&`` chains split,
    comments dropped, ``.venv/bin/`` prefixes removed."""
    out = []
    for line in code.replace("\\\n", " ").splitlines():
        words = shlex.split(line, comments=True)
        part: list[str] = []
        for w in [*words, "&&"]:
            if w == "&&":
                if part:
                    out.append([part[0].removeprefix(".venv/bin/"), *part[1:]])
                part = []
            else:
                part.append(w)
    return out


def not_run(argv: list[str]) -> str | None:
    """Why a documented command is not run by the tests (``None``: it is run)."""
    head = argv[0]
    if head in ("pip", "python3", "python") and argv[1:3] in (["-m", "venv"], ["-m", "pip"]) \
            or head == "pip":
        return "installs packages (the test run is that install)"
    if head in ("python", "python3") and argv[1:3] == ["-m", "pytest"]:
        return "the test run itself"
    if head in ("python", "python3") and argv[1:3] == ["-m", "mypy"]:
        return "tests/test_typing.py runs it"
    if head == "ruff":
        return "the lint, run by .ci/run"
    if head == "mkdocs":
        return "tests/test_docs_site.py builds the site"
    if head != "moik":
        return f"not a moik command ({head})"
    if argv[1:2] == ["compile"]:
        return "compiles every kernel: minutes on a first run (tests/cli/test_kernels.py)"
    if argv[1:3] == ["experiment", "run"] and "--quick" not in argv:
        return "a full-size experiment: minutes to hours (its --quick runs are tested)"
    if "--dask-scheduler" in argv:
        return "needs a Dask cluster (tests/experiments run the Dask executor locally)"
    if "--config" in argv:
        return "a file of the reader's own"
    if argv[1] == "report":
        if "--docs" in argv:
            return "rewrites the committed docs/results pages"
        folders = [a for a in argv[2:] if not a.startswith("-")]
        if not all(f.rstrip("/").endswith("-quick") for f in folders):
            return "reports a full-size run's results"
    return None


def _moik(argv: list[str]) -> None:
    from moik.cli import main

    code = main(argv)
    if code not in ((0, 1) if argv[0] == "solve" else (0,)):  # solve: 1 = not solved
        raise AssertionError(f"`{shlex.join(['moik', *argv])}` exited with {code}")


def run_block(block: Block, namespace: dict) -> str:
    """Run one block in the current folder; what it printed."""
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        if block.lang == "python":
            exec(compile(block.code, f"{block.page.name}:{block.line}", "exec"), namespace)
        else:
            for argv in commands(block.code):
                if not_run(argv) is None:
                    _moik(argv[1:])
    return buffer.getvalue()


def normalise(text: str) -> str:
    """Printed text without what changes from run to run or machine to machine (times,
    compile notices, FK evaluation counts)."""
    text = FK_COUNT.sub("<n> FK evaluations", COMPILED.sub("", text))
    return TIME.sub("<time>", text).rstrip()


def run_page(page: Path, workdir: Path) -> list[tuple[Block, str]]:
    """Every block of ``page`` run in order in ``workdir``, with what each printed."""
    os.environ.setdefault("MPLBACKEND", "Agg")
    namespace: dict = {"__name__": "__main__"}
    here = Path.cwd()
    os.chdir(workdir)
    try:
        return [(b, run_block(b, namespace)) for b in blocks(page)]
    finally:
        os.chdir(here)
        import matplotlib.pyplot as plt

        plt.close("all")


FIRST_RUNS = DOCS / "results" / "first-runs.txt"
FIRST_RUN_BLOCK = re.compile(r"(<!-- first-run times: generated from docs/results/first-runs\.txt "
                             r"-->\n)(?P<body>.*?)(<!-- end first-run times -->)", re.S)
MEASURED = re.compile(r"^(?P<what>.+?): median (?P<wall>[\d.]+) s wall \((?P<low>[\d.]+)-"
                      r"(?P<high>[\d.]+)\)", re.M)


def first_run_text() -> str:
    """The README's first-run times, in words, from ``benchmarks/startup.py --first-runs``'s
    stored table."""
    table = FIRST_RUNS.read_text(encoding="utf-8")
    header = table.splitlines()[0]
    when = re.search(r"; (\d{4}-\d\d-\d\d) [\d:]+, [^,]+, (\d+) CPUs", header)
    runs = {m["what"]: m for m in MEASURED.finditer(table)}
    def seconds(m: re.Match) -> str:
        low, high = f"{float(m['low']):.0f}", f"{float(m['high']):.0f}"
        return f"{float(m['wall']):.0f} s" + (f" ({low}-{high} s)" if low != high else "")

    said = "; ".join(f"{what.split(' (')[0]} {seconds(m)}" for what, m in runs.items())
    machine = f"a {when[2]}-CPU machine on {when[1]}" if when else "one machine"
    load = re.search(r"load average ([\d.]+) after them", table)
    busy = (f", shared with other work (load average {float(load[1]):.0f}: expect less on "
            "a quiet machine)" if load and when and float(load[1]) > int(when[2]) else "")
    return (f"Measured with an empty kernel cache on {machine}{busy}; median wall time "
            f"([docs/results/first-runs.txt](docs/results/first-runs.txt), "
            f"`benchmarks/startup.py --first-runs`): {said}.\n")


def update(page: Path, workdir: Path) -> None:
    """Rewrite the page's shown outputs with what its blocks print now; copy the figures
    it writes to ``docs/examples/figures/`` (gallery pages)."""
    results = run_page(page, workdir)
    text = page.read_text(encoding="utf-8")
    for block, printed in sorted(results, key=lambda r: -(r[0].output or (0, 0))[0]):
        if block.output is not None:
            a, b = block.output
            text = text[:a] + printed.rstrip() + "\n" + text[b:]
    if page.name == "README.md":
        text = FIRST_RUN_BLOCK.sub(lambda m: m[1] + first_run_text() + m[3], text)
    page.write_text(text, encoding="utf-8")
    for figure in sorted(workdir.glob("*.png")):
        if f"examples/figures/{figure.name}" in text:
            FIGURES.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(figure, FIGURES / figure.name)


if __name__ == "__main__":
    import tempfile

    if sys.argv[1:2] != ["--update"]:
        sys.exit(__doc__)
    chosen = [Path(p).resolve() for p in sys.argv[2:]] or PAGES
    for page in chosen:
        with tempfile.TemporaryDirectory() as tmp:
            update(page, Path(tmp))
            print("updated", page.relative_to(ROOT))
