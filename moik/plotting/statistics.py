"""Statistics plots: solve time per target (EOSMA Figs. 9, 14), box plots of
final errors (Figs. 10, 15) and Wilcoxon p-value bars (Figs. 11, 16)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from moik.exceptions import ParameterError, ShapeError
from moik.plotting._common import (
    LOG_FLOOR,
    as_array,
    check_floor,
    check_mapping,
    floored,
    integer_ticks,
    legend_outside,
    new_axes,
    save_figure,
    series_style,
    sparse_markers,
)


def plot_solve_times(
    times: Mapping[str, np.ndarray],
    *,
    log: bool = False,
    ax=None,
    xlabel: str = "target index",
    ylabel: str = "solve time (s)",
    title: str = "Solve time per target",
    proposed: str | None = None,
    save: str | None = None,
):
    """Wall time of every algorithm at every target, one line per algorithm.

    Reproduces EOSMA Figs. 9 and 14 (solution time at the 100 random targets).
    The legend shows each algorithm's mean time.

    Args:
        times: Algorithm name -> ``(targets,)`` seconds (all the same length).
        log: Log y axis.
        ax: Axes to draw in (a new figure otherwise).
        xlabel: X label.
        ylabel: Y label with unit.
        title: Axes title.
        proposed: The paper's proposed algorithm: drawn thicker, on top, bold in the legend.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Axes (one line per algorithm, x = 1..targets, integer ticks; the legend
        beside the axes).

    Raises:
        ParameterError: empty ``times``, negative times, or zero times on a log axis.
        ShapeError: an entry is not 1-D or the lengths differ.
    """
    times = check_mapping(times, "times")
    arrays = {n: as_array(t, f"times of {n!r}", ndim=1) for n, t in times.items()}
    lengths = {n: len(t) for n, t in arrays.items()}
    if len(set(lengths.values())) != 1:
        raise ShapeError(f"every algorithm needs one time per target; got lengths {lengths}")
    for name, t in arrays.items():
        if np.any(t < 0) or (log and np.any(t <= 0)):
            need = "> 0 on a log axis" if log else ">= 0"
            raise ParameterError(f"times of {name!r} must be {need}, got min {t.min():g}")
    ax = new_axes(ax, figsize=(7.0, 4.5))
    for i, (name, t) in enumerate(arrays.items()):
        ax.plot(np.arange(1, len(t) + 1), t, label=f"{name} (mean {t.mean():.3g} s)",
                markevery=sparse_markers(i, len(t), 25),
                **series_style(i, emphasis=name == proposed))
    if log:
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    integer_ticks(ax.xaxis)
    legend_outside(ax, proposed=proposed)
    save_figure(ax.figure, save)
    return ax


def plot_error_boxes(
    errors: Mapping[str, np.ndarray],
    *,
    log: bool = True,
    floor: float = LOG_FLOOR,
    ax=None,
    ylabel: str = "final error",
    title: str = "Final errors",
    proposed: str | None = None,
    save: str | None = None,
):
    """Box plot of final errors, one box per algorithm.

    Reproduces EOSMA Figs. 10 and 15. As in the paper ("set results less than
    1e-18 to 1e-18"), on a log axis values below ``floor`` are drawn at
    ``floor``, and the y label says so.

    Args:
        errors: Algorithm name -> ``(n,)`` final errors (runs or targets;
            lengths may differ).
        log: Log y axis (default).
        floor: Smallest value shown on the log axis.
        ax: Axes to draw in (a new figure otherwise).
        ylabel: Y label with the quantity and unit.
        title: Axes title.
        proposed: The paper's proposed algorithm: its box drawn thicker in colour,
            its name in bold.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Axes (x tick labels are the algorithm names, in order).

    Raises:
        ParameterError: empty ``errors`` or negative errors on a log axis.
        ShapeError: an entry is not 1-D or is empty.
    """
    errors = check_mapping(errors, "errors")
    arrays = {n: as_array(e, f"errors of {n!r}", ndim=1) for n, e in errors.items()}
    if log:
        floor = check_floor(floor)
        arrays = {n: floored(e, floor, f"errors of {n!r}") for n, e in arrays.items()}
        sep = "\n" if len(ylabel) > 30 else " "  # a long label keeps the note on its own line
        ylabel = f"{ylabel}{sep}[< {floor:g} shown at {floor:g}]"
    ax = new_axes(ax, figsize=(max(5.0, 0.6 * len(arrays) + 2), 4.5))
    parts = ax.boxplot(list(arrays.values()), showfliers=True)
    ax.set_xticks(np.arange(1, len(arrays) + 1), list(arrays))  # works on matplotlib >= 3.7
    if proposed in arrays:
        k = list(arrays).index(proposed)
        for key in ("boxes", "medians", "whiskers", "caps"):
            per_box = len(parts[key]) // len(arrays)
            for line in parts[key][k * per_box:(k + 1) * per_box]:
                line.set_linewidth(2.4)
                line.set_color(series_style(0)["color"] if key != "medians" else "black")
        ax.get_xticklabels()[k].set_fontweight("bold")
    if log:
        ax.set_yscale("log")
    ax.tick_params(axis="x", labelrotation=45 if len(arrays) > 5 else 0)
    ax.set_xlabel("algorithm")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, axis="y", alpha=0.3)
    save_figure(ax.figure, save)
    return ax


def plot_wilcoxon(
    p_values: Mapping[str, float],
    *,
    proposed: str = "proposed",
    alpha: float = 0.05,
    log: bool = True,
    floor: float = 1e-300,
    ax=None,
    title: str | None = None,
    save: str | None = None,
):
    """Bars of Wilcoxon rank-sum p-values of ``proposed`` against each baseline.

    Reproduces EOSMA Figs. 11 and 16. A dashed line marks the significance level
    ``alpha``; bars below it (significant difference) are drawn in one colour,
    the others in another. On a log axis p-values below ``floor`` (underflow to
    0) are drawn at ``floor`` and then the label says so.

    Args:
        p_values: Baseline name -> p-value in ``[0, 1]``.
        proposed: Name of the algorithm compared against the baselines.
        alpha: Significance level (0 < alpha < 1).
        log: Log y axis (default; p-values span many decades).
        floor: Smallest p-value shown on the log axis.
        ax: Axes to draw in (a new figure otherwise).
        title: Axes title (default names ``proposed``).
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Axes (one bar per baseline, one horizontal line at ``alpha``).

    Raises:
        ParameterError: empty ``p_values``, a p-value outside ``[0, 1]``, bad ``alpha``.
        ShapeError: a value that is not a scalar.
    """
    from matplotlib.patches import Patch

    p_values = check_mapping(p_values, "p_values")
    alpha = float(alpha)
    if not 0 < alpha < 1:
        raise ParameterError(f"alpha must be in (0, 1), got {alpha}")
    names = list(p_values)
    if any(np.ndim(v) != 0 for v in p_values.values()):
        raise ShapeError("p_values must map each baseline name to one scalar p-value")
    p = as_array(list(p_values.values()), "p_values", ndim=1)
    bad = [n for n, v in zip(names, p, strict=True) if not 0 <= v <= 1]
    if bad:
        raise ParameterError(f"p-values must lie in [0, 1]; bad for {bad}")
    ylabel = "p-value"
    if log:
        floor = check_floor(floor)
        if np.any(p < floor):
            ylabel = f"p-value [< {floor:g} shown at {floor:g}]"
        p = np.maximum(p, floor)
    ax = new_axes(ax, figsize=(max(5.0, 0.6 * len(names) + 2), 4.5))
    colors = np.where(p < alpha, "tab:blue", "tab:orange")
    ax.bar(names, p, color=colors)
    level = ax.axhline(alpha, color="red", linestyle="--", label=f"p = {alpha:g}")
    keys = [level] + [Patch(color=c, label=t) for c, t in (
        ("tab:blue", f"p < {alpha:g}: significant difference"),
        ("tab:orange", f"p >= {alpha:g}: no significant difference"))]
    if log:
        ax.set_yscale("log")  # from a decade below the smallest p (or alpha) up to p = 1
        ax.set_ylim(min(float(p.min()), alpha) / 10.0, 1.0)
    else:
        ax.set_ylim(0.0, 1.0)
    ax.tick_params(axis="x", labelrotation=45 if len(names) > 5 else 0)
    ax.set_xlabel("baseline algorithm")
    ax.set_ylabel(ylabel)
    ax.set_title(title if title is not None else f"Wilcoxon rank-sum test: {proposed} vs baselines")
    legend_outside(ax, loc="below", below=-0.3 if len(names) > 5 else -0.15, handles=keys)
    save_figure(ax.figure, save)
    return ax
