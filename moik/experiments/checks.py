"""The small validators of experiment configs, built on :mod:`moik._validate`.

Each takes ``where`` (the file or experiment name and the key, e.g.
``"mpso-table2: targets.n"``) for its message and raises
:class:`~moik.exceptions.ConfigError`; the rules are those of
:mod:`moik._validate` (an integer is never a bool or a float such as ``2.0``; a
number is finite and never a bool).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from moik import _validate
from moik.exceptions import ConfigError


def integer(where: str, value: Any, minimum: int) -> int:
    """``value`` as an int ``>= minimum``."""
    return _validate.integer(where, value, minimum=minimum, error=ConfigError)


def number(where: str, value: Any, *, positive: bool = False) -> float:
    """``value`` as a finite float (``> 0`` if ``positive``)."""
    if positive:
        return _validate.positive(where, value, error=ConfigError)
    return _validate.number(where, value, error=ConfigError)


def numbers(where: str, value: Any, n: int) -> list[float]:
    """``value`` as a list of ``n`` finite floats (a list or tuple literal in the config)."""
    if not isinstance(value, (list, tuple)) or len(value) != n:
        raise ConfigError(f"{where} must be a list of {n} numbers, got {value!r}")
    return [number(f"{where}[{i}]", v) for i, v in enumerate(value)]


def flag(where: str, value: Any) -> bool:
    """``value`` as a bool (``True`` or ``False`` only)."""
    return _validate.flag(where, value, error=ConfigError)


def check_keys(where: str, spec: Any, allowed: set[str], required: tuple[str, ...] = ()) -> dict:
    """``spec`` as a dict with only ``allowed`` keys and all ``required`` ones."""
    if not isinstance(spec, Mapping):
        raise ConfigError(f"{where} must be a dict, got {type(spec).__name__}")
    _validate.known_keys(where, spec, allowed, error=ConfigError)
    missing = [k for k in required if k not in spec]
    if missing:
        raise ConfigError(f"{where}: missing key(s) {', '.join(missing)}")
    return dict(spec)
