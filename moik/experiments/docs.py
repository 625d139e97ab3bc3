"""``moik report DIR [DIR ...] --docs DOCS``: the project's docs generated from stored results.

For every results folder given (a folder of ``moik experiment run NAME --out
F``, or a parent folder holding several):

- ``DOCS/results/NAME.md`` (``NAME-quick.md`` for the quick size) is written
  whole: a stamp line, then the experiment's full report section (tables,
  analyses, figure links; :func:`moik.experiments.report.experiment_section`),
  its PNG figures in ``DOCS/results/figures/NAME/``;
- in ``DOCS/reproducing.md`` and the other :data:`SUMMARY_PAGES` every block ::

      <!-- generated: NAME summary -->
      ...
      <!-- end generated -->

  of that experiment is replaced by its stamp line and headline numbers
  (:mod:`moik.experiments.headlines`). Text outside the blocks is left as it
  is, byte for byte; blocks of experiments not given are kept, and one without
  a stamp line is named in a warning (a stale block must say so).

The stamp (:func:`stamp`) names the moik version and git commit of the code
that ran the trials (recorded in ``meta.json`` at run time), the config
fingerprint the results folder keys its trials by, trials finished / planned,
the run's wall time and the commit that generated the docs. Nothing in it
depends on when the docs were generated, so running the command twice on the
same results gives the same files.

A results folder that cannot be read gives a warning and is left out (the
others are used); when none can be read the command fails with
:class:`~moik.exceptions.ResultsError`.
"""

from __future__ import annotations

import datetime as _dt
import re
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from moik._paths import file_name, inside, remove
from moik.exceptions import ParameterError, ResultsError
from moik.experiments.files import atomic_write_bytes, git_commit
from moik.experiments.headlines import headline
from moik.experiments.report import (
    FOLDER_ERRORS,
    damaged_warning,
    experiment_section,
    md,
    result_folders,
)
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results

BLOCK = re.compile(r"^<!-- generated: (?P<name>[a-z0-9-]+) (?P<kind>[a-z0-9-]+) -->\n"
                   r"(?P<body>.*?)^<!-- end generated -->$", re.DOTALL | re.MULTILINE)
"""A generated block of a docs page: experiment name, kind, body."""

STAMP = re.compile(r"^_Stamp: .+_$", re.MULTILINE)
"""The stamp line every block carries (generated, or ``not regenerated since ...``)."""

KINDS = ("summary",)
"""Block kinds the command writes."""


def _short(commit: str | None) -> str:
    if not commit:
        return "unknown commit"
    dirty = commit.endswith("-dirty")
    return commit[:12] + (" (with uncommitted changes)" if dirty else "")


def _time(text: str | None) -> _dt.datetime | None:
    if text is None:
        return None
    try:
        return _dt.datetime.fromisoformat(text)
    except (TypeError, ValueError):
        return None


def wall_time(store: ResultStore, records: list[dict]) -> tuple[float, bool]:
    """Seconds the runs of ``store`` took, and whether every session recorded its own.

    A session that ended normally records ``wall_time_s``; for one that did not (an
    older moik, or an interrupted run) the span from its start to its last finished
    trial is counted instead.
    """
    sessions = store.meta.get("sessions", [])
    starts = [_time(s.get("started")) for s in sessions]
    done = sorted(t for t in (_time(r.get("finished_at")) for r in records) if t is not None)
    total, measured = 0.0, True
    for i, s in enumerate(sessions):
        if s.get("wall_time_s") is not None:
            total += float(s["wall_time_s"])
            continue
        measured = False
        start, end = starts[i], starts[i + 1] if i + 1 < len(starts) else None
        if start is None:
            continue
        inside = [t for t in done if t >= start and (end is None or t < end)]
        if inside:
            total += (inside[-1] - start).total_seconds()
    return total, measured


