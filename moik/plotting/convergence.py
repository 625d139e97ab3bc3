"""Convergence curves (EOSMA Figs. 8, 13, 19b) and the best joint vector per
iteration (EOSMA Fig. 19a)."""

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
    joint_display,
    legend_outside,
    new_axes,
    save_figure,
    series_style,
    sparse_markers,
)


def plot_convergence(
    curves: Mapping[str, np.ndarray],
    *,
    x=None,
    band: tuple[float, float] | None = None,
    log: bool = True,
    floor: float = LOG_FLOOR,
    ax=None,
    xlabel: str = "iteration",
    ylabel: str = "mean best fitness",
    title: str = "Mean convergence curves",
    proposed: str | None = None,
    save: str | None = None,
):
    """Mean best-so-far value per generation, one line per algorithm.

    Reproduces EOSMA Figs. 8 and 13 (average convergence curves over the random
    targets) and Fig. 19b. The mean is taken over runs on the raw values; only
    then, on a log axis, values below ``floor`` (exact zeros included) are
    drawn at ``floor``, and the y label says so, so a curve that reaches zero
    shows as flat at the floor instead of disappearing.

    Args:
        curves: Algorithm name -> ``(runs, generations)`` best values (a 1-D
            array is one run). Algorithms may have different generation counts.
        x: Optional common x values ``(generations,)`` (e.g. evaluations);
            default ``1..generations`` per algorithm.
        band: Optional percentiles ``(lo, hi)`` over runs drawn as a shaded band
            (e.g. ``(25, 75)``); ``None`` for the mean alone.
        log: Log y axis (default, as in the papers).
        floor: Smallest value shown on the log axis.
        ax: Axes to draw in (a new figure otherwise).
        xlabel: X label (say ``"function evaluations"`` when ``x`` holds them).
        ylabel: Y label with the quantity and unit.
        title: Axes title.
        proposed: The paper's proposed algorithm: drawn thicker, on top, bold in the legend.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Each algorithm has its own colour, marker and line style (distinct up to 20
    algorithms); the legend is beside the axes; without ``x`` the iteration axis
    has integer ticks.

    Returns:
        The Axes (one line per algorithm, one filled band each when ``band``).

    Raises:
        ParameterError: empty ``curves``, bad ``band``, negative values on a log axis.
        ShapeError: a curve array is not 1-D/2-D or ``x`` does not match its length.
    """
    curves = check_mapping(curves, "curves")
    if band is not None:
        lo, hi = (float(b) for b in band)
        if not 0 <= lo < hi <= 100:
            raise ParameterError(f"band must be percentiles (lo, hi) with 0 <= lo < hi <= 100, "
                                 f"got {band}")
    if log:
        floor = check_floor(floor)
        ylabel = f"{ylabel}\n[< {floor:g} shown at {floor:g}]"
    ax = new_axes(ax)
    for i, (name, C) in enumerate(curves.items()):
        C = np.atleast_2d(as_array(C, f"curves of {name!r}"))
        if C.ndim != 2 or C.shape[1] == 0:
            raise ShapeError(f"curves of {name!r} must be (runs, generations), got {C.shape}")
        xs = np.arange(1, C.shape[1] + 1) if x is None else as_array(x, "x", ndim=1)
        if xs.shape[0] != C.shape[1]:
            raise ShapeError(f"x has {xs.shape[0]} values but curves of {name!r} have "
                             f"{C.shape[1]} generations")
        mean = C.mean(axis=0)
        if log:
            mean = floored(mean, floor, f"curves of {name!r}")
        (line,) = ax.plot(xs, mean, label=f"{name} (n={C.shape[0]})",
                          markevery=sparse_markers(i, len(xs)),
                          **series_style(i, emphasis=name == proposed))
        if band is not None:
            low, high = np.percentile(C, [lo, hi], axis=0)
            if log:
                low = floored(low, floor, f"curves of {name!r}")
                high = floored(high, floor, f"curves of {name!r}")
            ax.fill_between(xs, low, high, color=line.get_color(), alpha=0.2, linewidth=0)
    if log:
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if band is not None:
        title = f"{title} (band: {lo:g}-{hi:g} percentile over runs)"
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    if x is None:
        integer_ticks(ax.xaxis)
    legend_outside(ax, proposed=proposed)
    save_figure(ax.figure, save)
    return ax


def plot_joint_history(
    history,
    *,
    joint_labels=None,
    prismatic=None,
    unit: str | None = None,
    ax=None,
    xlabel: str = "iteration",
    ylabel: str | None = None,
    title: str = "Best candidate joint angles",
    save: str | None = None,
):
    """Best candidate joint vector against iteration, one line per joint.

    Reproduces EOSMA Fig. 19a (the optimal candidate joint angle of EOSMA
    varying with the number of iterations).

    Args:
        history: ``(generations, dof)`` best joint vector of every generation, in rad
            (prismatic joints in ``unit``); drawn in degrees, as every moik figure
            draws joint values.
        joint_labels: Legend text per joint (default ``q1 .. q_dof``).
        prismatic: Optional ``(dof,)`` mask of prismatic joints (drawn as they are).
        unit: Length unit of the prismatic joints, for the label.
        ax: Axes to draw in (a new figure otherwise).
        xlabel: X label.
        ylabel: Y label (default ``"joint angle (deg)"``, naming the prismatic unit
            when there are prismatic joints).
        title: Axes title.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Axes (one line per joint).

    Raises:
        ShapeError: ``history`` is not 2-D, or the label count or ``prismatic`` does not
            match.
    """
    H = as_array(history, "history", ndim=2)
    H, u = joint_display(H, prismatic, unit, what="history")
    if ylabel is None:
        ylabel = f"joint {'value' if 'prismatic' in u else 'angle'} ({u})"
    dof = H.shape[1]
    labels = [f"q{j + 1}" for j in range(dof)] if joint_labels is None else list(joint_labels)
    if len(labels) != dof:
        raise ShapeError(f"joint_labels has {len(labels)} entries, history has {dof} joints")
    ax = new_axes(ax)
    it = np.arange(1, H.shape[0] + 1)
    for j in range(dof):
        ax.plot(it, H[:, j], label=str(labels[j]), markevery=sparse_markers(j, len(it)),
                **series_style(j))
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    integer_ticks(ax.xaxis)
    legend_outside(ax)
    save_figure(ax.figure, save)
    return ax
