"""Folders without a usable ``meta.json``: whether their trials may be kept.

``meta.json`` says which configuration a folder's trials belong to. When it is
gone or damaged, the trials are never deleted and never relabelled: a run without
``--resume`` is refused (saying how to recover), and ``--resume`` adopts them only
when every stored line carries the fingerprint of the configuration being run
(each line records ``experiment`` and ``config_fingerprint``). A damaged
``meta.json`` is kept beside as ``meta.json.damaged``.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
from pathlib import Path

from moik._paths import file_name
from moik._validate import unknown_keys_message
from moik.exceptions import ResultsError
from moik.experiments.records import read_lines

META_REQUIRED = {"experiment": str, "config_fingerprint": str, "config": dict}
"""The ``meta.json`` fields a run needs to resume a folder (with their JSON types)."""


def stored_fingerprint(meta: dict) -> str | None:
    """The configuration fingerprint recomputed from ``meta["config"]`` and
    ``meta["algorithms"]`` (the formula of ``ExperimentConfig.fingerprint``), or None."""
    if not isinstance(meta.get("config"), dict) or not isinstance(meta.get("algorithms"), list):
        return None
    text = json.dumps([meta["config"], meta["algorithms"]], sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def repair_meta(meta: dict) -> list[str]:
    """Restores what a damaged ``meta.json`` lost and can be rebuilt from the rest (in place):
    the fingerprint (from the stored config) and the session list. Returns what it did."""
    notes = []
    if "config_fingerprint" not in meta and stored_fingerprint(meta) is not None:
        meta["config_fingerprint"] = stored_fingerprint(meta)
        notes.append("meta.json had no config_fingerprint: recomputed it from its stored config")
    if not isinstance(meta.get("sessions"), list):
        notes.append(f"meta.json had no session list (sessions = {meta.get('sessions')!r}): "
                     "started a new one")
        meta["sessions"] = []
    return notes


META_KEYS = ("format", "experiment", "quick", "config_path", "config", "config_fingerprint",
             "algorithms", "skipped_algorithms", "created", "versions", "git_commit", "machine",
             "sessions", "targets", "trials", "adopted", "robot")
"""Every key moik writes in ``meta.json`` (any other is refused, naming the nearest)."""
READ_REQUIRED = {"experiment": str, "config": dict, "targets": list}
"""The ``meta.json`` fields every reader needs (the fingerprint and sessions are repairable)."""
CONFIG_REQUIRED = {"name": str, "title": str, "source": str, "problem": dict}
"""The fields of ``meta.json``'s stored config the report reads."""


def meta_problem(meta: dict, *, reading: bool = False) -> str | None:
    """What makes ``meta`` unusable (a missing or mistyped field), or None.

    Args:
        meta: The parsed ``meta.json``.
        reading: Check only what a reader needs (:data:`READ_REQUIRED`); else also what
            resuming needs (:data:`META_REQUIRED`).
    """
    unknown = unknown_keys_message("meta.json", meta, META_KEYS)
    if unknown is not None:
        return "has " + unknown.removeprefix("meta.json: ")
    required = READ_REQUIRED if reading else {**META_REQUIRED, **READ_REQUIRED}
    for key, kind in required.items():
        if key not in meta:
            return f"lacks {key!r}"
        if not isinstance(meta[key], kind):
            return f"has {key!r} = {_short(meta[key])}, expected a {kind.__name__}"
    for key, kind in CONFIG_REQUIRED.items():
        value = meta["config"].get(key)
        if not isinstance(value, kind):
            return f"has a config whose {key!r} is {_short(value)}, expected a {kind.__name__}"
    try:
        file_name(meta["experiment"], "its experiment name")
    except ResultsError as exc:
        return f"has {exc}"
    return _optional_problem(meta)


OPTIONAL_TYPES = {"quick": bool, "versions": dict, "machine": dict, "sessions": list,
                  "trials": list, "algorithms": list, "skipped_algorithms": list,
                  "config_fingerprint": str, "robot": dict}
"""The types of the other ``meta.json`` fields, where present."""


SESSION_TYPES: dict[str, tuple[type, ...]] = {
    "started": (str,), "finished": (str,), "executor": (str,), "git_commit": (str, type(None)),
    "wall_time_s": (int, float, type(None)), "trials_run": (int,), "versions": (dict,)}
"""The types of the fields of a session entry, where present."""


