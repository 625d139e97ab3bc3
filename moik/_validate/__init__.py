"""The one set of input validators used across moik.

One rule each, everywhere (robots, problems, algorithms, solver, experiments, CLI):

- an *integer* is a Python ``int`` or a numpy integer, never a ``bool`` and never
  a float (``2.0`` is refused: a count is not a measurement);
- a *number* is a finite real (``int``/``float``/numpy scalar), never a ``bool``;
- an *array* holds real numbers (no strings, complex numbers, bools or ragged rows),
  is converted to contiguous, writeable ``float64`` and must be finite;
- a *seed* is ``None``, a non-negative integer or a ``numpy.random.SeedSequence``;
- a *name* is one of a listed set (case-insensitive), else
  :class:`~moik.exceptions.UnknownNameError` listing the valid names.

Each validator takes the ``name`` of the argument for its message and an
``error`` class (a :class:`~moik.exceptions.MoikError` subclass; experiments pass
:class:`~moik.exceptions.ConfigError` so the message names the config key).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Mapping
from typing import Any, TypeGuard

import numpy as np

from moik.exceptions import MoikError, NonFiniteError, ParameterError, ShapeError, UnknownNameError

_INTEGER = (int, np.integer)
_REAL = (int, float, np.integer, np.floating)


def is_integer(value: object) -> TypeGuard[int | np.integer]:
    """Whether ``value`` is an integer under moik's rule (int or numpy integer, not bool)."""
    return isinstance(value, _INTEGER) and not isinstance(value, (bool, np.bool_))


def integer(name: str, value: object, *, minimum: int | None = None, maximum: int | None = None,
            error: type[MoikError] = ParameterError) -> int:
    """``value`` as an ``int`` in ``[minimum, maximum]``.

    Raises:
        error: If ``value`` is not an integer (bools and floats are refused) or is
            out of range; the message gives the range and the value received.
    """
    if minimum is not None and maximum is not None:
        expected = f"an integer in [{minimum}, {maximum}]"
    elif minimum is not None:
        expected = f"an integer >= {minimum}"
    elif maximum is not None:
        expected = f"an integer <= {maximum}"
    else:
        expected = "an integer"
    if not is_integer(value):
        raise error(f"{name} must be {expected}, got {value!r}")
    v = int(value)
    if (minimum is not None and v < minimum) or (maximum is not None and v > maximum):
        raise error(f"{name} must be {expected}, got {v}")
    return v


def optional_integer(name: str, value: object, *, minimum: int | None = None,
                     error: type[MoikError] = ParameterError) -> int | None:
    """``None`` or :func:`integer`."""
    return None if value is None else integer(name, value, minimum=minimum, error=error)


def number(name: str, value: object, *, minimum: float | None = None,
           maximum: float | None = None, lo_open: bool = False, hi_open: bool = False,
           error: type[MoikError] = ParameterError) -> float:
    """``value`` as a finite ``float`` in the given (closed or open) range.

    Raises:
        error: If ``value`` is not a finite real number (bools refused) or is out
            of range; the message shows the range in interval notation.
    """
    lo = -np.inf if minimum is None else minimum
    hi = np.inf if maximum is None else maximum
    v = _real_in(value, lo, hi, lo_open, hi_open)
    if v is None:
        if minimum is None and maximum is None:
            expected = "a finite number"
        else:
            expected = (f"a finite number in {'(' if lo_open or minimum is None else '['}"
                        f"{lo}, {hi}{')' if hi_open or maximum is None else ']'}")
        raise error(f"{name} must be {expected}, got {value!r}")
    return v


def interval(name: str, value: object, lo: float, hi: float, *, lo_open: bool = False,
             hi_open: bool = False, error: type[MoikError] = ParameterError) -> float:
    """``value`` as a finite ``float`` in the interval from ``lo`` to ``hi``.

    The rule of :func:`number`, with both ends given (an infinite end is open) and
    the message hyperparameters use: ``"z must be a number in [0.0, 1.0], got 2"``.

    Raises:
        error: If ``value`` is not a finite real number (bools refused) or lies
            outside the interval.
    """
    v = _real_in(value, lo, hi, lo_open, hi_open)
    if v is None:
        raise error(f"{name} must be a number in {'(' if lo_open else '['}{lo}, {hi}"
                    f"{')' if hi_open else ']'}, got {value!r}")
    return v


