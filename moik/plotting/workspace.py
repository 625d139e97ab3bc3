"""Random targets in the workspace in 3-D, coloured by height, with orientation
arrows (EOSMA Figs. 7, 12)."""

from __future__ import annotations

import numpy as np

from moik.exceptions import ParameterError, ShapeError
from moik.plotting._common import as_array, new_axes, save_figure, unit_suffix
from moik.plotting._scene import finish_3d

_AXIS_NAMES = ("x", "y", "z")


def plot_targets(
    positions,
    rotations=None,
    *,
    axis: int = 2,
    arrow_length: float | None = None,
    unit: str | None = "m",
    ax=None,
    title: str = "Targets in the workspace",
    save: str | None = None,
):
    """Target positions as points coloured by height; optional orientation arrows.

    Reproduces EOSMA Fig. 7 (100 random positions, colour = height) and Fig. 12
    (random poses, dots for positions and line segments for the posture).

    Args:
        positions: ``(n, 3)`` target positions in ``unit``.
        rotations: Optional ``(n, 3, 3)`` target rotation matrices; an arrow is
            drawn along their column ``axis`` from each position.
        axis: Which end-effector axis the arrows show: 0 = x, 1 = y, 2 = z
            (approach, default).
        arrow_length: Arrow length in ``unit`` (default 10 % of the largest
            extent of the point cloud, or 1 for a single point).
        unit: Length unit of the positions for the axis labels.
        ax: A 3-D Axes to draw in (a new figure otherwise).
        title: Axes title.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Axes: one scatter collection with the ``n`` points (and a colour
        bar for the height), plus one quiver collection with ``n`` arrows when
        ``rotations`` is given.

    Raises:
        ShapeError: ``positions`` not ``(n, 3)`` or ``rotations`` not ``(n, 3, 3)``.
        ParameterError: ``axis`` not in 0..2 or a non-positive ``arrow_length``.
    """
    P = as_array(positions, "positions", shape=(None, 3))
    R = None
    if rotations is not None:
        R = as_array(rotations, "rotations", shape=(None, 3, 3))
        if R.shape[0] != P.shape[0]:
            raise ShapeError(f"rotations has {R.shape[0]} matrices for {P.shape[0]} positions")
    if axis not in (0, 1, 2):
        raise ParameterError(f"axis must be 0, 1 or 2 (x, y, z of the target frame), got {axis!r}")
    if arrow_length is None:
        extent = float(np.ptp(P, axis=0).max())
        arrow_length = 0.1 * extent if extent > 0 else 1.0
    elif not arrow_length > 0:
        raise ParameterError(f"arrow_length must be > 0, got {arrow_length}")
    ax = new_axes(ax, figsize=(6.5, 5.5), projection="3d")
    sc = ax.scatter(P[:, 0], P[:, 1], P[:, 2], c=P[:, 2], cmap="viridis", s=14,
                    depthshade=False, label=f"targets ({len(P)})")
    ax.figure.colorbar(sc, ax=ax, shrink=0.7, pad=0.1, label=f"height z{unit_suffix(unit)}")
    if R is not None:
        d = R[:, :, axis]
        ax.quiver(P[:, 0], P[:, 1], P[:, 2], d[:, 0], d[:, 1], d[:, 2],
                  length=arrow_length, normalize=True, color="tab:red", linewidth=0.8,
                  label=f"target {_AXIS_NAMES[axis]} axis")
    finish_3d(ax, unit)
    ax.set_title(title)
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, -0.14), fontsize="small", ncol=2)
    save_figure(ax.figure, save)
    return ax
