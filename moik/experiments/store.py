"""The results folder of an experiment run.

Layout (format ``moik-results/1``)::

    OUT/meta.json         experiment name, config (as run) and its fingerprint, quick flag,
                          the URDF arm it ran on (``robot``: the file's absolute path and
                          SHA-256, :mod:`moik.experiments.kinds.ik_robot`; catalog arms: none),
                          versions (moik, pymoo, numpy, scipy, python), git commit, machine,
                          targets, every planned trial with its seeds, one entry per session
                          (start, executor, versions, git commit; at its end: finish time,
                          wall time and trials run)
    OUT/results.jsonl     one JSON object per finished trial (scalars, seeds, status)
    OUT/arrays/ID.npz     that trial's arrays (convergence curve, front, best x)
    OUT/run.lock          while a run writes: its PID and host (see :mod:`moik.experiments.lock`)

Why JSON lines + .npz: both are standard (``pandas.read_json(lines=True)``,
``numpy.load``), append-friendly and human-readable where it matters.

Crash safety: ``meta.json`` and each ``.npz`` are written to a temporary file
and moved into place with ``os.replace`` (atomic). A trial's line is appended
after its arrays are in place, with one ``write`` on an ``O_APPEND``
descriptor followed by ``fsync``: the line is the commit mark of the trial. A
line torn by a crash (no trailing newline, or not valid JSON) is ignored when
reading and cut off before the next append, so an interruption loses at most
the trials in flight. Non-finite floats are stored as ``null``.

One writer at a time: :meth:`ResultStore.create` takes the folder's run lock
(:mod:`moik.experiments.lock`; a second live run is refused, a stale lock taken
over) and removes the temporary files an interrupted write left behind.

Damaged arrays: a trial counts as stored only if its ``.npz`` is there and
every array in it reads back (zip CRC checked). :meth:`ResultStore.check_arrays`
names the ok trials whose file is missing or unreadable; a resumed run runs
them again, and a store opened with ``verify=True`` (the report,
:func:`~moik.experiments.results.load_results`) leaves them out of
:meth:`ResultStore.records`.
"""

from __future__ import annotations

import contextlib
import datetime as _dt
import errno
import io
import json
import math
import os
import shutil
import sys
from pathlib import Path

import numpy as np

from moik import _paths
from moik._validate import flag
from moik._validate import reading as _reading
from moik.exceptions import MoikError, ResultsError
from moik.experiments.config import ExperimentConfig
from moik.experiments.files import (
    atomic_write_bytes,
    environment,
    make_folders,
    read_npz,
    remove_stale_temporaries,
)
from moik.experiments.kinds.ik_robot import config_folder
from moik.experiments.lock import RunLock
from moik.experiments.records import read_lines
from moik.experiments.recovery import adopt, meta_problem, repair_meta

FORMAT = "moik-results/1"
MEMBERS = ("meta.json", "results.jsonl", "arrays", "run.lock", "figures", "report.md",
           "report.html")
"""What moik writes in a results folder: none of them may be a symbolic link."""


def planned_ids(meta: dict) -> set[str] | None:
    """The ids of the trials ``meta`` plans (None: it lists none, so every id counts)."""
    trials = meta.get("trials")
    if not isinstance(trials, list) or not trials:
        return None
    return {t["trial_id"] for t in trials if isinstance(t, dict)
            and isinstance(t.get("trial_id"), str)}


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


