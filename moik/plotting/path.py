"""Path tracking: desired against reached points with per-point errors
(MO-m-PSO Fig. 7, the 50-point circle)."""

from __future__ import annotations

import numpy as np

from moik.exceptions import ShapeError
from moik.plotting._common import (
    LOG_FLOOR,
    as_array,
    check_floor,
    floored,
    integer_ticks,
    joint_display,
    save_figure,
    series_style,
    unit_suffix,
)
from moik.plotting._scene import finish_3d


def plot_path_tracking(
    desired,
    reached,
    *,
    orientation_errors=None,
    Q=None,
    prismatic=None,
    unit: str | None = "cm",
    log: bool = False,
    floor: float = LOG_FLOOR,
    title: str = "Path tracking",
    save: str | None = None,
):
    """Desired and reached paths in 3-D, with the error at every point.

    Reproduces MO-m-PSO Fig. 7: (a) the input trajectory (red) and the tracked
    one (black), (b) the joint angles returned at each point (when ``Q`` is
    given), plus the relative error at each point the text describes. The
    position error is the Euclidean distance between desired and reached point.

    Args:
        desired: ``(n, 3)`` target points in ``unit``.
        reached: ``(n, 3)`` end-effector positions (FK of the solutions).
        orientation_errors: Optional ``(n,)`` orientation errors in rad, drawn in
            their own panel.
        Q: Optional ``(n, dof)`` joint solutions per point in rad, drawn in their
            own panel in degrees (as every moik figure draws joint values).
        prismatic: Optional ``(dof,)`` mask of prismatic joints in ``Q`` (in ``unit``,
            drawn as they are).
        unit: Length unit for the labels.
        log: Log y axis on the error panels; errors below ``floor`` (exact
            hits) are drawn at ``floor`` and the label says so.
        floor: Smallest error shown on log axes.
        title: Figure title.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Figure. ``fig.axes[0]`` is the 3-D view (lines: desired, reached);
        ``fig.axes[1]`` the position error per point (one line of ``n``
        points); then the orientation-error panel and the joint-angle panel
        (``dof`` lines) when their data are given.

    Raises:
        ShapeError: ``desired``/``reached`` not ``(n, 3)`` of equal ``n``, or an
            optional array with another number of points.
    """
    import matplotlib.pyplot as plt
    from matplotlib.layout_engine import ConstrainedLayoutEngine
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    D = as_array(desired, "desired points", shape=(None, 3))
    R = as_array(reached, "reached points", shape=(None, 3))
    if R.shape != D.shape:
        raise ShapeError(f"reached points {R.shape} must match desired points {D.shape}")
    npts = D.shape[0]
    ori = None
    if orientation_errors is not None:
        ori = as_array(orientation_errors, "orientation_errors", ndim=1)
        if ori.shape[0] != npts:
            raise ShapeError(f"orientation_errors has {ori.shape[0]} values for {npts} points")
    joints = None
    if Q is not None:
        joints = as_array(Q, "Q", ndim=2)
        if joints.shape[0] != npts:
            raise ShapeError(f"Q has {joints.shape[0]} rows for {npts} points")
        joints, joint_unit = joint_display(joints, prismatic, unit)
    pos_err = np.linalg.norm(R - D, axis=1)
    note = ""
    if log:
        floor = check_floor(floor)
        pos_err = floored(pos_err, floor, "position errors")
        if ori is not None:
            ori = floored(ori, floor, "orientation_errors")
        note = f" [< {floor:g} shown at {floor:g}]"

    n_right = 1 + (ori is not None) + (joints is not None)
    fig = plt.figure(figsize=(12.5, 3.0 * max(n_right, 2)), layout="constrained")
    engine = fig.get_layout_engine()
    assert isinstance(engine, ConstrainedLayoutEngine)  # layout="constrained"
    engine.set(wspace=0.12)  # room for the 3-D z label beside the panels
    grid = fig.add_gridspec(n_right, 2, width_ratios=(1.1, 1.0))
    ax3 = fig.add_subplot(grid[:, 0], projection="3d")
    ax3.plot(D[:, 0], D[:, 1], D[:, 2], "r-o", markersize=3, label="desired")
    ax3.plot(R[:, 0], R[:, 1], R[:, 2], "k--x", markersize=4, label="reached")
    ax3.add_collection3d(Line3DCollection(np.stack([D, R], axis=1), colors="0.5",
                                          linewidths=0.7))
    finish_3d(ax3, unit)
    ax3.set_title("(a) desired and reached path\n(grey: each desired point to its reached one)")
    ax3.legend(loc="upper left", bbox_to_anchor=(0.0, 1.0), fontsize="small")

    idx = np.arange(1, npts + 1)
    sfx = unit_suffix(unit)
    note = f"\n{note.strip()}" if note else ""  # own line: keeps the labels short
    row = 0
    ax = fig.add_subplot(grid[row, 1])
    ax.plot(idx, pos_err, "b.-", label=f"mean {pos_err.mean():.3g} {unit or ''}".rstrip())
    ax.set_ylabel(f"position error{sfx}{note}")
    ax.set_title("position error per point")
    panels = [ax]
    if ori is not None:
        row += 1
        ax = fig.add_subplot(grid[row, 1], sharex=panels[0])
        ax.plot(idx, ori, "g.-", label=f"mean {ori.mean():.3g} rad")
        ax.set_ylabel(f"orientation error (rad){note}")
        ax.set_title("orientation error per point")
        panels.append(ax)
    for ax in panels:
        if log:
            ax.set_yscale("log")
        ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0),
                  borderaxespad=0)
    if joints is not None:
        row += 1
        ax = fig.add_subplot(grid[row, 1], sharex=panels[0])
        for j in range(joints.shape[1]):
            ax.plot(idx, joints[:, j], label=f"q{j + 1}",
                    **(series_style(j) | {"markersize": 3, "linewidth": 1.0}))
        ax.set_ylabel(f"joint {'value' if 'prismatic' in joint_unit else 'angle'} "
                      f"({joint_unit})")
        ax.set_title("(b) joint angles per point")
        ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0),
                  borderaxespad=0)
        panels.append(ax)
    for ax in panels:
        ax.grid(True, alpha=0.3)
    integer_ticks(panels[-1].xaxis)
    panels[-1].set_xlabel("path point index")
    fig.align_ylabels(panels)
    fig.suptitle(f"{title} ({npts} points)")
    save_figure(fig, save)
    return fig