def _optional_problem(meta: dict) -> str | None:
    for key, kind in OPTIONAL_TYPES.items():
        if key in meta and not isinstance(meta[key], kind):
            return f"has {key!r} = {_short(meta[key])}, expected a {kind.__name__}"
    for key in ("targets", "sessions", "trials"):
        if any(not isinstance(item, dict) for item in meta.get(key, [])):
            return f"has a {key!r} entry that is not an object"
    if any(not isinstance(t.get("name"), str) for t in meta["targets"]):
        return "has a target without a name (string)"
    for target in meta["targets"]:
        problem = _target_problem(target)
        if problem is not None:
            return f"has target {_short(target['name'])} whose {problem}"
    for key in ("algorithms", "skipped_algorithms"):
        if any(not isinstance(a, str) for a in meta.get(key, [])):
            return f"has {key!r} entries that are not names (strings)"
    for session in meta.get("sessions", []):
        for key, kinds in SESSION_TYPES.items():
            if key in session and (not isinstance(session[key], kinds)
                                   or isinstance(session[key], bool)):
                return f"has a session whose {key!r} is {_short(session[key])}"
    for key in ("versions", "machine"):
        if any(not isinstance(v, (str, int, float, type(None))) or isinstance(v, bool)
               for v in meta.get(key, {}).values()):
            return f"has {key!r} values that are not text or numbers"
    return None


def _numbers(value: object, shape: tuple[int, ...]) -> bool:
    """Whether ``value`` is nested lists of finite numbers (not booleans) of ``shape``."""
    if not shape:
        return (isinstance(value, (int, float)) and not isinstance(value, bool)
                and math.isfinite(value))
    return (isinstance(value, list) and len(value) == shape[0]
            and all(_numbers(v, shape[1:]) for v in value))


def _target_problem(target: dict) -> str | None:
    """What makes a ``meta.json`` IK target entry unreadable (as moik writes it: ``position``
    3 numbers, ``rotation`` None or 3 x 3 numbers, ``hv_ref_point`` None or numbers), or None.
    A benchmark function's entry (``benchmark``: the functions kinds) has none of these."""
    if "benchmark" in target:
        return None
    if "position" not in target:
        return "'position' is missing"
    if not _numbers(target["position"], (3,)):
        return f"'position' is {_short(target['position'])}, expected 3 finite numbers"
    rotation = target.get("rotation")
    if rotation is not None and not _numbers(rotation, (3, 3)):
        return f"'rotation' is {_short(rotation)}, expected null or 3 x 3 finite numbers"
    ref = target.get("hv_ref_point")
    if ref is not None and not (isinstance(ref, list) and ref
                                and all(_numbers(v, ()) for v in ref)):
        return f"'hv_ref_point' is {_short(ref)}, expected null or finite numbers"
    return None


def _short(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def adopt(folder: Path, config, problem: str, resume: bool) -> list[str]:
    """Whether the trials of a folder without a usable ``meta.json`` may be kept for a run
    of ``config`` (only on ``--resume``, and only if every line names this configuration).

    A damaged ``meta.json`` is kept as ``meta.json.damaged`` (never overwritten silently).
    Returns the notes saying what was done.

    Raises:
        ResultsError: Without ``resume``, or when a line was written by another
            configuration (or by a moik that did not record it), or when ``results.jsonl``
            holds lines but no trial record (another program's file): nothing is changed.
    """
    lines = read_lines(folder / "results.jsonl")
    where = str(folder)
    notes = []
    if not lines.records and (lines.malformed or lines.torn_tail):
        raise ResultsError(
            f"{where!r} holds a results.jsonl with no moik trial record "
            f"({lines.describe(folder / 'results.jsonl', shown=2) or 'one torn line'}) and "
            f"{problem}: it is not moik's, and moik does not write into it; nothing was "
            "changed: choose another --out folder, or move results.jsonl away")
    if lines.records:
        what = (f"{where!r} holds {len(lines.records)} trial record(s) in results.jsonl but "
                f"{problem}; nothing was changed")
        if not resume:
            raise ResultsError(
                f"{what}. To keep them, run the same experiment with --resume (it adopts "
                "the trials when every line was written by this configuration); otherwise "
                "choose another --out folder, or move results.jsonl away")
        fingerprint = config.fingerprint()
        foreign: dict[str, int] = {}
        for rec in lines.records:
            if rec.get("config_fingerprint") != fingerprint:
                key = (f"{rec.get('experiment', '?')!r} (configuration "
                       f"{str(rec['config_fingerprint'])[:12]})"
                       if rec.get("config_fingerprint") else "no configuration fingerprint "
                       "(written by an older moik)")
                foreign[key] = foreign.get(key, 0) + 1
        if foreign:
            found = "; ".join(f"{n} line(s) of {k}" for k, n in foreign.items())
            raise ResultsError(
                f"{what}. Cannot adopt them for {config.name!r} (configuration "
                f"{fingerprint[:12]}): {found}. Restore meta.json, or resume with the "
                "configuration that wrote them, or choose another --out folder")
        notes.append(f"adopted {len(lines.records)} stored trial record(s) of "
                     f"{config.name!r} (every line carries this configuration's fingerprint)"
                     f" although {problem}; meta.json rebuilt")
    damaged = folder / "meta.json"
    if damaged.exists():
        keep = folder / "meta.json.damaged"
        n = 1
        while keep.exists():
            n += 1
            keep = folder / f"meta.json.damaged{n}"
        os.replace(damaged, keep)
        notes.append(f"kept the unusable meta.json as {keep.name}")
    return notes
