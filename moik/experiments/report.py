"""``moik report DIR``: a Markdown report of one or several results folders.

``DIR`` is a results folder (it has ``meta.json``) or a folder of results
folders (``results/`` after several ``moik experiment run``). With ``--docs``
the command writes the project's docs instead (:mod:`moik.experiments.docs`).
The report,
``DIR/report.md``, has per experiment: its source and configuration, the run's
metadata (versions, commit, machine, executors), the tables of its analyses
with the paper's numbers side by side, and the figures (``figures/`` beside
each results folder) when :mod:`moik.plotting` can draw them.

Damaged results do not stop a report: trials whose arrays are damaged or
missing are left out (the counts say what is really there) with a warning in
the section and on stderr, so are malformed lines of ``results.jsonl`` (named by
line number), and a folder that cannot be read at all gets a
section saying why while the others are reported.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from moik._paths import inside
from moik.exceptions import MoikError, ResultsError
from moik.experiments.analysis import analyze
from moik.experiments.figures import make_figures
from moik.experiments.files import atomic_write_bytes
from moik.experiments.kinds.ik_robot import describe
from moik.experiments.records import read_lines
from moik.experiments.registry import experiment_files
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results, Table


def result_folders(folder: str | Path) -> list[Path]:
    """``folder`` itself if it is a results folder, else its results sub-folders.

    A sub-folder counts if it has a ``meta.json`` or a ``results.jsonl`` (a results
    folder that lost its metadata is reported as unreadable, not silently skipped).

    Raises:
        ResultsError: If neither holds a ``meta.json``.
    """
    folder = Path(folder)
    if (folder / "meta.json").is_file():
        return [folder]
    subs = sorted({p.parent for name in ("meta.json", "results.jsonl")
                   for p in folder.glob(f"*/{name}")}) if folder.is_dir() else []
    if not subs:
        raise ResultsError(f"{str(folder)!r} holds no moik results (no meta.json in it or in "
                           "its sub-folders); run `moik experiment run NAME --out DIR` first")
    return subs


_TAG = re.compile(r"<(?=[A-Za-z/!?])")


def md(text: object) -> str:
    """``text`` (from a results folder or a config: data, not markup) made safe to put in
    a line of Markdown: on one line, no HTML tag or comment (``<x`` becomes ``&lt;x``) and
    no inline link (``](`` becomes ``]\\(``). Other text is kept as it is."""
    one_line = " ".join(str(text).splitlines()) if text is not None else "None"
    return _TAG.sub("&lt;", one_line).replace("](", "]\\(")


def _code(text: object) -> str:
    """``text`` inside a Markdown code span (a backtick would end it)."""
    return str(text).replace("`", "'")


def _escape(cell: str) -> str:
    return md(cell).replace("|", "\\|")


def table_markdown(table: Table) -> str:
    """A :class:`Table` as a Markdown section (every text escaped: :func:`md`)."""
    lines = [f"#### {md(table.title)}", "", "| " + " | ".join(map(_escape, table.header))
             + " |", "|" + "|".join("---" for _ in table.header) + "|"]
    lines += ["| " + " | ".join(_escape(c) for c in row) + " |" for row in table.rows]
    lines += [""] + [f"- {md(n)}" for n in table.notes]
    return "\n".join(lines) + "\n"


def experiment_section(store: ResultStore, *, figures: bool, link: Callable[[Path], str],
                       figure_folder: Path | None = None, folder_label: str | None = None
                       ) -> str:
    """The report section of one results folder (Markdown).

    Args:
        store: The opened results folder.
        figures: Draw the figures.
        link: Figure PNG path -> the link written in the section (relative to the file
            that holds the section; :mod:`moik.experiments.docs` copies the file there).
        figure_folder: Where the figures are drawn (default ``store.folder/figures``).
        folder_label: How the results folder is named (default its path; the docs give its
            name alone: a committed page holds no path of the machine that wrote it).
    """
    res, tables = analyze(store)
    meta, cfg = store.meta, store.meta["config"]
    size = "quick size" if meta.get("quick") else "full size"
    algs = ", ".join(meta.get("algorithms", []))
    if meta.get("skipped_algorithms"):
        algs += (" (not registered, left out: " + ", ".join(meta["skipped_algorithms"]) + ")")
    sess = meta.get("sessions", [])
    versions, machine = meta.get("versions", {}), meta.get("machine", {})
    lines = [f"## {cfg['name']}: {cfg['title']} ({size})", "",
             f"- source: {cfg['source']}",
             (f"- benchmark problems {', '.join(t['name'] for t in meta['targets'])}, "
              + (f"{cfg['problem']['evaluations']} evaluations per run, "
                 if cfg["problem"].get("evaluations") else "")
              if cfg["problem"]["kind"] in ("benchmark", "moo-benchmark") else
              f"- robot {describe(cfg['robot'])}, problem `{cfg['problem']['kind']}`"
              + ("" if cfg["problem"]["kind"] == "position" else
                 f" (orientation `{cfg['problem'].get('orientation')}`)") + ", ")
             + f"{len(meta['targets'])} target(s), runs per target {cfg['runs']}, "
             f"population {cfg['pop_size']}, "
             + ("" if cfg["problem"].get("evaluations")
                else f"iterations {cfg['iterations']}, ")
             + f"seed {cfg['seed']}",
             f"- algorithms: {algs}",
             f"- moik {versions.get('moik', '?')}, pymoo {versions.get('pymoo', '?')}, numpy "
             f"{versions.get('numpy', '?')}, commit {meta.get('git_commit') or 'unknown'}; "
             f"machine {machine.get('hostname', '?')} ({machine.get('platform', '?')}, "
             f"{machine.get('cpu_count', '?')} cores)",
             "- sessions: " + "; ".join(f"{s.get('started', '?')} ({s.get('executor', '?')})"
                                        for s in sess),
             f"- results folder: `{_code(folder_label or store.folder)}`"]
    lines = [md(line) for line in lines]
    lines += [f"- {md(n)}" for n in res.notes()]
    if store.damaged:
        lines.append(f"- **warning**: {md(damaged_warning(store))}")
    if store.malformed:
        lines.append(f"- **warning**: {md(malformed_warning(store))}")
    lines.append("")
    lines += [table_markdown(t) for t in tables]
    if figures:
        if figure_folder is None:
            figure_folder = inside(store.folder, store.folder / "figures")
        made, notes = _figures(res, figure_folder)
        for caption, png in made:
            lines.append(f"![{md(caption).replace(']', '')}]({link(png)})\n")
        lines += [f"- {md(n)}" for n in notes]
    return "\n".join(lines) + "\n"


def _relative(png: Path, base: Path) -> str:
    return (png.relative_to(base) if png.is_relative_to(base) else png).as_posix()


def _figures(res: Results, folder: Path):
    if not res.ok:
        return [], ["no finished trials: no figures"]
    if res.config["problem"]["kind"] == "moo-benchmark":
        return [], ["multi-objective benchmark experiments have tables only"]
    return make_figures(res, folder)


def rerun_command(store: ResultStore) -> str:
    """The command that resumes ``store``'s run: by name for a shipped experiment, else
    ``--config FILE`` (a user's config file has no name ``moik experiment run`` knows)."""
    meta = store.meta
    name, path = meta.get("experiment", "NAME"), meta.get("config_path")
    shipped = experiment_files().get(name)
    same = path is None or (shipped is not None and Path(path).resolve() == shipped.resolve())
    which = name if same and shipped is not None else (f"--config {path}" if path else name)
    return (f"moik experiment run {which}{' --quick' if meta.get('quick') else ''} "
            f"--out {store.folder} --resume")


def damaged_warning(store: ResultStore) -> str:
    """One sentence naming the trials of ``store`` left out for damaged or missing arrays."""
    n = len(store.damaged)
    shown = "; ".join(list(store.damaged.values())[:5]) + ("; ..." if n > 5 else "")
    return (f"{n} trial(s) left out: their arrays are damaged or missing ({shown}); "
            f"`{rerun_command(store)}` runs them again")


def malformed_warning(store: ResultStore) -> str:
    """One sentence naming the malformed lines of ``store``'s results.jsonl (skipped)."""
    return read_lines(store.results_path).describe(store.results_path)


@dataclass
class Report:
    """What :func:`make_report` wrote.

    Attributes:
        path: The report file.
        warnings: Damaged or missing trials, per folder (the report goes on without them).
        failed: Folders that could not be reported, each with the reason.
    """

    path: Path
    warnings: list[str] = field(default_factory=list)
    failed: list[str] = field(default_factory=list)


FOLDER_ERRORS = (MoikError, OSError, ValueError, KeyError, TypeError, IndexError, AttributeError)
"""What reading or analysing one damaged folder may raise (a report goes on past it)."""


def make_report(folder: str | Path, *, figures: bool = True,
                output: str | Path | None = None) -> Report:
    """Write the Markdown report of ``folder``; one bad results folder does not stop it.

    A report writes into each results folder (its figures): a sub-folder of ``folder`` that
    is a symbolic link is not followed (reported as failed), so nothing is written outside
    the folder given.

    Args:
        folder: A results folder or a folder of results folders.
        figures: Draw the figures (needs matplotlib).
        output: Report file (default ``folder/report.md``).

    Returns:
        A :class:`Report` (warnings and failed folders are also printed on stderr).

    Raises:
        ResultsError: If ``folder`` holds no results, or no folder in it can be read.
    """
    base = Path(folder)
    out = Path(output) if output is not None else base / "report.md"
    if output is None:
        inside(base, out)
    report = Report(out)
    parts = ["# moik reproduction report", "",
             "Tables put moik's numbers (source `moik`) beside the paper's (source = the "
             "paper's table). Times are wall-clock seconds per trial on the machine named in "
             "each section, without the process's one-off kernel load (each process runs "
             "an untimed one-iteration warm-up of each algorithm and problem first); the "
             "papers' times are MATLAB times on theirs.", ""]
    subs = result_folders(base)
    for sub in subs:
        if sub != base and sub.is_symlink():  # its figures would be written where it points
            why = "a symbolic link to another folder (not followed: the report writes into it)"
            report.failed.append(f"{sub}: {why}")
            print(f"moik: warning: {sub} not reported: {why}", file=sys.stderr)
            parts.append(md(f"## {sub.name}: not reported") + "\n\n"
                         + md(f"- `{sub}`: {why}") + "\n")
            continue
        try:
            store = ResultStore.open(sub, verify=True)
            if store.damaged:
                report.warnings.append(f"{sub}: {damaged_warning(store)}")
                print(f"moik: warning: {sub}: {damaged_warning(store)}", file=sys.stderr)
            parts.append(experiment_section(store, figures=figures,
                                            link=lambda png: _relative(png, out.parent)))
            if store.malformed:
                report.warnings.append(malformed_warning(store))
        except FOLDER_ERRORS as exc:
            why = f"{exc.__class__.__name__}: {exc}"
            report.failed.append(f"{sub}: {why}")
            print(f"moik: warning: {sub} not reported: {why}", file=sys.stderr)
            parts.append(md(f"## {sub.name}: not reported") + "\n\n" +
                         md(f"- `{sub}` could not be read or analysed: {why}") + "\n")
    if len(report.failed) == len(subs):
        raise ResultsError("no results folder could be reported: " + "; ".join(report.failed))
    atomic_write_bytes(out, "\n".join(parts).encode(), folder=base if output is None else None)
    return report


def write_report(folder: str | Path, *, figures: bool = True,
                 output: str | Path | None = None) -> Path:
    """Write the Markdown report of ``folder`` and return its path (see :func:`make_report`).

    Raises:
        ResultsError: If ``folder`` holds no results, or no folder in it can be read.
    """
    return make_report(folder, figures=figures, output=output).path
