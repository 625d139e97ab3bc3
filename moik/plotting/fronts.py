"""Pareto fronts of several algorithms on one target (EOSMA Figs. 17-18,
MO-m-PSO Fig. 5a)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from moik.plotting._common import (
    LOG_FLOOR,
    as_array,
    check_floor,
    check_mapping,
    floored,
    legend_outside,
    new_axes,
    save_figure,
    series_style,
)


def plot_pareto_fronts(
    fronts: Mapping[str, np.ndarray],
    *,
    compromise=None,
    compromise_label: str = "compromise",
    ax=None,
    xlabel: str = "position error (m)",
    ylabel: str = "orientation error (rad)",
    title: str = "Pareto fronts",
    log: bool = False,
    floor: float = LOG_FLOOR,
    proposed: str | None = None,
    save: str | None = None,
):
    """Two-objective fronts, one marker series per algorithm, sorted by f1.

    Reproduces EOSMA Figs. 17-18 (PF of the multi-objective algorithms at poses
    P1 and P2) and MO-m-PSO Fig. 5a (front with the chosen solution).

    Args:
        fronts: Algorithm name -> objective values ``(n, 2)`` (non-empty).
        compromise: Optional point ``(2,)`` drawn as a star (e.g. the knee /
            compromise solution picked from the front).
        compromise_label: Legend text of that point.
        ax: Axes to draw in (a new figure otherwise).
        xlabel: First-objective label with its unit (say the robot's unit).
        ylabel: Second-objective label with its unit.
        title: Axes title, e.g. ``"PF at pose P1"``.
        log: Log scale on both axes; values below ``floor`` are drawn at
            ``floor`` and the axis labels say so.
        floor: Smallest value shown on log axes.
        proposed: The paper's proposed algorithm: larger markers with a black edge,
            on top, bold in the legend.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Each algorithm has its own colour and marker (distinct up to 20 algorithms);
    the legend is beside the axes.

    Returns:
        The Axes (one line per algorithm, then the compromise line if given).

    Raises:
        ParameterError: empty ``fronts``.
        ShapeError: a front is not ``(n, 2)`` or ``compromise`` is not ``(2,)``.
    """
    fronts = check_mapping(fronts, "fronts")
    arrays = {n: as_array(F, f"front of {n!r}", shape=(None, 2)) for n, F in fronts.items()}
    point = None
    if compromise is not None:
        point = as_array(compromise, "compromise point", shape=(2,))
    if log:
        floor = check_floor(floor)
        arrays = {n: floored(F, floor, f"front of {n!r}") for n, F in arrays.items()}
        if point is not None:
            point = floored(point, floor, "compromise point")
        xlabel = f"{xlabel} [< {floor:g} shown at {floor:g}]"
        ylabel = f"{ylabel} [< {floor:g} shown at {floor:g}]"
    ax = new_axes(ax)
    for i, (name, F) in enumerate(arrays.items()):
        F = F[np.argsort(F[:, 0], kind="stable")]
        style = series_style(i, emphasis=name == proposed) | {"linestyle": "none"}
        style["markersize"] += 1.0
        if i >= 10:  # the second ten: hollow markers as well as other colours
            style["markerfacecolor"] = "none"
        ax.plot(F[:, 0], F[:, 1], label=f"{name} ({len(F)})", **style)
    if point is not None:
        ax.plot([point[0]], [point[1]], marker="*", markersize=16, linestyle="none",
                color="red", markeredgecolor="black", zorder=10, label=compromise_label)
    if log:
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    legend_outside(ax, proposed=proposed)
    save_figure(ax.figure, save)
    return ax

