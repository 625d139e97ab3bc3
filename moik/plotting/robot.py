"""Draw a robot arm in 3-D at one or several configurations (I-BES Figs. 17-18,
MO-m-PSO Fig. 4a)."""

from __future__ import annotations

import numpy as np

from moik.robots.chain import Robot


def plot_robot(robot: Robot, Q, *, ax=None, target=None, labels=None, save: str | None = None):
    """Stick drawing of ``robot`` through its joint frames.

    Args:
        robot: The arm.
        Q: ``(dof,)`` or ``(k, dof)`` configurations; one line each.
        ax: A 3-D Axes to draw in (a new figure otherwise).
        target: Optional target position ``(3,)`` drawn as a star.
        labels: Legend label per configuration.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Axes.
    """
    import matplotlib.pyplot as plt

    Q = np.atleast_2d(robot.check_q(Q))
    if ax is None:
        ax = plt.figure(figsize=(6, 5)).add_subplot(projection="3d")
    frames = robot.frames(Q)
    for k, F in enumerate(frames):
        pts = F[:, :3, 3]
        label = labels[k] if labels is not None else None
        ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], "-o", markersize=3, label=label)
    if target is not None:
        t = np.asarray(target, dtype=float)
        ax.scatter([t[0]], [t[1]], [t[2]], marker="*", s=120, color="red", label="target")
    unit = robot.unit
    ax.set_xlabel(f"x ({unit})")
    ax.set_ylabel(f"y ({unit})")
    ax.set_zlabel(f"z ({unit})")
    ax.set_title(robot.name)
    ax.set_aspect("equal")
    from matplotlib.ticker import MaxNLocator

    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):  # equal aspect squeezes short axes
        axis.set_major_locator(MaxNLocator(5))
    if labels is not None or target is not None:
        ax.legend(loc="upper left", fontsize="small")
    if save:
        ax.figure.savefig(f"{save}.png", dpi=120)
        ax.figure.savefig(f"{save}.pdf")
    return ax
