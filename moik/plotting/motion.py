"""Motion from a start to a solved configuration: end-effector trajectory and
joint angle / velocity / acceleration curves (EOSMA Figs. 19-20)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from moik.exceptions import ParameterError, ShapeError
from moik.kinematics.trajectory import quintic_trajectory
from moik.plotting._common import (
    as_array,
    check_mapping,
    joint_display,
    legend_outside,
    new_axes,
    save_figure,
    series_style,
    sparse_markers,
)
from moik.plotting._scene import base_marker, finish_3d, ground_grid
from moik.robots.chain import Robot


def plot_end_effector_paths(
    robot: Robot,
    q_start,
    goals: Mapping[str, np.ndarray],
    *,
    duration: float = 2.0,
    n: int = 101,
    target=None,
    show_arm: bool = True,
    ax=None,
    title: str = "End-effector trajectories",
    proposed: str | None = None,
    save: str | None = None,
):
    """End-effector paths of quintic joint motions from ``q_start`` to each goal.

    Reproduces EOSMA Fig. 20a (trajectories of the end effector of the 7-DOF
    arm for the solutions of several algorithms). The joint motion is
    :func:`moik.kinematics.trajectory.quintic_trajectory`; the path is its
    forward kinematics.

    Args:
        robot: The arm.
        q_start: Start configuration ``(dof,)``.
        goals: Label (e.g. algorithm) -> solved configuration ``(dof,)``.
        duration: Motion time in seconds.
        n: Samples along each motion.
        target: Optional desired position ``(3,)`` drawn as a star.
        show_arm: Also draw the arm (grey) at the start and at each goal.
        ax: A 3-D Axes to draw in (a new figure otherwise).
        title: Axes title.
        proposed: The paper's proposed algorithm's goal label: its path thicker, on top.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    The scene has the ground grid at ``z = 0`` and the base (black square) for
    reference, each path its own colour, marker and line style; the legend is
    beside the axes.

    Returns:
        The Axes: one path line per goal (labelled), then grey arm lines when
        ``show_arm`` (start, then one per goal), then the start marker.

    Raises:
        ParameterError: empty ``goals``.
        ShapeError: a configuration does not have ``robot.dof`` entries, or
            ``target`` is not ``(3,)``.
    """
    goals = check_mapping(goals, "goals")
    q0 = robot.check_q(q_start, "q_start")
    if q0.ndim != 1:
        raise ShapeError(f"q_start must have shape ({robot.dof},), got {q0.shape}")
    ends = {}
    for name, q in goals.items():
        q1 = robot.check_q(q, f"goal {name!r}")
        if q1.ndim != 1:
            raise ShapeError(f"goal {name!r} must have shape ({robot.dof},), got {q1.shape}")
        ends[name] = q1
    t_pos = None if target is None else as_array(target, "target position", shape=(3,))
    ax = new_axes(ax, figsize=(6.0, 5.0), projection="3d")
    drawn = []
    for i, (name, q1) in enumerate(ends.items()):
        _, Q, _, _ = quintic_trajectory(q0, q1, duration, n)
        p = robot.fk(Q)[:, :3, 3]
        style = series_style(i, emphasis=name == proposed)
        style["linewidth"] += 0.7
        style["markersize"] -= 2.0
        ax.plot(p[:, 0], p[:, 1], p[:, 2], label=name, markevery=sparse_markers(i, n, 6),
                **style)
        drawn.append(p)
    if show_arm:
        for q in (q0, *ends.values()):
            pts = robot.frames(q)[:, :3, 3]
            ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], "-o", color="0.6", markersize=2, linewidth=1)
            drawn.append(pts)
    ground_grid(ax, np.vstack(drawn))
    base_marker(ax, label=None)
    p0 = robot.fk(q0)[:3, 3]
    ax.plot([p0[0]], [p0[1]], [p0[2]], "o", color="white", markeredgecolor="black",
            markersize=7, label="start", zorder=8)
    if t_pos is not None:
        ax.scatter([t_pos[0]], [t_pos[1]], [t_pos[2]], marker="*", s=120, color="red",
                   label="target")
    finish_3d(ax, robot.unit)
    ax.set_title(title)
    legend_outside(ax, proposed=proposed, below=0.0, loc="below")
    save_figure(ax.figure, save)
    return ax


def plot_motion(
    robot: Robot,
    q_start,
    q_goal,
    *,
    duration: float = 2.0,
    n: int = 101,
    label: str = "solution",
    others: Mapping[str, np.ndarray] | None = None,
    target=None,
    proposed: str | None = None,
    save: str | None = None,
):
    """Quintic motion from ``q_start`` to ``q_goal``: path plus joint curves.

    Reproduces EOSMA Fig. 20: (a) end-effector trajectory, (b) joint angles,
    (c) joint velocities and (d) joint accelerations against time, one line per
    joint, in degrees (deg/s, deg/s²; prismatic joints in the robot's unit), as
    every moik figure draws joint values. ``others`` adds more solutions' paths
    to panel (a) only, as in the paper's comparison of EOSMA, EO and SMA.

    Args:
        robot: The arm.
        q_start: Start configuration ``(dof,)`` (EOSMA Table 9's initial angles).
        q_goal: Solved configuration ``(dof,)`` whose joint curves are drawn.
        duration: Motion time in seconds.
        n: Samples along the motion.
        label: Legend text of ``q_goal``'s path (e.g. ``"EOSMA"``).
        others: Optional label -> configuration ``(dof,)`` for more paths in (a).
        target: Optional desired position ``(3,)`` drawn as a star in (a).
        proposed: The paper's proposed algorithm's label: its path thicker, on top.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Figure; ``fig.axes[0]`` is the 3-D path, ``fig.axes[1:4]`` hold the
        angle, velocity and acceleration curves (``robot.dof`` lines each).

    Raises:
        ShapeError: a configuration does not have ``robot.dof`` entries.
        ParameterError: bad ``duration``/``n``, or ``others`` reuses ``label``.
    """
    import matplotlib.pyplot as plt

    goals = {label: q_goal}
    if others:
        goals.update(check_mapping(others, "others"))
        if len(goals) != 1 + len(others):
            raise ParameterError(f"others must not reuse the label {label!r}")
    q0 = robot.check_q(q_start, "q_start")
    q1 = robot.check_q(q_goal, "q_goal")
    if q0.ndim != 1 or q1.ndim != 1:
        raise ShapeError(f"q_start and q_goal must have shape ({robot.dof},), "
                         f"got {q0.shape} and {q1.shape}")
    t, Q, Qd, Qdd = quintic_trajectory(q0, q1, duration, n)
    fig = plt.figure(figsize=(12.0, 8.5), layout="constrained")
    ax3 = fig.add_subplot(2, 2, 1, projection="3d")
    plot_end_effector_paths(robot, q0, goals, duration=duration, n=n, target=target, ax=ax3,
                            title="(a) end-effector trajectory\n(grey: arm at start and goals; "
                                  "black square: base)",
                            proposed=proposed)
    panels: list[tuple[np.ndarray, str, str]] = []
    for Y, name, rate in ((Q, "angle", ""), (Qd, "velocity", "/s"), (Qdd, "acceleration", "/s²")):
        shown, u = joint_display(Y, robot.is_prismatic, robot.unit, rate=rate)
        panels.append((shown, f"({'bcd'[len(panels)]}) joint {name}", f"joint {name} ({u})"))
    for k, (Y, ttl, ylabel) in enumerate(panels):
        ax = fig.add_subplot(2, 2, k + 2)
        for j in range(robot.dof):
            ax.plot(t, Y[:, j], label=f"q{j + 1}", markevery=sparse_markers(j, len(t)),
                    **series_style(j))
        ax.set_xlabel("time (s)")
        ax.set_ylabel(ylabel)
        ax.set_title(ttl)
        ax.grid(True, alpha=0.3)
        if k == 0:
            legend_outside(ax)
    fig.suptitle(f"{robot.name}: quintic motion to {label} in {float(duration):g} s")
    save_figure(fig, save)
    return fig
