"""Draw a robot arm at one or several configurations (I-BES Figs. 17-18, MO-m-PSO
Fig. 4a; the drawing of ``moik solve --plot``).

Two views: a 3-D view with the references a projection needs (ground grid at
``z = 0``, the base, joint numbers, the end-effector frame of every solution
and the target frame as red/green/blue axes, a dotted drop line from the
target to the ground) and a side view, the orthographic projection on the
vertical plane through the base and the target, where heights and horizontal
reach are true lengths. Each solution's legend entry carries its position (and
orientation) error; several solutions get distinct colours, markers and line
styles, and each is drawn thinner than the one before, on top of it, so that
none hides another even where they coincide.
"""

from __future__ import annotations

import numpy as np

from moik.exceptions import ShapeError
from moik.kinematics.orientation import geodesic_error
from moik.plotting._common import as_array, legend_outside, save_figure, series_style
from moik.plotting._scene import (
    base_marker,
    drop_lines,
    finish_3d,
    frame_axes,
    ground_grid,
)
from moik.plotting.geometry import draw_collision
from moik.robots.chain import Robot

_SOLUTION_STYLES = ("-", "--", ":", "-.")


def target_pose(target, rotation=None) -> tuple[np.ndarray | None, np.ndarray | None]:
    """``(position (3,), rotation (3, 3) or None)`` of a target given as a position,
    a ``(4, 4)`` pose or an object with ``position`` and ``rotation`` (a
    :class:`moik.problems.Target`); ``rotation`` overrides the target's own."""
    if target is None:
        if rotation is not None:
            raise ShapeError("target_rotation needs a target position")
        return None, None
    R = None
    if hasattr(target, "position") and hasattr(target, "rotation"):
        p = as_array(target.position, "target position", shape=(3,))
        R = None if target.rotation is None else as_array(target.rotation, "target rotation",
                                                          shape=(3, 3))
    else:
        arr = np.asarray(target, dtype=float)
        if arr.shape == (4, 4):
            p, R = as_array(arr[:3, 3], "target position"), as_array(arr[:3, :3], "target")
        else:
            p = as_array(arr, "target", shape=(3,))
    if rotation is not None:
        R = as_array(rotation, "target_rotation", shape=(3, 3))
    return p, R


def joint_origins(robot: Robot, frames: np.ndarray) -> np.ndarray:
    """Where each joint moves the chain: ``(k, dof, 3)`` from ``robot.frames`` ``(k, dof+1, 4, 4)``.

    Frame ``j`` is ``F_0 M_1 ... M_j P_j``; the joint ``j`` acts at the origin of
    ``frame_j P_j^-1`` (for standard DH robots the DH frame ``j - 1``).
    """
    inv = np.linalg.inv(robot.kinematic_chain.link_frames)
    return (frames[:, 1:] @ inv)[..., :3, 3]


def _error_text(T: np.ndarray, p_t, R_t, unit: str) -> str:
    if p_t is None:
        return ""
    text = f"position error {np.linalg.norm(T[:3, 3] - p_t):.2e} {unit}"
    if R_t is not None:
        text += f", orientation error {float(geodesic_error(T[:3, :3], R_t)):.2e} rad"
    return f" ({text})"


def _joint_numbers(ax, points: np.ndarray, colors: list, scale: float, *, dims: int) -> None:
    """Number the joints; coincident joints (of one or several solutions) share one label."""
    groups: dict[tuple, list] = {}
    for k, P in enumerate(points):
        for j, p in enumerate(P):
            key = tuple(np.round(p[:dims] / (1e-3 * scale)).astype(int))
            groups.setdefault(key, []).append((k, j + 1, p))
    offset = 0.025 * scale
    for members in groups.values():
        sols = {k for k, _, _ in members}
        text = ",".join(str(j) for j in sorted({j for _, j, _ in members}))
        color = colors[members[0][0]] if len(sols) == 1 else "black"
        ax.text(*(members[0][2][:dims] + offset), text, color=color, fontsize=8,
                fontweight="bold", zorder=8, gid="data-label")  # on the data, not the layout


