"""``moik report DIR``: a Markdown report of one or several results folders.

``DIR`` is a results folder (it has ``meta.json``) or a folder of results
folders (``results/`` after several ``moik experiment run``). The report,
``DIR/report.md``, has per experiment: its source and configuration, the run's
metadata (versions, commit, machine, executors), the tables of its analyses
with the paper's numbers side by side, and the figures (``figures/`` beside
each results folder) when :mod:`moik.plotting` can draw them.
"""

from __future__ import annotations

from pathlib import Path

from moik.exceptions import ResultsError
from moik.experiments.analysis import analyze
from moik.experiments.figures import make_figures
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results, Table


def result_folders(folder: str | Path) -> list[Path]:
    """``folder`` itself if it is a results folder, else its results sub-folders.

    Raises:
        ResultsError: If neither holds a ``meta.json``.
    """
    folder = Path(folder)
    if (folder / "meta.json").is_file():
        return [folder]
    subs = sorted(p.parent for p in folder.glob("*/meta.json")) if folder.is_dir() else []
    if not subs:
        raise ResultsError(f"{str(folder)!r} holds no moik results (no meta.json in it or in "
                           "its sub-folders); run `moik experiment run NAME --out DIR` first")
    return subs


def _escape(cell: str) -> str:
    return cell.replace("|", "\\|")


def table_markdown(table: Table) -> str:
    """A :class:`Table` as a Markdown section."""
    lines = [f"#### {table.title}", "", "| " + " | ".join(table.header) + " |",
             "|" + "|".join("---" for _ in table.header) + "|"]
    lines += ["| " + " | ".join(_escape(c) for c in row) + " |" for row in table.rows]
    lines += [""] + [f"- {n}" for n in table.notes]
    return "\n".join(lines) + "\n"


def _section(store: ResultStore, base: Path, *, figures: bool) -> str:
    res, tables = analyze(store)
    meta, cfg = store.meta, store.meta["config"]
    size = "quick size" if meta.get("quick") else "full size"
    algs = ", ".join(meta.get("algorithms", []))
    if meta.get("skipped_algorithms"):
        algs += (" (not registered, left out: " + ", ".join(meta["skipped_algorithms"]) + ")")
    sess = meta["sessions"]
    lines = [f"## {cfg['name']}: {cfg['title']} ({size})", "",
             f"- source: {cfg['source']}",
             (f"- benchmark problems {', '.join(t['name'] for t in meta['targets'])}, "
              if cfg["problem"]["kind"] == "benchmark" else
              f"- robot `{cfg['robot']}`, problem `{cfg['problem']['kind']}`"
              + ("" if cfg["problem"]["kind"] == "position" else
                 f" (orientation `{cfg['problem'].get('orientation')}`)") + ", ")
             + f"{len(meta['targets'])} target(s), runs per target {cfg['runs']}, "
             f"population {cfg['pop_size']}, generations {cfg['n_gen']}, seed {cfg['seed']}",
             f"- algorithms: {algs}",
             f"- moik {meta['versions']['moik']}, pymoo {meta['versions']['pymoo']}, numpy "
             f"{meta['versions']['numpy']}, commit {meta.get('git_commit') or 'unknown'}; "
             f"machine {meta['machine']['hostname']} ({meta['machine']['platform']}, "
             f"{meta['machine']['cpu_count']} cores)",
             "- sessions: " + "; ".join(f"{s['started']} ({s.get('executor', '?')})"
                                        for s in sess),
             f"- results folder: `{store.folder}`"]
    lines += [f"- {n}" for n in res.notes()] + [""]
    lines += [table_markdown(t) for t in tables]
    if figures:
        made, notes = _figures(res, store.folder / "figures")
        for caption, png in made:
            rel = png.relative_to(base) if png.is_relative_to(base) else png
            lines.append(f"![{caption}]({rel.as_posix()})\n")
        lines += [f"- {n}" for n in notes]
    return "\n".join(lines) + "\n"


def _figures(res: Results, folder: Path):
    if not res.ok:
        return [], ["no finished trials: no figures"]
    if res.config["problem"]["kind"] == "benchmark":
        return [], ["benchmark experiments have tables only (the figures draw robots/targets)"]
    return make_figures(res, folder)


def write_report(folder: str | Path, *, figures: bool = True,
                 output: str | Path | None = None) -> Path:
    """Write the Markdown report of ``folder`` and return its path.

    Args:
        folder: A results folder or a folder of results folders.
        figures: Draw the figures (needs matplotlib).
        output: Report file (default ``folder/report.md``).

    Raises:
        ResultsError: If ``folder`` holds no results.
    """
    base = Path(folder)
    stores = [ResultStore.open(p) for p in result_folders(base)]
    out = Path(output) if output is not None else base / "report.md"
    parts = ["# moik reproduction report", "",
             "Tables put moik's numbers (source `moik`) beside the paper's (source = the "
             "paper's table). Times are wall-clock seconds per trial on the machine named in "
             "each section; the papers' times are MATLAB times on theirs.", ""]
    parts += [_section(s, out.parent, figures=figures) for s in stores]
    out.write_text("\n".join(parts))
    return out
