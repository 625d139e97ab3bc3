"""Reading JSON and TOML that came from elsewhere: bounded size, nesting and numbers.

Scene files, capsule models, experiment configs and results folders may have been
written by anyone. Every such file is read here: at most :data:`MAX_BYTES` bytes
(``/dev/zero`` or a FIFO is not read forever; only regular files are read), strict
UTF-8, nesting at most :data:`MAX_DEPTH` deep, integers at most :data:`MAX_INTEGER`
in size, no NaN or infinite floats. What breaks a rule ends in the caller's
:class:`~moik.exceptions.MoikError` subclass naming the file, never in a raw
``RecursionError``, ``OverflowError`` or ``UnicodeDecodeError``.
"""

from __future__ import annotations

import json
import math
import os
import stat
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from moik import _toml
from moik.exceptions import MoikError

MAX_BYTES = 256 * 2**20
"""Size of a JSON or TOML file moik reads (a results.jsonl of a million trials is smaller)."""
MAX_DEPTH = 64
"""Nesting of arrays and objects (moik's own files nest at most 6 deep)."""
MAX_INTEGER = 2**128
"""Magnitude of an integer (a 128-bit seed entropy is the largest moik writes)."""


def read_bytes(path: str | Path, what: str, error: type[MoikError], *,
               limit: int = MAX_BYTES) -> bytes:
    """The bytes of the regular file ``path`` (at most ``limit``).

    Raises:
        error: Missing, not a regular file (a folder, a device, a FIFO), unreadable,
            or larger than ``limit``.
    """
    path = Path(path)
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except FileNotFoundError:
        raise error(f"cannot read {what} {str(path)!r}: it does not exist") from None
    except OSError as exc:
        raise error(f"cannot read {what} {str(path)!r}: {exc.strerror or exc}") from None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise error(f"cannot read {what} {str(path)!r}: it is not a regular file")
        chunks, size = [], 0
        while True:
            chunk = os.read(fd, 1 << 20)
            if not chunk:
                break
            size += len(chunk)
            if size > limit:
                raise error(f"cannot read {what} {str(path)!r}: larger than {limit} bytes")
            chunks.append(chunk)
        return b"".join(chunks)
    except OSError as exc:
        raise error(f"cannot read {what} {str(path)!r}: {exc.strerror or exc}") from None
    finally:
        os.close(fd)


def text(data: bytes, what: str, error: type[MoikError]) -> str:
    """``data`` decoded as UTF-8 (invalid bytes are refused, not replaced)."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise error(f"{what} is not UTF-8 text (byte {exc.start}: {exc.reason})") from None


def depth_problem(value: Any, limit: int = MAX_DEPTH) -> str | None:
    """Why ``value`` (parsed JSON/TOML) breaks the rules of this module, or None.

    Walks without recursion: nesting deeper than ``limit``, an integer beyond
    :data:`MAX_INTEGER`, a non-finite float.
    """
    stack = [(value, 1)]
    while stack:
        item, level = stack.pop()
        if isinstance(item, dict):
            children = list(item.values())
        elif isinstance(item, list):
            children = item
        elif isinstance(item, bool):
            continue
        elif isinstance(item, int):
            if abs(item) > MAX_INTEGER:
                return f"an integer of {len(str(abs(item)))} digits (at most 2**128 is read)"
            continue
        elif isinstance(item, float):
            if not math.isfinite(item):
                return f"a non-finite number ({item})"
            continue
        else:
            continue
        if level > limit:
            return f"nesting deeper than {limit} levels"
        stack.extend((c, level + 1) for c in children)
    return None


def _refuse_constant(name: str) -> float:
    raise ValueError(f"{name} is not a JSON number")


def _bounded_int(digits: str) -> int:
    if len(digits.lstrip("-")) > 40:
        raise ValueError(f"an integer of {len(digits.lstrip('-'))} digits")
    return int(digits)


def parse_json(data: bytes | str, what: str, error: type[MoikError]) -> Any:
    """The JSON value in ``data`` under this module's rules.

    Raises:
        error: Invalid UTF-8 or JSON, too deep, an out-of-range or non-finite number.
    """
    source = text(data, what, error) if isinstance(data, bytes) else data
    try:
        value = json.loads(source, parse_constant=_refuse_constant, parse_int=_bounded_int)
    except RecursionError:
        raise error(f"{what} is nested deeper than {MAX_DEPTH} levels") from None
    except ValueError as exc:
        raise error(f"{what} is not valid JSON: {str(exc)[:200]}") from None
    why = depth_problem(value)
    if why is not None:
        raise error(f"{what} holds {why}")
    return value


def read_json(path: str | Path, what: str, error: type[MoikError], *,
              limit: int = MAX_BYTES) -> Any:
    """The JSON value of the file ``path`` (see :func:`read_bytes` and :func:`parse_json`)."""
    label = f"{what} {str(path)!r}"
    return parse_json(read_bytes(path, what, error, limit=limit), label, error)


def read_toml(path: str | Path, what: str, error: type[MoikError]) -> dict[str, Any]:
    """The TOML table of the file ``path`` under this module's rules.

    Raises:
        error: Unreadable, invalid UTF-8 or TOML, too deep, out-of-range numbers.
    """
    label = f"{str(path)}"
    source = text(read_bytes(path, what, error), label, error)
    try:
        value = _toml.loads(source)
    except RecursionError:
        raise error(f"{label}: nested deeper than {MAX_DEPTH} levels") from None
    except _toml.TOMLDecodeError as exc:
        hint = ("; it looks like Python code: a config is data (TOML), never run"
                if any(w in source for w in ("import ", "def ", "EXPERIMENT =", "lambda")) else "")
        raise error(f"{label}: not valid TOML: {exc}{hint}") from None
    why = depth_problem(value)
    if why is not None and "non-finite" not in why:  # TOML's inf/nan: the config checks them
        raise error(f"{label}: holds {why}")
    return value


def robot_xml(text: str, label: str, kind: str, error: type[MoikError]) -> ET.Element:
    """The root ``<robot>`` element of a URDF or SRDF document (``kind``: its name in the
    messages, with its article: ``"a URDF"``), or ``error`` naming ``label``: not XML, or
    another root element."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise error(f"cannot read {kind.split()[-1]} {label!r}: {exc}") from None
    if root.tag != "robot":
        raise error(f"{label!r} is not {kind} file: root element <{root.tag}>")
    return root
