"""The Pareto set of exact IK solutions: its front, the arm in a few of its postures
(small multiples on one scale), and parallel coordinates for three or more criteria."""

from __future__ import annotations

import numpy as np

from moik.exceptions import ParameterError, ShapeError
from moik.plotting._common import as_array, save_figure
from moik.robots.chain import Robot

LETTERS = "ABCDEFGH"
UNITS = {"joint_motion": "rad", "orientation": "rad", "limit_margin": "fraction of the range"}
"""Units shown beside the built-in criteria's names (manipulability's depends on the arm)."""


def posture_picks(F_min: np.ndarray, compromise: int | None, n: int) -> list[int]:
    """Members to draw: each criterion's best, the compromise, then spread members,
    at most ``n``, ordered along the first criterion."""
    picks = list(dict.fromkeys([int(i) for i in np.argmin(F_min, axis=0)]
                               + ([] if compromise is None else [int(compromise)])))
    span = np.ptp(F_min, axis=0)
    Z = (F_min - F_min.min(axis=0)) / np.where(span > 0, span, 1.0)
    while len(picks) < min(n, len(F_min)):
        dist = np.min(np.linalg.norm(Z[:, None] - Z[picks][None], axis=2), axis=1)
        picks.append(int(np.argmax(dist)))
    return sorted(picks[:n], key=lambda i: (F_min[i, 0], i))


def _label(name: str, sense: str) -> str:
    unit = f", {UNITS[name]}" if name in UNITS else ""
    return f"{name} ({'larger' if sense == 'max' else 'smaller'} is better{unit})"


def _colour(k: int):
    import matplotlib.pyplot as plt

    return plt.get_cmap("tab10")(k % 10)


def plot_pareto_ik(robot: Robot, X, F, *, objectives, senses, target=None,
                   compromise: int | None = None, n_postures: int = 4,
                   title: str | None = None, save: str | None = None):
    """Front, postures and (for 3+ criteria) parallel coordinates of a Pareto set of IK solutions.

    Args:
        robot: The arm.
        X: Members ``(k, dof)``.
        F: Their criteria ``(k, m)`` in natural signs (as ``ParetoIKResult.F``).
        objectives: The criteria's names (``m``).
        senses: ``"min"`` / ``"max"`` per criterion.
        target: Target position ``(3,)`` drawn as a star in each posture.
        compromise: Index of the compromise member (drawn as a star on the front).
        n_postures: Postures drawn (at most 8): each criterion's best, the
            compromise, then members spread over the front.
        title: Figure title.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Figure.

    Raises:
        ShapeError: Inconsistent shapes, or an empty set.
        ParameterError: ``senses`` other than ``"min"`` / ``"max"``, ``n_postures``
            outside 1..8 or ``compromise`` not a member index.
    """
    import matplotlib.pyplot as plt

    X = robot.check_q(as_array(X, "members X", ndim=2))
    F = as_array(F, "criteria F", shape=(len(X), None))
    names, senses = [str(n) for n in objectives], list(senses)
    if len(names) != F.shape[1] or len(senses) != F.shape[1]:
        raise ShapeError(f"objectives and senses must name the {F.shape[1]} columns of F, got "
                         f"{len(names)} and {len(senses)}")
    if any(s not in ("min", "max") for s in senses):
        raise ParameterError(f"senses must be 'min' or 'max', got {senses}")
    if not (isinstance(n_postures, int) and 1 <= n_postures <= len(LETTERS)):
        raise ParameterError(f"n_postures must be an integer in [1, {len(LETTERS)}], got "
                             f"{n_postures!r}")
    if compromise is not None and not 0 <= compromise < len(X):
        raise ParameterError(f"compromise must index a member (0..{len(X) - 1}), got "
                             f"{compromise}")
    m = F.shape[1]
    F_min = F * np.where(np.array(senses) == "max", -1.0, 1.0)
    picks = posture_picks(F_min, compromise, n_postures)
    n_top = max(len(picks), 2 if m < 3 else 3)
    fig = plt.figure(figsize=(3.2 * n_top, 6.6 if m < 3 else 9.4))
    grid = fig.add_gridspec(2 if m < 3 else 3, n_top, height_ratios=[1.0, 1.1] + (
        [0.8] if m > 2 else []))
    ax = fig.add_subplot(grid[0, :])
    _front(ax, F, names, senses, picks, compromise)
    _postures(fig, grid, robot, X, F, names, picks, target)
    if m > 2:
        _parallel(fig.add_subplot(grid[2, :]), F, names, senses, picks)
    fig.suptitle(title or f"{robot.name}: {len(X)} exact solutions, mutually non-dominated")
    fig.tight_layout()
    save_figure(fig, save)
    return fig


