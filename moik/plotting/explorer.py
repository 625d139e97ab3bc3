"""The interactive explorer: Pareto fronts linked to the postures behind their points.

One self-contained HTML file (plotly.js inline once; nothing is fetched when it is
opened): each front panel plots the fronts (one trace per algorithm and run, hover
values on every point); clicking a member draws that posture in 3-D (links through
the joint frames, the joints numbered, every frame's axes, the target and its frame)
and lists its joint values, limits and errors, recomputed by the robot's FK
(:meth:`moik.robots.Robot.frames`, the frames :func:`moik.plotting.plot_robot`
draws). Curve panels plot convergence curves, table panels the report's statistics.

plotly is an optional dependency (the ``explorer`` extra: ``pip install -e
'.[explorer]'`` in the repository), imported only when a page is written.

>>> from moik import get_robot, solve_ik_pareto
>>> from moik.plotting import pareto_explorer
>>> robot = get_robot("panda")
>>> res = solve_ik_pareto(robot, pose, q_current=q0)           # doctest: +SKIP
>>> pareto_explorer(res, robot, "front.html", target=pose)     # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from moik._paths import atomic_write_bytes
from moik.collision.model import CollisionChecker, CollisionModel
from moik.exceptions import ParameterError, ShapeError
from moik.plotting._explorer_page import page
from moik.plotting.explorer_panels import (
    CurvePanel,
    Front,
    FrontPanel,
    TablePanel,
    curve_panel_data,
    front_panel_data,
    plotly_modules,
)
from moik.plotting.geometry import robot_meshes, scene_traces
from moik.plotting.pareto import UNITS
from moik.robots.chain import Robot

if TYPE_CHECKING:
    from moik.collision.model import Scene

__all__ = ["CurvePanel", "Front", "FrontPanel", "TablePanel", "pareto_explorer",
           "write_explorer"]


def write_explorer(path: str | Path, panels: Sequence[FrontPanel | CurvePanel | TablePanel], *,
                   title: str, notes: Sequence[str] = ()) -> Path:
    """Write the explorer page of ``panels`` to ``path`` (one self-contained HTML file).

    Returns:
        The path written.

    Raises:
        ParameterError: plotly is not installed, or no panel was given.
        ShapeError: A front whose criteria or members do not match.
    """
    if not panels:
        raise ParameterError("the explorer needs at least one panel")
    go, get_plotlyjs = plotly_modules()
    built = []
    for panel in panels:
        if isinstance(panel, FrontPanel):
            built.append(front_panel_data(panel, go))
        elif isinstance(panel, CurvePanel):
            built.append(curve_panel_data(panel, go))
        elif isinstance(panel, TablePanel):
            built.append({"kind": "table", "title": panel.title, "header": list(panel.header),
                          "rows": [list(r) for r in panel.rows], "notes": list(panel.notes)})
        else:
            raise ParameterError(f"panels must be FrontPanel, CurvePanel or TablePanel, got "
                                 f"{type(panel).__name__}")
    path = Path(path)
    html = page(title=title, notes=list(notes), panels=built, plotlyjs=get_plotlyjs())
    atomic_write_bytes(path, html.encode("utf-8"))  # never written through a link
    return path


def _label(name: str, sense: str) -> str:
    unit = f", {UNITS[name]}" if name in UNITS else ""
    return f"{name} ({'larger' if sense == 'max' else 'smaller'} is better{unit})"


def _as_front(name: str, result, unit: str) -> tuple[Front, list[str], int]:
    """A ParetoIKResult, an IKResult with a front, or a dict of arrays as one trace, its
    criteria's labels, and the member shown first (the compromise where there is one)."""
    if hasattr(result, "objectives") and hasattr(result, "senses"):  # ParetoIKResult
        labels = [_label(n, s) for n, s in zip(result.objectives, result.senses, strict=True)]
        first = result.compromise_index() if len(result.X) else 0
        return Front(name, np.asarray(result.F), np.asarray(result.X)), labels, first
    if hasattr(result, "front") and hasattr(result, "front_q"):  # IKResult of solve_ik
        if result.front is None:
            raise ParameterError(f"{name}: this solve_ik result has no front (status "
                                 f"{result.status!r}: fronts come with unreachable poses)")
        Q = np.asarray(result.front_q)  # the solver's compromise, res.q, is a member
        first = int(np.argmin(np.linalg.norm(Q - np.asarray(result.q), axis=1)))
        return (Front(name, np.asarray(result.front), Q),
                [f"position error ({unit})", "orientation error (geodesic, rad)"], first)
    if isinstance(result, Mapping) and "F" in result:
        F = np.atleast_2d(np.asarray(result["F"], dtype=float))
        names = list(result.get("objectives") or [f"f{k + 1}" for k in range(F.shape[1])])
        senses = list(result.get("senses") or ["min"] * len(names))
        return (Front(name, F, None if result.get("X") is None else np.asarray(result["X"])),
                [_label(n, s) for n, s in zip(names, senses, strict=True)], 0)
    raise ParameterError("result must be a ParetoIKResult, a solve_ik result with a front, a "
                         "dict with 'F' (and 'X', 'objectives', 'senses') or a dict of these, "
                         f"got {type(result).__name__}")