def stamp(store: ResultStore, res: Results, *, generated_at: str | None) -> str:
    """The stamp line of the docs generated from ``store`` (see the module docstring)."""
    meta = store.meta
    sessions = meta.get("sessions", [])
    run_commits = list(dict.fromkeys(_short(s.get("git_commit", meta.get("git_commit")))
                                     for s in sessions)) or [_short(meta.get("git_commit"))]
    versions = list(dict.fromkeys(s.get("versions", meta.get("versions", {})).get("moik", "?")
                                  for s in sessions)) or [meta.get("versions", {}).get("moik", "?")]
    executors = ", ".join(dict.fromkeys(s.get("executor", "?") for s in sessions))
    seconds, measured = wall_time(store, res.ok + res.failed)
    started = (sessions[0].get("started") or "?")[:10] if sessions else "?"
    size = "quick size" if meta.get("quick") else "full size"
    return (f"_Stamp: {meta['experiment']} ({size}) run by moik {', '.join(versions)} at commit "
            f"{', '.join(run_commits)} on {started}; config fingerprint "
            f"{(meta.get('config_fingerprint') or '?')[:12]}; {len(res.ok)} of "
            f"{len(meta.get('trials') or []) or '?'} trials finished; wall time {seconds:.1f} s"
            f"{'' if measured else ' (from the trials timestamps)'} ({executors}); generated by "
            f"`moik report --docs` at commit {_short(generated_at)}_")


def page_name(store: ResultStore) -> str:
    """``NAME`` of ``DOCS/results/NAME.md`` for this results folder.

    Raises:
        ResultsError: An experiment name that cannot name a file (``../x``, a NUL ...).
    """
    name = file_name(store.meta["experiment"], "the experiment name in meta.json")
    return name + ("-quick" if store.meta.get("quick") else "")


@dataclass
class DocsUpdate:
    """What :func:`write_docs` did.

    Attributes:
        pages: The ``DOCS/results/*.md`` files written.
        replaced: ``(experiment, kind)`` of every block of the summary pages regenerated.
        kept: Experiments whose blocks were kept as they are (not among the results).
        block_pages: The summary pages (:data:`SUMMARY_PAGES`) that hold blocks.
        warnings: Folders left out, damaged trials, blocks without a stamp, unknown kinds.
    """

    pages: list[Path] = field(default_factory=list)
    replaced: list[tuple[str, str]] = field(default_factory=list)
    kept: list[str] = field(default_factory=list)
    block_pages: list[Path] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def _warn(update: DocsUpdate, text: str) -> None:
    update.warnings.append(text)
    print(f"moik: warning: {text}", file=sys.stderr)


def _page(store: ResultStore, docs: Path, name: str, line: str, *, figures: bool) -> Path:
    """Write ``DOCS/results/NAME.md`` and its figures; returns the page's path."""
    results = docs / "results"
    fig_dir = results / "figures" / name
    with tempfile.TemporaryDirectory() as tmp:
        drawn: dict[Path, Path] = {}

        def link(png: Path) -> str:
            drawn[png] = fig_dir / png.name
            return (Path("figures") / name / png.name).as_posix()

        section = experiment_section(store, figures=figures, link=link, figure_folder=Path(tmp),
                                     folder_label=store.folder.name)
        inside(docs, fig_dir)
        if fig_dir.is_dir():
            for old in fig_dir.glob("*.png"):
                remove(docs, old)
        if drawn:
            fig_dir.mkdir(parents=True, exist_ok=True)
            for src, dst in drawn.items():
                atomic_write_bytes(dst, src.read_bytes(), folder=docs)
    # no table of contents beside the page (mkdocs-material): its wide tables get the room
    text = (f"---\nhide: [toc]\n---\n\n# {name}: generated results\n\n{md(line)}\n\n"
            "Generated from the stored results by "
            "`moik report RESULTS --docs docs` (do not edit by hand: the next run replaces this "
            "file).\n\n" + section)
    path = results / f"{name}.md"
    inside(docs, results)
    results.mkdir(parents=True, exist_ok=True)
    atomic_write_bytes(path, text.encode(), folder=docs)
    return path


SUMMARY_PAGES = ("reproducing.md", "algorithms.md")
"""Pages of DOCS whose ``generated`` blocks are replaced (absent ones are skipped; a
missing ``reproducing.md`` is warned about)."""


