"""3-D scene pieces shared by the robot, motion and workspace plots.

A 3-D projection of an arm is easy to misread (a horizontal link looks as if it
descends), so the scenes carry references that fix the reading: the ground
grid at ``z = 0``, the robot's base as a black square at the origin,
coordinate frames as red/green/blue (x/y/z) axes, equal axis scales with at
most five ticks per axis. None of them is a ``Line2D`` (they are collections),
so ``ax.get_lines()`` keeps returning the plotted data alone.
"""

from __future__ import annotations

import numpy as np

FRAME_COLORS = ("#e00000", "#00a000", "#0000e0")
"""x, y, z axis of a drawn frame: red, green, blue."""


def _nice_step(span: float, n: int) -> float:
    raw = span / max(n, 1)
    mag = 10 ** np.floor(np.log10(raw))
    return float(min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=raw))


def ground_grid(ax, points: np.ndarray, *, z: float = 0.0, lines: int = 8):
    """Grey grid on the plane ``z`` under ``points`` (``(n, 3)``; the origin included)."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    xy = np.vstack([np.asarray(points, dtype=float).reshape(-1, 3)[:, :2], [[0.0, 0.0]]])
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    span = float(max(np.max(hi - lo), 1e-9))
    step = _nice_step(1.1 * span, lines)
    lo, hi = np.floor(lo / step - 0.5) * step, np.ceil(hi / step + 0.5) * step
    xs, ys = np.arange(lo[0], hi[0] + step / 2, step), np.arange(lo[1], hi[1] + step / 2, step)
    segs = [[(x, ys[0], z), (x, ys[-1], z)] for x in xs] + \
        [[(xs[0], y, z), (xs[-1], y, z)] for y in ys]
    grid = Line3DCollection(segs, colors="0.55", linewidths=0.6, alpha=0.6, zorder=0)
    ax.add_collection3d(grid)
    return grid


def base_marker(ax, *, label: str | None = "base"):
    """The robot's base: a black square at the origin."""
    return ax.scatter([0.0], [0.0], [0.0], marker="s", s=70, color="black", depthshade=False,
                      label=label, zorder=6)


def frame_axes(ax, poses: np.ndarray, length: float, *, linestyle: str = "-",
               linewidth: float = 2.0):
    """The x/y/z axes (red/green/blue) of every pose in ``poses`` (``(k, 4, 4)``)."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    poses = np.asarray(poses, dtype=float).reshape(-1, 4, 4)
    out = []
    for axis, color in enumerate(FRAME_COLORS):
        segs = [[T[:3, 3], T[:3, 3] + length * T[:3, axis]] for T in poses]
        coll = Line3DCollection(segs, colors=color, linewidths=linewidth, linestyles=linestyle,
                                zorder=7)
        ax.add_collection3d(coll)
        out.append(coll)
    return out


def drop_lines(ax, points: np.ndarray, *, z: float = 0.0):
    """Dotted vertical lines from ``points`` (``(n, 3)``) down to the plane ``z``."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    segs = [[p, (p[0], p[1], z)] for p in pts]
    coll = Line3DCollection(segs, colors="0.35", linewidths=0.9, linestyles=":", zorder=1)
    ax.add_collection3d(coll)
    return coll


def finish_3d(ax, unit: str | None, *, ticks: int = 5, min_fraction: float = 0.3) -> None:
    """Axis labels with ``unit``, equal scales, short axes lengthened, few ticks.

    Equal scales squash an axis whose data spread is small (targets at nearly one
    height) into a sliver with unreadable ticks: each axis is widened about its
    centre to at least ``min_fraction`` of the longest one (the scales stay equal),
    and gets at most ``ticks`` ticks, fewer in proportion when it is shorter.
    """
    from matplotlib.ticker import FixedLocator, MaxNLocator

    sfx = f" ({unit})" if unit else ""
    ax.set_xlabel(f"x{sfx}", labelpad=12)  # clear of the tick labels in any view
    ax.set_ylabel(f"y{sfx}", labelpad=16)
    ax.set_zlabel(f"z{sfx}", labelpad=14)
    limits = [ax.get_xlim(), ax.get_ylim(), ax.get_zlim()]
    longest = max(hi - lo for lo, hi in limits)
    setters = (ax.set_xlim, ax.set_ylim, ax.set_zlim)
    for (lo, hi), set_lim, axis in zip(limits, setters, (ax.xaxis, ax.yaxis, ax.zaxis),
                                       strict=True):
        half = max(hi - lo, min_fraction * longest) / 2
        set_lim((lo + hi) / 2 - half, (lo + hi) / 2 + half)
        lo, hi = (lo + hi) / 2 - half, (lo + hi) / 2 + half
        at = MaxNLocator(max(3, round(ticks * 2 * half / longest))).tick_values(lo, hi)
        at = at[(at >= lo) & (at <= hi)]
        if axis is ax.xaxis:  # the x axis ends where the y axis starts (matplotlib's views,
            # azimuth -60 deg): no x tick near that corner, where its label would sit on
            # the first y label
            at = at[at <= hi - 0.12 * (hi - lo)]
        axis.set_major_locator(FixedLocator(at))
    ax.set_aspect("equal")
