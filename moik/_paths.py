"""Paths derived from data moik reads, and writes that stay inside their folder.

Results folders, docs folders and caches may come from elsewhere (another machine,
another person), so every name read from such data becomes a file name only
through :func:`file_name` (no separator, no ``..``, no NUL, bounded length), and
everything moik writes or deletes inside such a folder goes through
:func:`inside` first: the path must lie under the folder, and no component
between the folder and the path may be a symbolic link (a link planted in a
results folder must not make moik write or delete elsewhere). Files are created
with ``O_NOFOLLOW | O_EXCL`` (:func:`atomic_write_bytes`) or opened with
``O_NOFOLLOW`` (:func:`open_append`).
"""

from __future__ import annotations

import contextlib
import os
import secrets
from pathlib import Path

from moik.exceptions import MoikError, ResultsError

MAX_NAME = 120
"""Characters of a name that becomes a file name (file systems allow 255 bytes; room is
left for suffixes such as ``-quick.md`` or ``.NAME.PID.tmp``)."""

_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_FORBIDDEN = ("/", "\\")


def file_name(name: object, what: str, *, error: type[MoikError] = ResultsError) -> str:
    """``name`` if it may be used as one file name, else raise.

    A file name here is a non-empty string of at most :data:`MAX_NAME` characters,
    with no path separator (``/``, ``\\``), no NUL or other control
    character, not ``.`` or ``..`` and not starting with ``.`` (moik's temporaries).

    Raises:
        error: Naming ``what`` and the bad value.
    """
    if not isinstance(name, str):
        raise error(f"{what} must be a string, got {type(name).__name__}")
    shown = repr(name) if len(name) <= 60 else repr(name[:57]) + "..."
    if not name or len(name) > MAX_NAME:
        raise error(f"{what} must have 1 to {MAX_NAME} characters, got {len(name)}: {shown}")
    if any(c in name for c in _FORBIDDEN) or any(ord(c) < 32 or ord(c) == 127 for c in name):
        raise error(f"{what} {shown} cannot be a file name: it holds a path separator or a "
                    "control character")
    if name.startswith("."):
        raise error(f"{what} {shown} cannot be a file name: it starts with '.'")
    return name


def inside(folder: str | Path, path: str | Path) -> Path:
    """``path`` if it lies under ``folder`` with no symbolic link on the way, else raise.

    ``folder`` itself may be (or lie under) a link: it is the folder the user named.
    Every component of ``path`` below ``folder`` that exists must be a real folder (or,
    for the last one, not a link); components that do not exist yet are fine.

    Raises:
        ResultsError: ``path`` leaves ``folder`` (``..``, an absolute part) or a
            component below ``folder`` is a symbolic link.
    """
    folder, path = Path(folder), Path(path)
    try:
        rel = path.relative_to(folder)
    except ValueError:
        raise ResultsError(f"{str(path)!r} is not inside {str(folder)!r}: refused") from None
    if any(part in ("..", "") for part in rel.parts) or rel.is_absolute():
        raise ResultsError(f"{str(path)!r} leaves {str(folder)!r}: refused")
    current = folder
    for part in rel.parts:
        current = current / part
        if current.is_symlink():
            raise ResultsError(f"{str(current)!r} is a symbolic link; moik does not write or "
                               f"delete through links inside {str(folder)!r}: remove it")
    return path


def atomic_write_bytes(path: Path, data: bytes, *, folder: str | Path | None = None) -> None:
    """Write ``data`` to ``path`` atomically (temporary file + ``os.replace``).

    The temporary ``.NAME.PID.RANDOM.tmp`` is created with ``O_EXCL | O_NOFOLLOW`` and removed
    again whatever interrupts the write (a full disk, Ctrl-C, SIGTERM). With ``folder``,
    ``path`` is first checked to lie inside it without links (:func:`inside`); ``path``
    itself being a link is always refused (the link would be replaced, not written
    through, but a link there is not what moik wrote).

    Raises:
        ResultsError: If the path is refused or the write fails (a full disk: names
            ``path``); ``path`` then keeps its former content.
    """
    path = Path(path)
    if folder is not None:
        inside(folder, path)
    if path.is_symlink():
        raise ResultsError(f"{str(path)!r} is a symbolic link; moik does not write through "
                           "links: remove it")
    tmp = path.with_name(f".{path.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp")
    created = False
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW, 0o644)
        created = True
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException as exc:
        if created:
            with contextlib.suppress(OSError):
                tmp.unlink()
        if isinstance(exc, OSError):
            raise ResultsError(f"cannot write {str(path)!r}: {exc.strerror or exc}") from exc
        raise


def open_append(path: Path) -> int:
    """A descriptor appending to ``path`` (created if missing), never through a link.

    Raises:
        ResultsError: ``path`` is a symbolic link (or cannot be opened).
    """
    try:
        return os.open(path, os.O_WRONLY | os.O_APPEND | os.O_CREAT | _NOFOLLOW, 0o644)
    except OSError as exc:
        why = "it is a symbolic link" if Path(path).is_symlink() else exc.strerror or str(exc)
        raise ResultsError(f"cannot append to {str(path)!r}: {why}") from None


def remove(folder: str | Path, path: Path) -> None:
    """Delete the file ``path`` inside ``folder`` (checked by :func:`inside`; a missing
    file is fine). A link at ``path`` itself is removed, never what it points to."""
    inside(folder, path.parent)
    path.unlink(missing_ok=True)