def _front(ax, F, names, senses, picks, compromise) -> None:
    """The first two criteria (colour: the third, if any), picks lettered."""
    if F.shape[1] > 2:
        points = ax.scatter(F[:, 0], F[:, 1], c=F[:, 2], s=30, cmap="viridis", zorder=2,
                            label=f"{len(F)} members")
        ax.figure.colorbar(points, ax=ax, pad=0.01, label=f"{names[2]} ("
                           f"{'larger' if senses[2] == 'max' else 'smaller'} is better)")
    else:
        ax.scatter(F[:, 0], F[:, 1], color="tab:blue", s=30, zorder=2, label=f"{len(F)} members")
    for k, (letter, i) in enumerate(zip(LETTERS, picks, strict=False)):
        ax.annotate(letter, (F[i, 0], F[i, 1]), textcoords="offset points", xytext=(6, 6),
                    fontsize=11, fontweight="bold", color=_colour(k))
        ax.scatter([F[i, 0]], [F[i, 1]], s=110, facecolors="none", edgecolors=[_colour(k)],
                   linewidths=2, zorder=3)
    if compromise is not None:
        ax.scatter([F[compromise, 0]], [F[compromise, 1]], marker="*", s=220, color="red",
                   zorder=4, label="compromise (closest to utopia)")
    ax.set_xlabel(_label(names[0], senses[0]))
    ax.set_ylabel(_label(names[1], senses[1]) if len(names) > 1 else names[0])
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="best")


def _postures(fig, grid, robot, X, F, names, picks, target) -> None:
    """The arm in each picked member, every panel on the same axis limits; short grey
    segments along each joint axis show the twists a stick drawing would hide."""
    frames = robot.frames(X[picks])  # (k, dof + 1, 4, 4)
    points = frames[:, :, :3, 3]
    pts = points.reshape(-1, 3) if target is None else np.vstack([points.reshape(-1, 3),
                                                                  np.asarray(target)[None]])
    centre, half = (pts.max(0) + pts.min(0)) / 2, np.ptp(pts, axis=0).max() / 2 * 1.05
    for k, (letter, i) in enumerate(zip(LETTERS, picks, strict=False)):
        ax = fig.add_subplot(grid[1, k], projection="3d")
        p = points[k]
        for frame in frames[k, :-1]:  # joint axes (the z axis of each joint's frame)
            a = frame[:3, 3] + np.outer([-0.2, 0.2], frame[:3, 2]) * half
            ax.plot(a[:, 0], a[:, 1], a[:, 2], color="grey", linewidth=1)
        ax.plot(p[:, 0], p[:, 1], p[:, 2], "-o", color=_colour(k), markersize=3, linewidth=2)
        ax.scatter([p[0, 0]], [p[0, 1]], [p[0, 2]], marker="s", color="black", s=25)
        if target is not None:
            ax.scatter(*np.asarray(target)[:, None], marker="*", s=110, color="red")
        for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre, strict=True):
            setter(c - half, c + half)
        ax.set_box_aspect((1, 1, 1))
        ax.tick_params(labelsize=6)
        values = "\n".join(f"{n} = {F[i, j]:.4g}" for j, n in enumerate(names))
        ax.set_title(f"{letter}\n{values}", fontsize=8, color=_colour(k))


def _parallel(ax, F, names, senses, picks) -> None:
    """Parallel coordinates: each criterion scaled to [0, 1] over the set, 1 = best."""
    span = np.ptp(F, axis=0)
    Z = (F - F.min(axis=0)) / np.where(span > 0, span, 1.0)
    Z = np.where(np.array(senses) == "max", Z, 1.0 - Z)
    xs = np.arange(F.shape[1])
    for row in Z:
        ax.plot(xs, row, color="grey", alpha=0.35, linewidth=1)
    for k, (letter, i) in enumerate(zip(LETTERS, picks, strict=False)):
        ax.plot(xs, Z[i], linewidth=2.5, color=_colour(k), label=letter)
    ax.set_xticks(xs, [f"{_label(n, s)}\n[{F[:, j].min():.3g}, {F[:, j].max():.3g}]"
                       for j, (n, s) in enumerate(zip(names, senses, strict=True))],
                  fontsize=8)
    ax.set_ylabel("scaled (1 = best of the set)")
    ax.set_ylim(-0.05, 1.05)
    ax.grid(True, axis="x", alpha=0.5)
    ax.legend(fontsize="small", loc="center left", bbox_to_anchor=(1.0, 0.5))
