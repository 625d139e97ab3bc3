"""Shared plumbing of the plot functions: input checks, new axes, series styles, saving.

Every plot function takes plain numpy-compatible arrays (so an experiment runner
can call it on stored results), validates them here with messages that name the
bad entry, and saves through :func:`save_figure`.

Series styles (:func:`series_style`): 20 colours (tab10, then ten darker or
other hues), each series also with its own marker, and a new line style for
every ten series, so that up to 20 algorithms stay distinct by colour alone and
up to 40 by colour, marker and line style together (and in grey-scale print).
The paper's proposed method is drawn thicker, larger and on top, and its
legend entry is bold (:func:`emphasise_legend`). Legends go outside the data
(:func:`legend_outside`).

Units, one per quantity across every figure: joint values are given in radians
(the API's unit) and drawn in degrees, prismatic joints in the robot's length
unit (:func:`joint_display`), the axis label saying so; position errors in the
problem's length unit and orientation errors in rad, the unit in the label.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from moik.exceptions import NonFiniteError, ParameterError, ShapeError

#: Default floor for values shown on a log axis (EOSMA Figs. 10, 15 set results
#: below 1e-18 to 1e-18).
LOG_FLOOR = 1e-18

PALETTE = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
           "#7f7f7f", "#bcbd22", "#17becf",
           "#000075", "#800000", "#469990", "#f032e6", "#808000", "#000000", "#d4a000",
           "#9a6324", "#6a5acd", "#7fc97f")
"""20 colours: matplotlib's tab10, then navy, maroon, teal, magenta, olive, black, gold,
brown, slate blue and light green."""

MARKERS = ("o", "s", "^", "v", "D", "P", "X", "*", "<", ">", "p", "h", "d", "8", "H",
           "1", "2", "3", "4", "+")
LINESTYLES = ("-", "--", "-.", ":")


def series_style(index: int, *, emphasis: bool = False) -> dict:
    """Colour, marker, line style, width and z-order of series ``index`` (0-based).

    Args:
        index: Position of the series (algorithm) in its plot.
        emphasis: The paper's proposed method: thicker line, larger marker with a
            black edge, drawn on top.

    Returns:
        Keyword arguments for ``Axes.plot``.
    """
    return {"color": PALETTE[index % len(PALETTE)], "marker": MARKERS[index % len(MARKERS)],
            "linestyle": LINESTYLES[(index // 10) % len(LINESTYLES)],
            "linewidth": 2.8 if emphasis else 1.3, "markersize": 7.5 if emphasis else 4.5,
            "markeredgecolor": "black" if emphasis else None,
            "markeredgewidth": 0.8 if emphasis else None, "zorder": 5 if emphasis else 2}


def legend_outside(ax, *, proposed: str | None = None, ncol: int | None = None,
                   loc: str = "right", below: float = -0.14, **kwargs):
    """A legend beside (``loc="right"``) or below (``"below"``) the axes, off the data.

    Bold text for the entry of ``proposed`` (see :func:`emphasise_legend`); more than
    14 entries beside the axes get two columns; ``below`` is the top of a legend below
    the axes, in axes fractions.
    """
    n = len(ax.get_legend_handles_labels()[1])
    if loc == "below":
        legend = ax.legend(loc="upper center", bbox_to_anchor=(0.5, below), borderaxespad=0,
                           ncol=ncol or min(n, 3), fontsize="small", **kwargs)
    else:
        legend = ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0,
                           ncol=ncol or (1 if n <= 14 else 2), fontsize="small", **kwargs)
    emphasise_legend(legend, proposed)
    return legend


def emphasise_legend(legend, proposed: str | None) -> None:
    """Bold the legend entries whose text is ``proposed`` or starts with ``"proposed "``."""
    if proposed is None or legend is None:
        return
    for text in legend.get_texts():
        label = text.get_text()
        if label == proposed or label.startswith(f"{proposed} "):
            text.set_fontweight("bold")


def integer_ticks(axis) -> None:
    """Integer tick positions only on ``axis`` (an x or y axis of counts or iterations)."""
    from matplotlib.ticker import MaxNLocator

    axis.set_major_locator(MaxNLocator(integer=True))


def sparse_markers(index: int, n_points: int, n_marks: int = 10):
    """``markevery`` for series ``index``: about ``n_marks`` markers, staggered between series."""
    step = max(1, n_points // n_marks)
    return (index * max(1, step // 4) % step, step)


def check_mapping(data: Mapping, what: str) -> dict[str, Any]:
    """Reject an empty or non-mapping ``data``; return it as a plain dict (values unchecked)."""
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


def joint_display(Q, prismatic=None, unit: str | None = None, *, what: str = "Q",
                  rate: str = "") -> tuple[np.ndarray, str]:
    """Joint values as drawn: revolute columns (rad) in degrees, prismatic ones as they are.

    Args:
        Q: ``(..., dof)`` joint values (or rates) in rad (revolute) and ``unit`` (prismatic).
        prismatic: Optional ``(dof,)`` mask of the prismatic joints (default: none).
        unit: Length unit of the prismatic joints, for the label.
        what: Name of ``Q`` in error messages.
        rate: Per-time suffix of the label's unit: ``""``, ``"/s"`` or ``"/s²"``.

    Returns:
        ``(values, unit text)``: e.g. ``"deg"``, or ``"deg | cm for prismatic joints"``.

    Raises:
        ShapeError: ``prismatic`` does not have one entry per joint.
    """
    values = np.asarray(Q, dtype=float)
    mask = (np.zeros(values.shape[-1], dtype=bool) if prismatic is None
            else np.asarray(prismatic, dtype=bool).reshape(-1))
    if mask.shape[0] != values.shape[-1]:
        raise ShapeError(f"prismatic has {mask.shape[0]} entries, {what} has "
                         f"{values.shape[-1]} joints")
    shown = np.where(mask, values, np.degrees(values))
    text = f"deg{rate}"
    if mask.any():
        text += f" | {unit or 'length unit'}{rate} for prismatic joints"
    return shown, text