def _collision_model(collision, robot: Robot) -> CollisionModel | None:
    """The :class:`~moik.collision.CollisionModel` of ``collision`` (a model, a checker or
    None), checked to be ``robot``'s."""
    if collision is None:
        return None
    model = collision.model if isinstance(collision, CollisionChecker) else collision
    if not isinstance(model, CollisionModel):
        raise ParameterError(f"collision must be a CollisionModel or a CollisionChecker, got "
                             f"{type(collision).__name__}")
    if model.robot is not robot and (model.robot.name != robot.name
                                     or model.robot.dof != robot.dof):
        raise ParameterError(f"collision is the geometry of robot {model.robot.name!r}, the "
                             f"explorer draws {robot.name!r}")
    return model


def pareto_explorer(result, robot: Robot, path: str | Path, *, target=None,
                    title: str | None = None, scene: Scene | None = None,
                    obstacles: Sequence[dict] = (),
                    collision: CollisionChecker | CollisionModel | None = None) -> Path:
    """Write the explorer of one or several Pareto sets of IK solutions.

    Args:
        result: A :class:`moik.solver.pareto.ParetoIKResult`, a
            :func:`moik.solve_ik` result of an unreachable pose (its front of
            position and orientation errors), a dict of arrays ``{"F": (k, m),
            "X": (k, dof), "objectives": names, "senses": "min"/"max" each}``, or
            a dict ``{label: one of these}`` (one trace each, same criteria).
        robot: The arm.
        path: The HTML file to write.
        target: The target (position, ``(4, 4)`` pose or Target): drawn in the
            posture view, and each member's errors are recomputed against it.
        title: Page title.
        scene: A :class:`~moik.collision.Scene` whose obstacles are drawn in every
            posture (:func:`moik.plotting.geometry.scene_traces`; a half-space as a
            patch of its plane the size of the robot's reach).
        obstacles: More plotly 3-D trace dicts (e.g. ``{"type": "mesh3d", ...}``) drawn
            in every posture.
        collision: The geometry the answers were checked against: a
            :class:`~moik.collision.CollisionModel` of ``robot`` or a
            :class:`~moik.collision.CollisionChecker` (its scene's obstacles are drawn too
            when ``scene`` is not given). Its robot shapes are drawn at each posture, a
            compound as its convex parts (:func:`moik.plotting.geometry.robot_meshes`);
            ``solve_ik``'s own is ``moik.solver.collision.default_model(robot)``.

    Returns:
        The path written.

    Raises:
        ParameterError: plotly is missing, ``result`` is none of the above, or
            ``collision`` is not a model or checker of ``robot``.
        ShapeError: Arrays of inconsistent shapes.
    """
    model = _collision_model(collision, robot)
    if scene is None and isinstance(collision, CollisionChecker):
        scene = collision.scene
    several = isinstance(result, Mapping) and "F" not in result
    single = "error front" if hasattr(result, "front_q") else "Pareto set"
    items = list(result.items()) if several else [(single, result)]
    fronts: list[Front] = []
    labels: list[str] | None = None
    first = 0
    for name, res in items:
        front, names, best = _as_front(str(name), res, robot.unit)
        if labels is not None and names != labels:
            raise ShapeError(f"every front must have the same criteria: {labels} and {names}")
        labels, first = names, first if fronts else best
        fronts.append(front)
    panel = FrontPanel(title="Pareto front: click a point to see its posture", fronts=fronts,
                       objectives=labels or [], robot=robot, target=target,
                       initial=(0, first),
                       obstacles=(*([] if scene is None else
                                    scene_traces(scene, span=robot.reach)), *obstacles),
                       robot_shapes=() if model is None else robot_meshes(model),
                       notes=["The ring marks the member shown; the first member shown is "
                              "the compromise (closest to the utopia point) when the result "
                              "has one. Joint numbers shared by several joints mark joints "
                              "at one place."])
    return write_explorer(path, [panel], title=title or f"{robot.name}: Pareto set of IK "
                          f"solutions ({sum(len(f.F) for f in fronts)} members)")