def replace_blocks(text: str, summaries: dict[str, str], update: DocsUpdate,
                   where: str = "reproducing.md") -> str:
    """``text`` with the blocks of the experiments in ``summaries`` replaced by their summary.

    Other blocks are kept; one without a stamp line, or of an unknown kind, is warned about.
    """
    def swap(m: re.Match) -> str:
        name, kind = m["name"], m["kind"]
        if kind not in KINDS:
            _warn(update, f"{where}: block '{name} {kind}' has an unknown kind (expected one "
                          f"of: {', '.join(KINDS)}); kept as it is")
            return m[0]
        if name in summaries:
            update.replaced.append((name, kind))
            return f"<!-- generated: {name} {kind} -->\n{summaries[name]}<!-- end generated -->"
        update.kept.append(name)
        if not STAMP.search(m["body"]):
            _warn(update, f"{where}: block '{name} {kind}' is not regenerated and has no stamp "
                          "line ('_Stamp: ..._'): add one saying which results it came from")
        return m[0]

    return BLOCK.sub(swap, text)


def write_docs(folders, docs: str | Path, *, figures: bool = True,
               force: bool = False) -> DocsUpdate:
    """Regenerate the docs of the experiments in ``folders`` (see the module docstring).

    Args:
        folders: Results folders, or folders of results folders.
        docs: The docs folder (holding ``reproducing.md``, which may be absent).
        figures: Draw the figures (needs matplotlib).
        force: Write them even when moik's code has uncommitted changes (the stamps then
            say ``with uncommitted changes``); refused otherwise, so that committed pages
            name the commit whose code wrote them.

    Returns:
        A :class:`DocsUpdate` (its warnings are also printed on stderr).

    Raises:
        ResultsError: If no results folder among ``folders`` can be read.
        ParameterError: moik's code has uncommitted changes and ``force`` is not set.
    """
    docs, update = Path(docs), DocsUpdate()
    if not docs.is_dir():
        raise ResultsError(f"the docs folder {str(docs)!r} does not exist (or is not a folder): "
                           "give the docs folder that holds reproducing.md")
    summaries: dict[str, str] = {}
    generated_at = git_commit()
    if generated_at is not None and generated_at.endswith("-dirty") and not force:
        raise ParameterError("moik's code (moik/, experiments/, pyproject.toml) has uncommitted "
                             "changes: commit them first, so that the pages' stamps name the "
                             "code that wrote them (or force it: --force, force=True)")
    subs = []
    for folder in folders:
        try:
            subs += result_folders(folder)
        except ResultsError as exc:
            _warn(update, str(exc))
    used = 0
    for sub in subs:
        try:
            store = ResultStore.open(sub, verify=True)
            if store.damaged:
                _warn(update, f"{sub}: {damaged_warning(store)}")
            res = Results(store)
            line = stamp(store, res, generated_at=generated_at)
            name = page_name(store)
            update.pages.append(_page(store, docs, name, line, figures=figures))
            body = "\n".join(map(md, headline(res))).rstrip("\n")
            if store.meta["experiment"] in summaries:
                _warn(update, f"{sub}: a second results folder of {store.meta['experiment']!r}; "
                              "its summary replaces the earlier one's")
            summaries[store.meta["experiment"]] = f"{md(line)}\n\n{body}\n"
            used += 1
        except FOLDER_ERRORS as exc:
            _warn(update, f"{sub} left out: {exc.__class__.__name__}: {exc}")
    if not used:
        raise ResultsError("no results folder could be used for the docs: "
                           + ("; ".join(update.warnings) or "none given"))
    for page_file in SUMMARY_PAGES:
        page = docs / page_file
        if page.is_file():
            old = page.read_text()
            new = replace_blocks(old, summaries, update, where=page_file)
            if BLOCK.search(old):
                update.block_pages.append(page)
            if new != old:
                atomic_write_bytes(page, new.encode(), folder=docs)
        elif page_file == SUMMARY_PAGES[0]:
            _warn(update, f"{page} does not exist: only the results pages were written")
    return update