def _real_in(value: object, lo: float, hi: float, lo_open: bool, hi_open: bool) -> float | None:
    """``value`` as a float if it is a finite real (not a bool) in the range, else None."""
    if not isinstance(value, _REAL) or isinstance(value, (bool, np.bool_)):
        return None
    v = float(value)
    inside = (lo < v if lo_open else lo <= v) and (v < hi if hi_open else v <= hi)
    return v if bool(np.isfinite(v)) and inside else None


def positive(name: str, value: object, *, allow_zero: bool = False,
             error: type[MoikError] = ParameterError) -> float:
    """A finite number ``> 0`` (or ``>= 0`` with ``allow_zero``)."""
    real = isinstance(value, _REAL) and not isinstance(value, (bool, np.bool_))
    v = float(value) if real and isinstance(value, _REAL) else np.nan
    if not (np.isfinite(v) and (v >= 0 if allow_zero else v > 0)):
        kind = "a finite number >= 0" if allow_zero else "a positive finite number"
        raise error(f"{name} must be {kind}, got {value!r}")
    return v


def flag(name: str, value: object, *, error: type[MoikError] = ParameterError) -> bool:
    """``value`` as a ``bool`` (``True``/``False`` or numpy bools only)."""
    if not isinstance(value, (bool, np.bool_)):
        raise error(f"{name} must be True or False, got {value!r}")
    return bool(value)


def optional_callable(name: str, value: object) -> Any:
    """``value`` if it is ``None`` or callable (a function to call back), else raise."""
    if value is not None and not callable(value):
        raise ParameterError(f"{name} must be a function (or None), got {type(value).__name__} "
                             f"{value!r}")
    return value


