"""The explorer's panels (fronts linked to postures, convergence curves, statistics tables)
and the plotly figures and posture data built from them for :mod:`moik.plotting._explorer_page`.

Each member's posture is what :func:`moik.plotting.plot_robot` draws, from the robot's
FK of every frame (:meth:`moik.robots.Robot.frames`): the frame origins (the links),
the joints' origins (:func:`moik.plotting.robot.joint_origins`), every frame's axes;
its errors are recomputed against the target by the same FK.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from moik.exceptions import ParameterError, ShapeError
from moik.kinematics.orientation import geodesic_error
from moik.plotting._common import PALETTE, as_array
from moik.plotting.robot import joint_origins, target_pose
from moik.robots.chain import Robot


@dataclass(frozen=True)
class Front:
    """One trace of a front panel: a front's criteria and (optionally) its members.

    Attributes:
        name: Legend entry (e.g. ``"moeosma run 0"``).
        F: ``(k, m)`` criteria of the members.
        X: ``(k, dof)`` joint vectors, or ``None`` (no posture for this trace).
        group: Legend group (the algorithm): one colour per group.
        visible: Shown at first (else listed in the legend, one click away).
    """

    name: str
    F: np.ndarray
    X: np.ndarray | None = None
    group: str = ""
    visible: bool = True


@dataclass(frozen=True)
class FrontPanel:
    """Fronts of one target, linked to a 3-D posture view.

    Attributes:
        title: Section heading.
        fronts: The traces.
        objectives: The criteria's axis labels (``m``; the first two are plotted).
        robot: The arm (``None``: no posture view, e.g. a benchmark problem).
        target: Position ``(3,)``, ``(4, 4)`` pose or Target, drawn in the posture.
        initial: ``(trace, member)`` shown when the page opens.
        obstacles: plotly trace dicts drawn in every posture (the hook for collision
            scenes).
        robot_shapes: The arm's collision shapes as triangle meshes in their bodies'
            frames (:func:`moik.plotting.geometry.robot_meshes`), drawn at each posture
            where that posture's frames put them.
        notes: Lines printed under the panel.
    """

    title: str
    fronts: Sequence[Front]
    objectives: Sequence[str]
    robot: Robot | None = None
    target: object = None
    initial: tuple[int, int] = (0, 0)
    obstacles: Sequence[dict] = ()
    robot_shapes: Sequence[dict] = ()
    notes: Sequence[str] = ()


@dataclass(frozen=True)
class CurvePanel:
    """Convergence curves: ``{label: (runs, iterations)}``, mean (and range) per label."""

    title: str
    curves: Mapping[str, np.ndarray]
    ylabel: str
    xlabel: str = "iteration"
    notes: Sequence[str] = ()


@dataclass(frozen=True)
class TablePanel:
    """A statistics table, cells already formatted (as :class:`moik.experiments.Table`)."""

    title: str
    header: Sequence[str]
    rows: Sequence[Sequence[str]]
    notes: Sequence[str] = field(default_factory=tuple)


def plotly_modules():
    """``(plotly.graph_objects, plotly.offline.get_plotlyjs)``, or a clear error without plotly."""
    try:
        import plotly.graph_objects as go
        from plotly.offline import get_plotlyjs
    except ImportError:
        raise ParameterError("the explorer needs plotly, which is not installed: pip install "
                             "-e '.[explorer]' in the moik repository (or pip install "
                             "plotly)") from None
    return go, get_plotlyjs


def _plain(fig) -> dict:
    """A plotly figure as plain JSON data (plotly's own encoder: numpy arrays included)."""
    return json.loads(fig.to_json())


def _postures(robot: Robot, X: np.ndarray, target) -> dict:
    """What the page draws for each member: frame origins and axes, joints, q, errors."""
    frames = robot.frames(X)
    p_t, R_t = target_pose(target)
    digits = max(0, 5 - int(np.floor(np.log10(max(robot.reach, 1e-12)))))
    out = {"q": X.tolist(),  # unrounded: a member at a limit stays within it
           "origins": np.round(frames[:, :, :3, 3], digits).tolist(),
           "rotations": np.round(frames[:, :, :3, :3], 5).tolist(),
           "joints": np.round(joint_origins(robot, frames), digits).tolist()}
    out["joint_labels"] = [_joint_labels(J, robot.reach) for J in out["joints"]]
    if p_t is not None:
        out["position_error"] = np.linalg.norm(frames[:, -1, :3, 3] - p_t, axis=1).tolist()
        if R_t is not None:
            out["orientation_error"] = [float(geodesic_error(T[:3, :3], R_t))
                                        for T in frames[:, -1]]
    return out


def _joint_labels(joints: list, scale: float) -> list[str]:
    """Joint numbers, coincident joints sharing one label ("1,2") as plot_robot does."""
    P = np.asarray(joints)
    labels = [""] * len(P)
    taken = np.zeros(len(P), dtype=bool)
    for j in range(len(P)):
        if not taken[j]:
            same = ~taken & (np.linalg.norm(P - P[j], axis=1) <= 1e-3 * scale)
            taken |= same
            labels[j] = ",".join(str(k + 1) for k in np.flatnonzero(same))
    return labels


def _scene(robot: Robot, postures: list, target, obstacles: bool = False,
           shapes: bool = False) -> dict:
    """A fixed cube around every embedded posture and the target (switching keeps the scale);
    the caption says what is drawn (``obstacles``: grey surfaces too; ``shapes``: the arm's
    collision shapes, blue)."""
    pts = [np.reshape(p["origins"], (-1, 3)) for p in postures if p]
    p_t, _ = target_pose(target)
    if p_t is not None:
        pts.append(p_t[None])
    P = np.vstack(pts + [np.zeros((1, 3))])
    centre, half = (P.max(0) + P.min(0)) / 2, max(float(np.ptp(P, axis=0).max()) / 2, 1e-9) * 1.1
    unit = robot.unit
    return {"margin": {"l": 0, "r": 0, "t": 50, "b": 0}, "showlegend": False,
            "title": {"text": f"posture ({unit}): links through the joint frames, joints "
                              "numbered,<br>frame axes x red, y green, z blue; target: red "
                              "diamond, its frame dashed"
                              + ("; obstacles grey" if obstacles else "")
                              + ("; collision shapes blue" if shapes else ""),
                      "font": {"size": 12}, "x": 0.02,
                      "xanchor": "left", "y": 0.97},
            "scene": {"aspectmode": "cube", **{
                f"{a}axis": {"range": [centre[k] - half, centre[k] + half],
                             "title": f"{a} ({unit})"}
                for k, a in enumerate("xyz")}}}


def _marker(colour: str, F: np.ndarray, names: list[str], n_fronts: int) -> dict:
    """One colour per algorithm; a single front of 3+ criteria is coloured by the third."""
    marker = {"color": colour, "size": 7, "line": {"width": 0.5, "color": "white"}}
    if n_fronts == 1 and len(names) >= 3:
        marker.update(color=F[:, 2], colorscale="Viridis", showscale=True,
                      colorbar={"title": {"text": names[2], "side": "right"}})
    return marker


def front_panel_data(panel: FrontPanel, go) -> dict:
    names = [str(n) for n in panel.objectives]
    if len(names) < 2:
        raise ShapeError(f"a front panel needs at least 2 criteria, got {names}")
    fig, traces = go.Figure(), []
    postures: list[dict | None] = []
    groups = list(dict.fromkeys(f.group or f.name for f in panel.fronts))
    for f in panel.fronts:
        F = as_array(f.F, f"front {f.name!r}", shape=(None, len(names)))
        colour = PALETTE[groups.index(f.group or f.name) % len(PALETTE)]
        custom = np.column_stack([np.arange(1, len(F) + 1), F])  # members numbered from 1
        hover = "<br>".join(f"{n}: %{{customdata[{k + 1}]:.5g}}" for k, n in enumerate(names))
        fig.add_trace(go.Scatter(
            x=F[:, 0], y=F[:, 1], mode="markers", name=f.name, legendgroup=f.group or f.name,
            customdata=custom, visible=True if f.visible else "legendonly",
            marker=_marker(colour, F, names, len(panel.fronts)),
            hovertemplate=f"<b>{f.name}</b>, member %{{customdata[0]}}<br>{hover}"
                          "<br>(click: posture)<extra></extra>"))
        traces.append({"name": f.name, "size": len(F), "F": F.tolist()})
        posture = None
        if panel.robot is not None and f.X is not None:
            X = panel.robot.check_q(as_array(f.X, f"members of {f.name!r}", shape=(len(F), None)))
            posture = _postures(panel.robot, X, panel.target)
        postures.append(posture)
    fig.add_trace(go.Scatter(x=[], y=[], mode="markers", name="selected", showlegend=False,
                             hoverinfo="skip", marker={"size": 17, "color": "rgba(0,0,0,0)",
                                                       "line": {"width": 2.5,
                                                                "color": "black"}}))
    fig.update_layout(xaxis_title=names[0], yaxis_title=names[1], hovermode="closest",
                      margin={"l": 60, "r": 10, "t": 30, "b": 50},
                      legend={"font": {"size": 10}}, clickmode="event",
                      showlegend=len(panel.fronts) > 1)
    out: dict[str, Any] = {
           "kind": "front", "title": panel.title, "figure": _plain(fig), "traces": traces,
           "objectives": names, "notes": list(panel.notes), "initial": list(panel.initial),
           "obstacles": list(panel.obstacles), "robot_shapes": list(panel.robot_shapes),
           "no_posture": "no joint vectors stored for this front"}
    if panel.robot is None or not any(postures):
        out["postures"] = None
        return out
    robot = panel.robot
    p_t, R_t = target_pose(panel.target)
    out.update(postures=postures, unit=robot.unit, scale=robot.reach,
               limits=robot.limits.tolist(), prismatic=robot.is_prismatic.tolist(),
               joint_names=list(robot.joint_names) or [f"q{j + 1}" for j in range(robot.dof)],
               target=None if p_t is None else {
                   "position": p_t.tolist(), "rotation": None if R_t is None else R_t.tolist()},
               scene_layout=_scene(robot, postures, panel.target, bool(panel.obstacles),
                                   bool(panel.robot_shapes)))
    return out


def curve_panel_data(panel: CurvePanel, go) -> dict:
    fig = go.Figure()
    log = all(np.all(np.asarray(c) > 0) for c in panel.curves.values())
    for k, (label, C) in enumerate(panel.curves.items()):
        C = np.atleast_2d(as_array(C, f"curves of {label!r}"))
        fig.add_trace(go.Scatter(y=C.mean(axis=0), mode="lines", name=f"{label} (mean of "
                                 f"{len(C)})", line={"color": PALETTE[k % len(PALETTE)]},
                                 hovertemplate=f"{label}<br>iteration %{{x}}: %{{y:.5g}}"
                                               "<extra></extra>"))
    fig.update_layout(xaxis_title=panel.xlabel, yaxis_title=panel.ylabel,
                      yaxis_type="log" if log else "linear",
                      margin={"l": 70, "r": 10, "t": 20, "b": 50})
    return {"kind": "curves", "title": panel.title, "figure": _plain(fig),
            "notes": list(panel.notes)}
