"""Reading ``results.jsonl`` line by line: which lines are trial records, which are not.

A line is a trial record when it is a JSON object with the fields every trial
record has (:data:`REQUIRED`: ``trial``, ``status``, ``algorithm`` as strings,
``target`` and ``run`` as integers), its trial id the one moik writes from them
(``algorithm/target/run``). Anything else (``{}``, ``[1, 2, 3]``,
``"trial": null``, text that is not JSON, a line torn by a crash) is *malformed*:
it is skipped, and :class:`Lines` says which line and why, so that the caller can
warn with the file and the line number instead of failing on it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from moik import _paths
from moik._validate import reading as _reading
from moik.exceptions import MoikError, ResultsError

REQUIRED = {"trial": str, "status": str, "algorithm": str, "target": int, "run": int}
"""The fields (and their JSON types) every stored trial record has."""


_NUMBER: tuple[type, ...] = (int, float, type(None))
TYPED: dict[str, tuple[type, ...]] = {
    "time": _NUMBER, "n_eval": _NUMBER, "best_f": _NUMBER, "position_error": _NUMBER,
    "orientation_error": _NUMBER, "attempts": _NUMBER, "hv": _NUMBER, "igd": _NUMBER,
    "has_arrays": (bool,), "arrays": (list,), "target_name": (str,), "experiment": (str,),
    "config_fingerprint": (str,), "finished_at": (str, type(None))}
"""The JSON types of the other fields the report reads, where a record has them."""


def record_problem(record: object) -> str | None:
    """Why ``record`` (a parsed line) is not a trial record, or None when it is one."""
    if not isinstance(record, dict):
        return f"a JSON {type(record).__name__}, not an object"
    for key, kind in REQUIRED.items():
        if key not in record:
            return f"no {key!r} field"
        value = record[key]
        if not isinstance(value, kind) or isinstance(value, bool):
            shown = repr(value) if len(repr(value)) <= 60 else repr(value)[:57] + "..."
            return f"{key!r} is {shown}, expected a {kind.__name__}"
    for key, kinds in TYPED.items():
        value = record.get(key)
        if key in record and (not isinstance(value, kinds) or
                              isinstance(value, bool) and bool not in kinds):
            shown = repr(value) if len(repr(value)) <= 60 else repr(value)[:57] + "..."
            return f"{key!r} is {shown}, not of the type moik writes"
    if any(not isinstance(a, str) for a in record.get("arrays", [])):
        return "'arrays' holds entries that are not names"
    try:
        _paths.file_name(record["trial"].replace("/", "__"), "its trial id")
    except ResultsError as exc:
        return str(exc)
    expected = f"{record['algorithm']}/{record['target']}/{record['run']}"
    if record["trial"] != expected:  # moik writes the id from these three
        return (f"trial {record['trial']!r} does not match its algorithm, target and run "
                f"({expected})")
    return None


@dataclass
class Lines:
    """The lines of a ``results.jsonl``.

    Attributes:
        records: The trial records, in file order (repeated trial ids included).
        numbers: The line number of each record.
        malformed: ``(line number, why)`` of every line that is no trial record
            (line numbers from 1; a torn last line without newline is not included).
        torn_tail: Whether the file ends in a line without newline (a crash mid-append).
    """

    records: list[dict] = field(default_factory=list)
    numbers: list[int] = field(default_factory=list)
    malformed: list[tuple[int, str]] = field(default_factory=list)
    torn_tail: bool = False

    def describe(self, path: Path, shown: int = 5) -> str:
        """One sentence naming the malformed lines of ``path`` (empty when there are none)."""
        if not self.malformed:
            return ""
        listed = "; ".join(f"line {n}: {why}" for n, why in self.malformed[:shown])
        more = f"; and {len(self.malformed) - shown} more" if len(self.malformed) > shown else ""
        return (f"{path}: skipped {len(self.malformed)} malformed line(s) that are not trial "
                f"records ({listed}{more})")


def read_lines(path: Path) -> Lines:
    """Parse ``path`` (missing: no lines) into trial records and malformed lines.

    Raises:
        ResultsError: ``path`` is not a regular file, or cannot be read.
    """
    out = Lines()
    if not path.exists() and not path.is_symlink():
        return out
    if path.is_symlink():
        raise ResultsError(f"{str(path)!r} is a symbolic link; moik reads and appends to "
                           "the results.jsonl of the folder itself only: remove it")
    data = _reading.read_bytes(path, "results file", ResultsError, limit=2**32)
    lines = data.split(b"\n")
    out.torn_tail = lines[-1] != b""
    for number, line in enumerate(lines[:-1], start=1):
        if not line.strip():
            out.malformed.append((number, "an empty line"))
            continue
        try:
            record = _reading.parse_json(line, "the line", ResultsError)
        except MoikError as exc:
            text = str(exc).removeprefix("the line ")
            text = text.split(": ", 1)[1].split(":")[0] if "not valid JSON" in text else text
            out.malformed.append((number, f"not JSON ({text[:100]})"))
            continue
        why = record_problem(record)
        if why is None:
            out.records.append(record)
            out.numbers.append(number)
        else:
            out.malformed.append((number, why))
    return out