def finite_array(name: str, values: Any, *, shape: tuple[int | None, ...] | None = None,
                 ndim: int | None = None, error: type[MoikError] = ShapeError) -> np.ndarray:
    """``values`` as a contiguous, writeable, finite ``float64`` array.

    Args:
        name: What the array is, for messages.
        values: Anything ``numpy.asarray`` accepts.
        shape: Required shape; ``None`` entries match any length.
        ndim: Required number of dimensions (when ``shape`` is not given).
        error: Raised for a wrong shape or a non-numeric input.

    Raises:
        error: Wrong shape or not numeric.
        NonFiniteError: NaN or infinite entries (the first one is located).
    """
    arr = real_array(name, values, error=error)
    if shape is not None:
        ok = arr.ndim == len(shape) and all(
            s is None or s == n for s, n in zip(shape, arr.shape, strict=True))
        if not ok:
            want = "(" + ", ".join("n" if s is None else str(s) for s in shape) + (
                ",)" if len(shape) == 1 else ")")
            raise error(f"{name} must have shape {want}, got {arr.shape}")
    elif ndim is not None and arr.ndim != ndim:
        raise error(f"{name} must be {ndim}-D, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        bad = np.argwhere(~np.isfinite(arr))[0]
        where = f" at index {tuple(int(i) for i in bad)}" if arr.ndim else ""
        raise NonFiniteError(f"{name} must hold finite values only; got {arr[tuple(bad)]}{where}")
    return arr


def real_array(name: str, values: Any, *, error: type[MoikError] = ShapeError) -> np.ndarray:
    """``values`` as a contiguous, writeable ``float64`` array of real numbers (any shape).

    Refuses what ``numpy.asarray(values, dtype=float)`` would convert silently or
    fail on with a bare ``ValueError``/``TypeError``: strings (numeric ones such as
    ``"1.5"`` too), complex numbers, bools, ``None``, mappings, ragged nested
    lists and other objects. Finiteness is not checked (see :func:`finite_array`).

    Raises:
        error: ``values`` is not an array of real numbers; the message says what came.
    """
    arr = values
    if type(values) is not np.ndarray:
        if isinstance(values, (str, bytes, Mapping)):
            raise error(f"{name} must be an array of real numbers, got a "
                        f"{type(values).__name__} {_short(values)}")
        try:
            arr = np.asarray(values)
        except (TypeError, ValueError):  # ragged rows (numpy refuses inhomogeneous shapes)
            raise error(f"{name} must be an array of real numbers with rows of equal length, "
                        f"got {_short(values)}") from None
    kind = arr.dtype.kind
    if kind not in "iuf":
        what = {"U": "strings", "S": "bytes", "c": "complex numbers", "b": "booleans"}.get(
            kind, f"a {type(values).__name__}" if arr.ndim == 0 else f"{arr.dtype} entries")
        raise error(f"{name} must be an array of real numbers, got {what}: {_short(values)}")
    return np.array(arr, dtype=np.float64, order="C", copy=True)


def _short(value: object) -> str:
    """A repr of ``value`` cut to 80 characters, for messages."""
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def seed(name: str, value: object, *, error: type[MoikError] = ParameterError
         ) -> int | np.random.SeedSequence | None:
    """``None``, a non-negative integer, or a ``numpy.random.SeedSequence``."""
    if value is None or isinstance(value, np.random.SeedSequence):
        return value
    if not is_integer(value) or int(value) < 0:
        raise error(f"{name} must be a non-negative integer, a numpy SeedSequence or None, "
                    f"got {value!r}")
    return int(value)


def choice(kind: str, value: object, valid: Iterable[str] | Mapping[str, Any]) -> str:
    """``value`` lower-cased if it is one of ``valid`` (case-insensitive).

    Raises:
        UnknownNameError: Otherwise; the message lists the valid names.
    """
    names = list(valid)
    key = value.lower() if isinstance(value, str) else value
    if key not in {n.lower() for n in names}:
        raise UnknownNameError(kind, value, names)
    return key


def keywords(owner: str, given: Mapping[str, Any], accepted: Iterable[str]) -> None:
    """Refuse keywords outside ``accepted`` (a misspelled option must not pass silently).

    Raises:
        ParameterError: Naming the unknown keywords and listing the accepted ones.
    """
    allowed = set(accepted)
    unknown = sorted(set(given) - allowed)
    if unknown:
        raise ParameterError(f"unknown parameter(s) {', '.join(unknown)} for {owner}; "
                             f"accepted: {', '.join(sorted(allowed))}")


def unknown_keys_message(where: str, given: Iterable[object], accepted: Iterable[str]
                         ) -> str | None:
    """What is wrong with the keys ``given`` (each unknown one with the nearest accepted
    key), or None when every key is in ``accepted``."""
    allowed = sorted(set(accepted))
    unknown = sorted((k for k in given if k not in allowed), key=str)
    if not unknown:
        return None
    named = []
    for key in unknown:
        near = difflib.get_close_matches(str(key), allowed, n=1) if isinstance(key, str) else []
        shown = key if isinstance(key, str) and key.isprintable() and len(key) <= 80 \
            else _short(key)
        named.append(f"{shown}" + (f" (did you mean {near[0]!r}?)" if near else ""))
    expected = f"expected some of: {', '.join(allowed)}" if allowed else "none is accepted"
    return f"{where}: unknown key(s) {', '.join(named)}; {expected}"


def known_keys(where: str, given: Mapping[Any, Any], accepted: Iterable[str], *,
               error: type[MoikError] = ParameterError) -> None:
    """Refuse keys of ``given`` outside ``accepted`` (a misspelt key must not pass silently).

    Raises:
        error: Naming each unknown key with the nearest accepted one, and listing them all.
    """
    message = unknown_keys_message(where, given, accepted)
    if message is not None:
        raise error(message)


def named_numbers(where: str, given: object, limits: Mapping[str, tuple[float, float]], *,
                  error: type[MoikError] = ParameterError) -> dict[str, float]:
    """``given`` (a mapping name -> number) as ``{name: float}``, each name one of
    ``limits`` and each value a finite number within its ``(lower, upper)``.

    Raises:
        error: ``given`` is not a mapping, a name is not in ``limits`` (listing them), a
            value is not a finite number in its interval (naming it and the interval).
    """
    if not isinstance(given, Mapping):
        raise error(f"{where} must be a mapping {{name: value}}, got {_short(given)}")
    known_keys(where, given, limits, error=error)
    return {name: interval(f"{where}[{name!r}]", value, *limits[name], error=error)
            for name, value in given.items()}