class ResultStore:
    """Reader/writer of one results folder (see the module docstring).

    Build with :meth:`create` (to run an experiment) or :meth:`open` (to read).
    """

    def __init__(self, folder: Path, meta: dict):
        self.folder = Path(folder)
        self.meta = meta
        self.damaged: dict[str, str] = {}
        self.notes: list[str] = []
        self.malformed: list[tuple[int, str]] = []  # of results.jsonl, set by records()
        self._warned_lines = False
        self._fd: int | None = None
        self._lock: RunLock | None = None

    @property
    def results_path(self) -> Path:
        """``OUT/results.jsonl``."""
        return self.folder / "results.jsonl"

    @classmethod
    def open(cls, folder: str | Path, *, verify: bool = False) -> ResultStore:
        """Open an existing results folder for reading.

        Args:
            folder: The results folder.
            verify: Check every stored trial's arrays now; the damaged or missing ones
                (:attr:`damaged`: trial id -> what is wrong) are left out of :meth:`records`.

        Raises:
            ResultsError: If ``folder`` has no readable ``meta.json``.
        """
        folder = Path(folder)
        try:
            meta = _reading.read_json(folder / "meta.json", "meta.json", ResultsError)
        except ResultsError as exc:
            raise ResultsError(f"{str(folder)!r} is not a moik results folder ({exc})") from None
        found = meta.get("format") if isinstance(meta, dict) else type(meta).__name__
        if found != FORMAT:
            shown = repr(found) if len(repr(found)) <= 60 else repr(found)[:57] + "..."
            raise ResultsError(f"{folder}/meta.json has format {shown}, expected {FORMAT!r}")
        why = meta_problem(meta, reading=True)
        if why is not None:
            raise ResultsError(f"{folder}/meta.json {why}")
        try:  # the stored config is checked as a config file is (the report reads it)
            ExperimentConfig.from_dict(meta["config"], path=f"{folder}/meta.json: config",
                                       is_quick=bool(meta.get("quick")),
                                       folder=config_folder(meta))
        except MoikError as exc:
            raise ResultsError(f"{folder}/meta.json holds an invalid config: {exc}") from None
        store = cls(folder, meta)
        if flag("verify", verify):
            store.damaged = store.check_arrays()
        return store

    @classmethod
    def create(cls, folder: str | Path, *, config, targets: list[dict], trials: list[dict],
               resume: bool, session: dict) -> ResultStore:
        """Prepare ``folder`` for a run of ``config`` (a new one, or a resumed one).

        Takes the folder's run lock (released by :meth:`close`) and removes stale
        temporary files; what it did is in :attr:`notes`. A folder this call made
        is removed again if preparing it fails.

        Raises:
            ResultsError: If another live run holds the folder's lock, the folder
                holds results and ``resume`` is False, or ``resume`` is True and the
                stored configuration differs.
        """
        folder = Path(folder)
        made = make_folders(folder)
        lock = None
        try:
            for member in MEMBERS:
                _paths.inside(folder, folder / member)
            lock = RunLock.acquire(folder)
            notes = [f"took over a stale run lock: {lock.replaced}"] if lock.replaced else []
            removed = remove_stale_temporaries(folder)
            if removed:
                notes.append(f"removed {removed} stale temporary file(s) of interrupted writes")
            store = cls._prepare(folder, config=config, targets=targets, trials=trials,
                                 resume=resume, session=session)
        except BaseException:
            if made is not None and lock is not None:  # made here, and no other run got in
                shutil.rmtree(made, ignore_errors=True)
            if lock is not None:
                lock.release()
            raise
        store._lock, store.notes = lock, notes + store.notes
        return store

    @classmethod
    def _prepare(cls, folder: Path, *, config, targets: list[dict], trials: list[dict],
                 resume: bool, session: dict) -> ResultStore:
        """The body of :meth:`create`, run under the lock."""
        env = environment()
        entry = {"started": _now(), **session, **env}
        old, problem = cls._existing(folder)
        if old is not None:
            has_results = old.results_path.exists() and old.results_path.stat().st_size > 0
            if not resume and has_results:
                raise ResultsError(f"{str(folder)!r} already holds results of "
                                   f"{old.meta['experiment']!r}; pass --resume to continue them "
                                   "or choose another --out folder")
            if resume and old.meta["config_fingerprint"] != config.fingerprint():
                raise ResultsError(f"{str(folder)!r} holds results of another configuration "
                                   f"({old.meta['experiment']!r}, quick={old.meta.get('quick')}"
                                   "); cannot resume with this one")
            if resume:
                (folder / "arrays").mkdir(parents=True, exist_ok=True)  # deleted by hand?
                old.meta["sessions"].append(entry)
                old._write_meta()
                old._repair_tail()
                return old
        notes = [] if problem is None else adopt(folder, config, problem, resume)
        (folder / "arrays").mkdir(parents=True, exist_ok=True)
        results = folder / "results.jsonl"
        if results.exists() and results.stat().st_size == 0:
            results.unlink()
        meta = {"format": FORMAT, "experiment": config.name, "quick": config.is_quick,
                "config_path": config.path, "config": config.raw,
                "config_fingerprint": config.fingerprint(), "algorithms": config.labels,
                **({"robot": config.robot} if isinstance(config.robot, dict) else {}),
                "skipped_algorithms": list(config.skipped), "created": _now(), **env,
                "sessions": [entry], "targets": targets, "trials": trials,
                **({"adopted": {"at": _now(), "why": problem, "notes": notes}} if notes else {})}
        store = cls(folder, _clean(meta))
        store._write_meta()
        store._repair_tail()
        store.notes = notes
        return store

    @classmethod
    def _existing(cls, folder: Path) -> tuple[ResultStore | None, str | None]:
        """The store already in ``folder`` if its ``meta.json`` is usable, else why not.

        ``(None, None)``: no ``meta.json`` and no results (a new folder);
        ``(None, why)``: trials or a ``meta.json`` are there, but no usable ``meta.json``.
        """
        meta_path = folder / "meta.json"
        if not meta_path.exists():
            results = folder / "results.jsonl"
            has_results = results.exists() and results.stat().st_size > 0
            return None, ("it has no meta.json" if has_results else None)
        try:
            old = cls.open(folder)
        except ResultsError as exc:
            return None, str(exc)
        repaired = repair_meta(old.meta)
        why = meta_problem(old.meta)
        if why is not None:
            return None, f"its meta.json {why}"
        old.notes += repaired
        return old, None

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
        """File name of a trial's arrays (``/`` in the id becomes ``__``).

        Raises:
            ResultsError: An id that cannot name a file (:func:`moik._paths.file_name`).
        """
        if not isinstance(trial_id, str):
            raise ResultsError(f"a trial id must be a string, got {type(trial_id).__name__}")
        return _paths.file_name(trial_id.replace("/", "__"), "trial id") + ".npz"

    def append(self, record: dict, arrays: dict) -> None:
        """Store one finished trial: its arrays (atomic), then its line (commit mark).

        Raises:
            ResultsError: If either cannot be written (a full disk): names the file, and
                says that the trials stored so far are kept and ``--resume`` continues.
                A line that could be written only in part is cut off again.
        """
        record = dict(record, experiment=self.meta["experiment"],
                      config_fingerprint=self.meta["config_fingerprint"],
                      finished_at=_now(), has_arrays=bool(arrays),
                      **({"arrays": sorted(arrays)} if arrays else {}))
        try:
            if arrays:
                buf = io.BytesIO()
                # numpy's stub matches **arrays against savez's allow_pickle: bool too
                np.savez(buf, **{k: np.asarray(v) for k, v in arrays.items()})  # type: ignore[arg-type]
                atomic_write_bytes(self.folder / "arrays" / self.array_name(record["trial"]),
                                   buf.getvalue())
            self._append_line((json.dumps(_clean(record), allow_nan=False) + "\n").encode())
        except OSError as exc:
            raise ResultsError(f"{exc}; trial {record['trial']!r} was not stored (the trials "
                               f"stored before it are kept): once it can be written (free "
                               f"space, a link removed), run the same command with --resume "
                               f"to continue") from exc

    def _append_line(self, line: bytes) -> None:
        """One line at the end of ``results.jsonl``, whole or not at all (then raises)."""
        path = self.results_path
        if self._fd is None:
            self._fd = _paths.open_append(path)
        start = os.lseek(self._fd, 0, os.SEEK_END)
        try:
            view = memoryview(line)
            while view:  # a short write (a full disk) writes the rest, or raises
                written = os.write(self._fd, view)
                if written <= 0:
                    raise OSError(errno.ENOSPC, f"short write ({len(line) - len(view)} of "
                                                f"{len(line)} bytes)")
                view = view[written:]
            os.fsync(self._fd)
        except OSError as exc:
            with contextlib.suppress(OSError):
                os.ftruncate(self._fd, start)  # no torn line left behind
            raise ResultsError(f"cannot append to {str(path)!r}: {exc.strerror or exc}"
                               ) from exc

    def end_session(self, *, wall_time: float, ran: int) -> None:
        """Record in ``meta.json`` that the current session ended: its wall time and trial count.

        ``sessions[-1]`` gets ``finished`` (UTC), ``wall_time_s`` (seconds of the whole
        call, start-up included) and ``trials_run``; the docs stamp sums them. A
        ``meta.json`` that cannot be written (a full disk) is warned about on stderr, not
        raised: the trials are stored, and the error that ended the run stays the one shown.
        """
        self.meta["sessions"][-1].update(finished=_now(), wall_time_s=round(float(wall_time), 3),
                                         trials_run=int(ran))
        try:
            self._write_meta()
        except ResultsError as exc:
            print(f"moik: warning: the end of this session is not recorded: {exc}",
                  file=sys.stderr)

    def close(self) -> None:
        """Close the append descriptor and release the run lock."""
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None
        if self._lock is not None:
            self._lock.release()
            self._lock = None

    def records(self) -> list[dict]:
        """The stored trial records, the last one per trial id, in file order.

        Malformed lines (:mod:`moik.experiments.records`), and records carrying another
        configuration's fingerprint than ``meta.json``'s, are skipped, counted in
        :attr:`malformed` and named on stderr once. A store opened with
        ``verify=True`` leaves out the trials in :attr:`damaged`.
        """
        lines = read_lines(self.results_path)
        mine = self.meta.get("config_fingerprint")
        if isinstance(mine, str):  # a line of another configuration is not this run's trial
            kept = []
            for number, rec in zip(lines.numbers, lines.records, strict=True):
                theirs = rec.get("config_fingerprint")
                if theirs is not None and theirs != mine:
                    lines.malformed.append((number, f"trial {rec['trial']!r} was written by "
                                                    "another configuration (its fingerprint)"))
                else:
                    kept.append(rec)
            lines.malformed.sort()
            lines.records = kept
        self.malformed = lines.malformed
        if lines.malformed and not self._warned_lines:
            self._warned_lines = True
            print(f"moik: warning: {lines.describe(self.results_path)}", file=sys.stderr)
        by_id: dict[str, dict] = {}
        for rec in lines.records:
            by_id.pop(rec["trial"], None)
            by_id[rec["trial"]] = rec
        return [r for r in by_id.values() if r["trial"] not in self.damaged]

    def check_arrays(self, records: list[dict] | None = None) -> dict[str, str]:
        """Trial id -> what is wrong, for each ok trial whose arrays are missing or damaged.

        Every array of every stored ``.npz`` is read back (and, where the record lists
        its array names, each is checked to be there).
        """
        bad = {}
        for r in self.records() if records is None else records:
            if r.get("status") != "ok" or not r.get("has_arrays"):
                continue
            try:
                got = read_npz(self.folder / "arrays" / self.array_name(r["trial"]))
            except ResultsError as exc:
                bad[r["trial"]] = str(exc)
                continue
            lost = sorted(set(r.get("arrays", ())) - set(got))
            if lost:
                bad[r["trial"]] = f"arrays file of {r['trial']!r} lacks {', '.join(lost)}"
        return bad

    def finished_ids(self) -> set[str]:
        """Ids of trials stored with status ``ok`` and their arrays intact."""
        records = self.records()
        bad = self.check_arrays(records)
        return {r["trial"] for r in records if r.get("status") == "ok" and r["trial"] not in bad}

    def load_arrays(self, trial_id: str) -> dict[str, np.ndarray]:
        """The arrays of a trial (empty dict if it stored none).

        Raises:
            ResultsError: If its arrays file is damaged.
        """
        path = self.folder / "arrays" / self.array_name(trial_id)
        if not path.exists():
            return {}
        return read_npz(path)