def plot_robot(robot: Robot, Q, *, ax=None, target=None, target_rotation=None, labels=None,
               side_view: bool = True, save: str | None = None, collision=None):
    """Stick drawing of ``robot`` through its joint frames, in 3-D and from the side.

    Args:
        robot: The arm.
        Q: ``(dof,)`` or ``(k, dof)`` configurations; one line each.
        ax: A 3-D Axes to draw in (then no side view); a new figure otherwise.
        target: Optional target: a position ``(3,)`` (drawn as a star), a ``(4, 4)``
            pose or a :class:`moik.problems.Target` (then its frame is drawn, dashed,
            and the legend gives orientation errors too).
        target_rotation: Optional ``(3, 3)`` target rotation (with a position target).
        labels: Legend label per configuration (default ``configuration 1 ..``).
        side_view: Add the side view (only in a new figure).
        save: Path stem; writes ``save.png`` and ``save.pdf``.
        collision: Optional :class:`moik.collision.CollisionChecker`: its robot shapes at
            the first configuration and its obstacles are drawn in the 3-D view.

    Returns:
        The 3-D Axes: one line per configuration (base, every joint frame, end
        effector), scatter markers for the base and the target, frame axes and the
        ground grid as collections. With ``side_view`` the figure's second Axes is
        the side view (one line per configuration, same order).

    Raises:
        ShapeError: A configuration without ``robot.dof`` entries, ``labels`` of
            another length, or a malformed target.
    """
    import matplotlib.pyplot as plt

    Q = np.atleast_2d(robot.check_q(Q))
    labels = [f"configuration {i + 1}" for i in range(len(Q))] if labels is None else list(labels)
    if len(labels) != len(Q):
        raise ShapeError(f"labels has {len(labels)} entries for {len(Q)} configurations")
    p_t, R_t = target_pose(target, target_rotation)
    frames = robot.frames(Q)
    joints = joint_origins(robot, frames)
    pts = frames[:, :, :3, 3]
    every = np.vstack([pts.reshape(-1, 3)] + ([p_t[None]] if p_t is not None else []))
    scale = float(max(np.max(np.linalg.norm(every, axis=1)), 1e-9))
    side = None
    if ax is None:
        fig = plt.figure(figsize=(14.0, 7.0) if side_view else (7.0, 6.0))
        if side_view:  # the 3-D view larger; the side view's labels on its right side,
            # clear of the 3-D view's z label
            grid = fig.add_gridspec(1, 2, width_ratios=(1.25, 1.0), wspace=0.18, left=0.0,
                                    right=0.93, bottom=0.2, top=0.93)
        else:
            grid = fig.add_gridspec(1, 1)
        ax = fig.add_subplot(grid[0, 0], projection="3d")
        side = fig.add_subplot(grid[0, 1]) if side_view else None
    ax.view_init(elev=20, azim=-60)
    ground_grid(ax, every)
    styles = []
    for i, F in enumerate(frames):
        st = series_style(i) | {"linestyle": _SOLUTION_STYLES[i % len(_SOLUTION_STYLES)],
                                "linewidth": max(1.2, 3.6 - 0.8 * i), "zorder": 3 + i}
        styles.append(st)
        ax.plot(F[:, 0, 3], F[:, 1, 3], F[:, 2, 3], label=labels[i]
                + _error_text(F[-1], p_t, R_t, robot.unit), **st)
    _joint_numbers(ax, joints, [s["color"] for s in styles], scale, dims=3)
    frame_axes(ax, frames[:, -1], 0.12 * scale)
    if p_t is not None:
        ax.scatter([p_t[0]], [p_t[1]], [p_t[2]], marker="*", s=160, color="red",
                   edgecolors="black", linewidths=0.5, depthshade=False, label="target", zorder=9)
        drop_lines(ax, p_t[None])
        if R_t is not None:
            T = np.eye(4)
            T[:3, :3], T[:3, 3] = R_t, p_t
            frame_axes(ax, T[None], 0.18 * scale, linestyle="--", linewidth=1.4)
    if collision is not None:
        draw_collision(ax, collision, Q[0], span=scale)
    base_marker(ax)
    finish_3d(ax, robot.unit, min_fraction=0.5)
    ax.set_title(f"{robot.name}: 3-D view")
    if side is not None:  # under the 3-D view's tick and axis labels, as drawn
        fig = ax.figure
        drawn = ax.get_tightbbox(fig.canvas.get_renderer()).transformed(
            fig.transFigure.inverted())
        ax.legend(loc="upper center", bbox_to_anchor=((drawn.x0 + drawn.x1) / 2, drawn.y0),
                  bbox_transform=fig.transFigure, fontsize="small")
    else:
        legend_outside(ax, loc="below", ncol=1, below=-0.06)
    if side is not None:
        _side_view(side, robot, frames, joints, p_t, styles, scale,
                   has_target_frame=R_t is not None)
    save_figure(ax.figure, save)
    return ax


