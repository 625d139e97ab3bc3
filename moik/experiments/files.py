"""Files of a results folder: atomic writes, stale temporaries, reading ``.npz`` arrays back,
and the description of the run's environment that ``meta.json`` records.

Every file a run writes goes to ``.NAME.PID.RANDOM.tmp`` first and is moved into place
with ``os.replace`` (atomic on POSIX and Windows), so a reader never sees half a
file; a crash leaves at most such a temporary, which the next run removes
(:func:`remove_stale_temporaries`, under the folder's run lock).
"""

from __future__ import annotations

import os
import platform
import socket
import subprocess
import zipfile
from pathlib import Path

import numpy as np
import pymoo
import scipy

from moik import _paths
from moik._version import __version__
from moik.exceptions import ResultsError

_NPZ_ERRORS = (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile)
"""What reading a damaged ``.npz`` raises (emptied: EOFError; garbage: ValueError ...)."""


def make_folders(folder: Path) -> Path | None:
    """Create ``folder`` and missing parents; the topmost one this call created (or None).

    Raises:
        ResultsError: If a folder cannot be created.
    """
    made = None
    for p in [*folder.parents][::-1] + [folder]:
        if p.is_dir():
            continue
        try:
            p.mkdir()
        except FileExistsError:
            if not p.is_dir():
                raise ResultsError(f"cannot create the results folder {str(folder)!r}: "
                                   f"{str(p)!r} is a file") from None
        except OSError as exc:
            raise ResultsError(f"cannot create the results folder {str(folder)!r}: {exc}"
                               ) from None
        else:
            made = p if made is None else made
    return made


def atomic_write_bytes(path: Path, data: bytes, *, folder: str | Path | None = None) -> None:
    """Write ``data`` to ``path`` atomically (temporary file + ``os.replace``), never through
    a symbolic link, and (with ``folder``) only inside ``folder``
    (:func:`moik._paths.atomic_write_bytes`).

    Raises:
        ResultsError: If the path is refused or the write fails (a full disk: names
            ``path``); the temporary file is removed (also on Ctrl-C) and ``path`` keeps
            its former content.
    """
    _paths.atomic_write_bytes(path, data, folder=folder)


def remove_stale_temporaries(folder: Path) -> int:
    """Delete the ``.NAME.*.tmp`` files interrupted atomic writes left in ``folder``.

    Only safe while holding the folder's run lock (no other writer). Returns the count.

    Raises:
        ResultsError: ``folder/arrays`` is a symbolic link (nothing is deleted through it).
    """
    removed = 0
    for where in (folder, folder / "arrays"):
        _paths.inside(folder, where)
        for tmp in where.glob(".*.tmp"):
            _paths.remove(folder, tmp)
            removed += 1
    return removed


def read_npz(path: Path) -> dict[str, np.ndarray]:
    """Every array of the ``.npz`` at ``path``, read in full (so the zip CRCs are checked).

    Raises:
        ResultsError: If the file is missing or damaged (names the file and what is wrong).
    """
    try:
        size = path.stat().st_size
    except FileNotFoundError:
        raise ResultsError(f"arrays file {str(path)!r} is missing") from None
    except OSError as exc:  # `arrays` is a file, a link loop ...
        raise ResultsError(f"arrays file {str(path)!r} cannot be read: "
                           f"{exc.strerror or exc}") from None
    if size == 0 or not zipfile.is_zipfile(path):
        why = "an empty file" if size == 0 else f"{size} bytes that are not an .npz archive"
        raise ResultsError(f"arrays file {str(path)!r} is damaged ({why})")
    try:
        with np.load(path, allow_pickle=False) as data:
            return {k: data[k] for k in data.files}
    except _NPZ_ERRORS as exc:
        msg = str(exc).split(". ")[0]
        raise ResultsError(f"arrays file {str(path)!r} is damaged "
                           f"({exc.__class__.__name__}: {msg})") from None


CODE_PATHS = ("moik", "experiments", "pyproject.toml")
"""What a run's or a report's commit stands for: changes elsewhere (docs) do not make it dirty."""


def git_commit(root: str | Path | None = None) -> str | None:
    """The commit of the git checkout whose top folder is ``root`` (default: the one holding moik).

    ``-dirty`` is appended when tracked files of the code (``moik/``, ``experiments/``,
    ``pyproject.toml``) differ from the commit; edited docs do not count. None when git is
    absent, ``root`` is not the top of a checkout (an installed wheel inside some other
    repository does not take that repository's commit), or git fails: never raises.
    """
    root = Path(__file__).resolve().parents[2] if root is None else Path(root).resolve()

    def git(*args: str) -> str | None:
        out = subprocess.run(["git", "-C", str(root), *args], capture_output=True, text=True,
                             timeout=5, check=False)
        return out.stdout.strip() if out.returncode == 0 else None

    try:
        top = git("rev-parse", "--show-toplevel")
        if top is None or Path(top).resolve() != root:
            return None
        commit = git("rev-parse", "HEAD")
        if commit and git("status", "--porcelain", "-uno", "--", *CODE_PATHS):
            commit += "-dirty"
        return commit
    except (OSError, subprocess.SubprocessError):
        return None


def environment() -> dict:
    """Versions, git commit and machine description for the metadata.

    The commit is that of the git checkout holding this moik (None for an installed
    wheel; see :func:`git_commit`).
    """
    return {
        "versions": {"moik": __version__, "pymoo": pymoo.__version__,
                     "numpy": np.__version__, "scipy": scipy.__version__,
                     "python": platform.python_version()},
        "git_commit": git_commit(),
        "machine": {"hostname": socket.gethostname(), "platform": platform.platform(),
                    "processor": platform.processor() or platform.machine(),
                    "cpu_count": os.cpu_count()},
    }
