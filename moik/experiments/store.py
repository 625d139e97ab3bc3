"""The results folder of an experiment run.

Layout (format ``moik-results/1``)::

    OUT/meta.json         experiment name, config (as run) and its fingerprint, quick flag,
                          versions (moik, pymoo, numpy, scipy, python), git commit, machine,
                          targets, every planned trial with its seeds, one entry per session
    OUT/results.jsonl     one JSON object per finished trial (scalars, seeds, status)
    OUT/arrays/ID.npz     that trial's arrays (convergence curve, front, best x)

Why JSON lines + .npz: both are standard (``pandas.read_json(lines=True)``,
``numpy.load``), append-friendly and human-readable where it matters.

Crash safety: ``meta.json`` and each ``.npz`` are written to a temporary file
and moved into place with ``os.replace`` (atomic). A trial's line is appended
after its arrays are in place, with one ``write`` on an ``O_APPEND``
descriptor followed by ``fsync``: the line is the commit mark of the trial. A
line torn by a crash (no trailing newline, or not valid JSON) is ignored when
reading and cut off before the next append, so an interruption loses at most
the trials in flight. Non-finite floats are stored as ``null``.
"""

from __future__ import annotations

import datetime as _dt
import io
import json
import math
import os
import platform
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pymoo
import scipy

from moik._version import __version__
from moik.exceptions import ResultsError

FORMAT = "moik-results/1"


def _now() -> str:
    return _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds")


def _clean(value):
    """JSON-ready copy: numpy scalars to Python, non-finite floats to None."""
    if isinstance(value, dict):
        return {str(k): _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    if isinstance(value, np.ndarray):
        return _clean(value.tolist())
    if isinstance(value, (np.integer, np.bool_)):
        return value.item()
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    return value


def atomic_write_bytes(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically (temporary file + ``os.replace``)."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with open(tmp, "wb") as fh:
        fh.write(data)
        fh.flush()
        os.fsync(fh.fileno())
    os.replace(tmp, path)


def environment() -> dict:
    """Versions, git commit and machine description for the metadata.

    The commit is that of the git checkout holding this moik (None for an installed wheel).
    """
    commit = None
    try:
        root = Path(__file__).resolve().parents[2]
        out = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True,
                             text=True, timeout=5, check=False)
        if out.returncode == 0:
            commit = out.stdout.strip()
            dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "-uno"],
                                   capture_output=True, text=True, timeout=5, check=False)
            if dirty.stdout.strip():
                commit += "-dirty"
    except (OSError, subprocess.SubprocessError):
        commit = None
    return {
        "versions": {"moik": __version__, "pymoo": pymoo.__version__,
                     "numpy": np.__version__, "scipy": scipy.__version__,
                     "python": platform.python_version()},
        "git_commit": commit,
        "machine": {"hostname": socket.gethostname(), "platform": platform.platform(),
                    "processor": platform.processor() or platform.machine(),
                    "cpu_count": os.cpu_count()},
    }