def _side_view(ax, robot: Robot, frames, joints, p_t, styles, scale: float, *,
               has_target_frame: bool) -> None:
    """Projection on the vertical plane through the base and the target (or end effector)."""
    d = (p_t if p_t is not None else frames[0, -1, :3, 3])[:2]
    u = d / np.linalg.norm(d) if np.linalg.norm(d) > 1e-9 * scale else np.array([1.0, 0.0])
    azimuth = np.degrees(np.arctan2(u[1], u[0]))

    def flat(P):
        P = np.asarray(P)
        return np.stack([P[..., 0] * u[0] + P[..., 1] * u[1], P[..., 2]], axis=-1)

    for F, st in zip(frames, styles, strict=True):
        h = flat(F[:, :3, 3])
        ax.plot(h[:, 0], h[:, 1], **st)
    _joint_numbers(ax, flat(joints), [s["color"] for s in styles], scale, dims=2)
    z = np.concatenate([frames[..., 2, 3].ravel()] + ([[p_t[2]]] if p_t is not None else []))
    ax.axhline(0.0, color="0.3", linewidth=1.0)
    on_the_ground = z.min() > -1e-9 * scale  # else the base frame is not on the floor
    if on_the_ground:
        ax.axhspan(-0.04 * scale, 0.0, color="0.85", zorder=0)
    ax.plot([0.0], [0.0], "ks", markersize=8, zorder=10)
    if p_t is not None:
        t = flat(p_t)
        ax.plot([t[0]], [t[1]], "*", color="red", markeredgecolor="black", markersize=14,
                zorder=9)
    unit = robot.unit
    ax.set_xlabel(f"horizontal distance from the base toward azimuth {azimuth:.0f} deg ({unit})")
    ax.set_ylabel(f"height z ({unit})")
    ax.yaxis.set_label_position("right")
    ax.yaxis.tick_right()
    low, high = min(z.min(), 0.0) - 0.06 * scale, z.max() + 0.1 * scale
    top = max(high, low + 0.4 * scale)  # a flat arm keeps a readable panel
    ax.set_ylim(low, top)
    left, right = ax.get_xlim()
    if right - left < 0.6 * (top - low):  # and an upright one readable ticks
        middle = (left + right) / 2
        ax.set_xlim(middle - 0.3 * (top - low), middle + 0.3 * (top - low))
    ax.set_aspect("equal", adjustable="box")
    ax.grid(True, alpha=0.3)
    ax.set_title("side view: true heights (vertical plane through base and target)")
    shared = " (black where solutions share them)" if len(frames) > 1 else ""
    oriented = ", target dashed" if has_target_frame else ""
    plane = "the ground z = 0" if on_the_ground else "the base frame's plane z = 0"
    ax.annotate(f"frame axes (3-D view): x red, y green, z blue; end effector solid{oriented}"
                f"\nnumbers: joints{shared}; black square: base; grey: {plane}",
                xy=(0.0, 0.0), xycoords="axes fraction", xytext=(0, -48),
                textcoords="offset points", fontsize=8, color="0.3", va="top")
