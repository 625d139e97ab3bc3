"""Shared plumbing of the plot functions: input checks, new axes, saving.

Every plot function takes plain numpy-compatible arrays (so an experiment runner
can call it on stored results), validates them here with messages that name the
bad entry, and saves through :func:`save_figure`.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from moik.exceptions import NonFiniteError, ParameterError, ShapeError

#: Default floor for values shown on a log axis (EOSMA Figs. 10, 15 set results
#: below 1e-18 to 1e-18).
LOG_FLOOR = 1e-18


def check_mapping(data: Mapping, what: str) -> dict[str, object]:
    """Reject an empty or non-mapping ``data``; return it as a plain dict."""
    if not isinstance(data, Mapping):
        raise ParameterError(f"{what} must be a dict name -> array, got {type(data).__name__}")
    if len(data) == 0:
        raise ParameterError(f"{what} is empty; expected at least one entry name -> array")
    return {str(k): v for k, v in data.items()}


def as_array(values, what: str, *, ndim: int | None = None, shape: tuple | None = None,
             min_len: int = 1) -> np.ndarray:
    """Float array with an optional ndim / shape check (``None`` in ``shape`` = any).

    Raises:
        ShapeError: wrong ndim, shape, or fewer than ``min_len`` rows.
        NonFiniteError: NaN or inf in the values.
    """
    arr = np.asarray(values, dtype=float)
    if ndim is not None and arr.ndim != ndim:
        raise ShapeError(f"{what} must be {ndim}-D, got shape {arr.shape}")
    if shape is not None:
        ok = arr.ndim == len(shape) and all(
            s is None or s == a for s, a in zip(shape, arr.shape, strict=True)
        )
        if not ok:
            want = "(" + ", ".join("n" if s is None else str(s) for s in shape) + ")"
            raise ShapeError(f"{what} must have shape {want}, got {arr.shape}")
    if arr.ndim > 0 and arr.shape[0] < min_len:
        raise ShapeError(f"{what} needs at least {min_len} entries, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise NonFiniteError(f"{what} holds NaN or inf values")
    return arr


def check_floor(floor: float) -> float:
    """A log-axis floor must be a positive finite number."""
    floor = float(floor)
    if not (np.isfinite(floor) and floor > 0):
        raise ParameterError(f"floor must be a positive finite number, got {floor}")
    return floor


def floored(values: np.ndarray, floor: float, what: str) -> np.ndarray:
    """Clip ``values`` up to ``floor`` for a log axis; negatives are an error."""
    if np.any(values < 0):
        raise ParameterError(f"{what} has negative values; a log axis needs values >= 0")
    return np.maximum(values, floor)


def new_axes(ax=None, *, figsize=(6.0, 4.5), projection: str | None = None):
    """Return ``ax`` or a fresh Axes in a new figure."""
    import matplotlib.pyplot as plt

    if ax is not None:
        return ax
    fig = plt.figure(figsize=figsize)
    return fig.add_subplot(projection=projection) if projection else fig.add_subplot()


def save_figure(fig, save: str | None) -> None:
    """Write ``save.png`` and ``save.pdf`` when a path stem is given."""
    if save:
        fig.savefig(f"{save}.png", dpi=120, bbox_inches="tight")
        fig.savefig(f"{save}.pdf", bbox_inches="tight")


def unit_suffix(unit: str | None) -> str:
    """``" (cm)"`` for a unit, ``""`` without one."""
    return f" ({unit})" if unit else ""