class ResultStore:
    """Reader/writer of one results folder (see the module docstring).

    Build with :meth:`create` (to run an experiment) or :meth:`open` (to read).
    """

    def __init__(self, folder: Path, meta: dict):
        self.folder = Path(folder)
        self.meta = meta
        self._fd: int | None = None

    @property
    def results_path(self) -> Path:
        """``OUT/results.jsonl``."""
        return self.folder / "results.jsonl"

    @classmethod
    def open(cls, folder: str | Path) -> ResultStore:
        """Open an existing results folder for reading.

        Raises:
            ResultsError: If ``folder`` has no readable ``meta.json``.
        """
        folder = Path(folder)
        try:
            meta = json.loads((folder / "meta.json").read_text())
        except (OSError, ValueError) as exc:
            raise ResultsError(f"{str(folder)!r} is not a moik results folder (meta.json: "
                               f"{exc.__class__.__name__})") from None
        if meta.get("format") != FORMAT:
            raise ResultsError(f"{folder}/meta.json has format {meta.get('format')!r}, "
                               f"expected {FORMAT!r}")
        return cls(folder, meta)

    @classmethod
    def create(cls, folder: str | Path, *, config, targets: list[dict], trials: list[dict],
               resume: bool, session: dict) -> ResultStore:
        """Prepare ``folder`` for a run of ``config`` (a new one, or a resumed one).

        Raises:
            ResultsError: If the folder holds results and ``resume`` is False, or
                ``resume`` is True and the stored configuration differs.
        """
        folder = Path(folder)
        env = environment()
        entry = {"started": _now(), **session, **env}
        if (folder / "meta.json").exists():
            old = cls.open(folder)
            has_results = old.results_path.exists() and old.results_path.stat().st_size > 0
            if not resume and has_results:
                raise ResultsError(f"{str(folder)!r} already holds results of "
                                   f"{old.meta['experiment']!r}; pass --resume to continue them "
                                   "or choose another --out folder")
            if resume and old.meta["config_fingerprint"] != config.fingerprint():
                raise ResultsError(f"{str(folder)!r} holds results of another configuration "
                                   f"({old.meta['experiment']!r}, quick={old.meta['quick']}); "
                                   "cannot resume with this one")
            if resume:
                old.meta["sessions"].append(entry)
                old._write_meta()
                old._repair_tail()
                return old
        (folder / "arrays").mkdir(parents=True, exist_ok=True)
        if not resume:
            for stale in (folder / "results.jsonl",):
                stale.unlink(missing_ok=True)
        meta = {"format": FORMAT, "experiment": config.name, "quick": config.is_quick,
                "config_path": config.path, "config": config.raw,
                "config_fingerprint": config.fingerprint(), "algorithms": config.labels,
                "skipped_algorithms": list(config.skipped), "created": _now(), **env,
                "sessions": [entry], "targets": targets, "trials": trials}
        store = cls(folder, _clean(meta))
        store._write_meta()
        return store

    def _write_meta(self) -> None:
        data = json.dumps(_clean(self.meta), indent=1, allow_nan=False).encode()
        atomic_write_bytes(self.folder / "meta.json", data)

    def _repair_tail(self) -> None:
        """Cut a torn last line (crash during an append) before appending more."""
        path = self.results_path
        if not path.exists():
            return
        data = path.read_bytes()
        if data and not data.endswith(b"\n"):
            atomic_write_bytes(path, data[: data.rfind(b"\n") + 1])

    @staticmethod
    def array_name(trial_id: str) -> str:
        """File name of a trial's arrays (``/`` in the id becomes ``__``)."""
        return trial_id.replace("/", "__") + ".npz"

    def append(self, record: dict, arrays: dict) -> None:
        """Store one finished trial: its arrays (atomic), then its line (commit mark)."""
        record = dict(record, finished_at=_now(), has_arrays=bool(arrays))
        if arrays:
            buf = io.BytesIO()
            np.savez(buf, **{k: np.asarray(v) for k, v in arrays.items()})
            atomic_write_bytes(self.folder / "arrays" / self.array_name(record["trial"]),
                               buf.getvalue())
        line = (json.dumps(_clean(record), allow_nan=False) + "\n").encode()
        if self._fd is None:
            self._fd = os.open(self.results_path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        os.write(self._fd, line)
        os.fsync(self._fd)

    def close(self) -> None:
        """Close the append descriptor (appending reopens it)."""
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None

    def records(self) -> list[dict]:
        """The stored trial records, the last one per trial id, in file order."""
        if not self.results_path.exists():
            return []
        by_id: dict[str, dict] = {}
        for line in self.results_path.read_bytes().split(b"\n")[:-1]:
            try:
                rec = json.loads(line)
            except ValueError:
                print(f"moik: warning: skipping a damaged line in {self.results_path}",
                      file=sys.stderr)
                continue
            by_id.pop(rec["trial"], None)
            by_id[rec["trial"]] = rec
        return list(by_id.values())

    def finished_ids(self) -> set[str]:
        """Ids of trials stored with status ``ok`` and their arrays in place."""
        return {r["trial"] for r in self.records() if r.get("status") == "ok" and (
            not r.get("has_arrays") or (self.folder / "arrays" / self.array_name(r["trial"])
                                        ).exists())}

    def load_arrays(self, trial_id: str) -> dict[str, np.ndarray]:
        """The arrays of a trial (empty dict if it stored none)."""
        path = self.folder / "arrays" / self.array_name(trial_id)
        if not path.exists():
            return {}
        with np.load(path) as data:
            return {k: data[k] for k in data.files}
