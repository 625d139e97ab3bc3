"""The run lock of a results folder: at most one run writes into a folder at a time.

``OUT/run.lock`` is created with ``O_CREAT | O_EXCL`` (one creator wins) and
holds, as JSON, the holder's PID, host name, start time of the lock and the
process's start time (from ``/proc`` where the system has it, so that a PID
reused by another process after a crash is not taken for the holder). A
second run into the folder finds the lock and is refused with a
:class:`~moik.exceptions.ResultsError` naming the holder; a lock whose
process is gone (a crash, ``kill -9``) is stale and is taken over. A lock
held on another host cannot be checked from here, so it is never taken over:
the message says which file to delete once that run is known to be gone.

Taking over is race-safe: the stale file is renamed away (one renamer wins)
and checked to be the one judged stale before it is deleted; then the
``O_EXCL`` creation decides again between the contenders.
"""

from __future__ import annotations

import contextlib
import json
import os
import socket
import time
from dataclasses import dataclass
from pathlib import Path

from moik._validate import reading as _reading
from moik.exceptions import MoikError, ResultsError

LOCK_NAME = "run.lock"
_ATTEMPTS = 50
_WRITE_GRACE_S = 2.0  # an empty lock younger than this is being written, not stale


def process_start(pid: int) -> str | None:
    """Start time of process ``pid`` in clock ticks since boot (None where /proc lacks it)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = stat[stat.rfind(")") + 2:].split()  # after "pid (comm) "
    return fields[19] if len(fields) > 19 else None


def _zombie(pid: int) -> bool:
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat[stat.rfind(")") + 2:].startswith("Z")


@dataclass(frozen=True)
class LockHolder:
    """Who holds a run lock: PID, host, when it was taken, the process's start ticks."""

    pid: int
    host: str
    started: str
    process_start: str | None = None

    def describe(self) -> str:
        """``PID 123 on host h (since 2024-...)``."""
        return f"PID {self.pid} on host {self.host!r} (since {self.started})"

    def is_alive(self) -> bool:
        """Whether the holder may still run (True when it cannot be checked: another host)."""
        if self.host != socket.gethostname():
            return True
        try:
            os.kill(self.pid, 0)
        except ProcessLookupError:
            return False
        except PermissionError:  # another user's live process
            pass
        except OSError:
            return True
        if _zombie(self.pid):
            return False
        now = process_start(self.pid)
        return self.process_start is None or now is None or now == self.process_start


def _holder_from(raw: bytes) -> LockHolder | None:
    """The holder a lock file names, or None when it is unreadable (then stale)."""
    try:
        data = _reading.parse_json(raw[:4096], "run.lock", ResultsError)
        pid, start = data["pid"], data.get("process_start")
        if not isinstance(pid, int) or isinstance(pid, bool) or not 0 < pid < 2**31 or \
                not isinstance(start, (str, type(None))):
            return None
        return LockHolder(pid=pid, host=str(data["host"]), started=str(data["started"]),
                          process_start=start)
    except (MoikError, KeyError, TypeError):
        return None


class RunLock:
    """The run lock of one results folder: :meth:`acquire` takes it, :meth:`release` drops it.

    Attributes:
        path: ``OUT/run.lock``.
        replaced: The stale lock this one took over, described (``PID 123 on host 'h'
            (since ...), a process that is gone``, or ``an unreadable lock file``); None if
            the folder was free.
    """

    def __init__(self, path: Path, content: bytes, replaced: str | None):
        self.path = path
        self._content = content
        self.replaced = replaced
        self._held = True

    @classmethod
    def acquire(cls, folder: str | Path) -> RunLock:
        """Take the lock of ``folder`` (which must exist), taking over a stale one.

        Raises:
            ResultsError: If a live run holds it, or it cannot be created.
        """
        path = Path(folder) / LOCK_NAME
        me = {"pid": os.getpid(), "host": socket.gethostname(),
              "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
              "process_start": process_start(os.getpid()), "nonce": time.time_ns()}
        content = json.dumps(me).encode()
        replaced = None
        for _ in range(_ATTEMPTS):
            try:
                fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
            except FileExistsError:
                pass
            except OSError as exc:
                raise ResultsError(f"cannot create the run lock {str(path)!r}: {exc}") from None
            else:
                try:
                    os.write(fd, content)
                    os.fsync(fd)
                finally:
                    os.close(fd)
                return cls(path, content, replaced)
            replaced = cls._remove_if_stale(path) or replaced
        raise ResultsError(f"cannot take the run lock {str(path)!r}: other runs keep "
                           "taking it; try again")

    @staticmethod
    def _remove_if_stale(path: Path) -> str | None:
        """Judge the existing lock: raise if live; remove it if stale (returns its description).

        None means: nothing removed (released or taken over meanwhile, or being written).
        """
        try:
            raw = path.read_bytes()
            age = time.time() - path.stat().st_mtime
        except FileNotFoundError:
            return None  # released meanwhile: try again
        holder = _holder_from(raw)
        if holder is None and age < _WRITE_GRACE_S:
            time.sleep(0.05)  # its creator is writing it
            return None
        if holder is not None and holder.is_alive():
            same = holder.pid == os.getpid() and holder.host == socket.gethostname()
            raise ResultsError(
                f"{str(path.parent)!r} is in use by another run: {holder.describe()}"
                + (" (this process)" if same else "")
                + " holds its lock; wait for that run to finish or choose another --out "
                f"folder (if that run is gone, delete {str(path)!r})")
        aside = path.with_name(f".{LOCK_NAME}.stale.{os.getpid()}")
        try:
            os.replace(path, aside)
        except FileNotFoundError:
            return None  # another run took it over first
        try:
            moved = aside.read_bytes()
        except FileNotFoundError:
            return None
        if moved != raw:  # moved a lock taken meanwhile: put it back
            with contextlib.suppress(OSError):
                os.link(aside, path)
            aside.unlink(missing_ok=True)
            return None
        aside.unlink(missing_ok=True)
        return (f"{holder.describe()}, a process that is gone" if holder is not None
                else "an unreadable lock file")

    def release(self) -> None:
        """Drop the lock (only if the file is still this lock's)."""
        if not self._held:
            return
        self._held = False
        try:
            if self.path.read_bytes() == self._content:
                self.path.unlink()
        except FileNotFoundError:
            pass

    def __enter__(self) -> RunLock:
        return self

    def __exit__(self, *exc) -> None:
        self.release()
