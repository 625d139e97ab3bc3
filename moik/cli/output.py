"""How the ``moik`` command prints: text for people, one JSON object for scripts.

This module holds what every command shares and the catalog listings (it needs no
numba: ``moik robots`` stays fast); poses and solutions print in
:mod:`moik.cli.solutions`.

The JSON documents are described in :mod:`moik.cli`; in them, angles and revolute
joint values are radians, lengths and prismatic joint values the robot's unit.
The text shows revolute joints in degrees and prismatic joints in the robot's unit
(never through degrees), and poses in full precision (``repr`` of floats), so a
pose printed by ``moik fk`` can be pasted into ``moik solve``.
"""

from __future__ import annotations

import json
import math
from collections.abc import Collection
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from moik.robots import Robot


def kind(robot: Robot) -> str:
    """``"standard DH"``, ``"modified DH"`` or ``"general chain"`` (URDF, locked joints)."""
    return f"{robot.convention} DH" if robot.is_dh else "general chain"


def display_q(robot: Robot, q: np.ndarray) -> np.ndarray:
    """Revolute joints in degrees, prismatic joints in the robot's unit."""
    return np.where(robot.is_prismatic, q, np.degrees(q))


def q_units(robot: Robot) -> str:
    """The units :func:`display_q` shows, in words."""
    if not robot.is_prismatic.any():
        return "deg"
    return f"deg; prismatic in {robot.unit}" if not robot.is_prismatic.all() else robot.unit


def print_json(obj) -> None:
    """``obj`` as one line of strict JSON (floats in full precision, a non-finite one as
    ``null``: ``Infinity`` and ``NaN`` are not JSON)."""
    print(json.dumps(json_ready(obj), allow_nan=False))


def json_ready(value):
    """``value`` with numpy scalars and arrays as Python values, non-finite floats as None."""
    if isinstance(value, dict):
        return {k: json_ready(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(v) for v in value]
    if isinstance(value, np.ndarray):
        return json_ready(value.tolist())
    if isinstance(value, np.integer | np.bool_):
        return value.item()
    if isinstance(value, float | np.floating):
        return float(value) if math.isfinite(value) else None
    return value


def floats(values) -> str:
    """``(v1, v2, ...)`` with each float's ``repr`` (every digit; no ``-0.0``)."""
    return "(" + ", ".join(repr(float(v) + 0.0) for v in values) + ")"


def table(header: list[str], rows: list[list[str]], right: Collection[int] = ()) -> str:
    """Rows of text as columns sized to their widest cell (header included), two spaces
    apart; the columns whose index is in ``right`` are right-aligned, the last is not
    padded."""
    cells = [header, *rows]
    widths = [max(len(r[i]) for r in cells) for i in range(len(header))]
    lines = []
    for r in cells:
        parts = [c.rjust(w) if i in right else c.ljust(w)
                 for i, (c, w) in enumerate(zip(r, widths, strict=True))]
        parts[-1] = parts[-1] if len(header) - 1 in right else r[-1]
        lines.append("  ".join(parts).rstrip())
    return "\n".join(lines)


def print_robot_list(robots: list[Robot], as_json: bool) -> None:
    """The catalog: name, DOF, kind, unit and source of each robot."""
    if as_json:
        print_json({"robots": [{"name": r.name, "dof": r.dof, "kind": kind(r), "unit": r.unit,
                                "source": r.source} for r in robots]})
        return
    print(table(["name", "dof", "kind", "unit", "source"],
                [[r.name, str(r.dof), kind(r), r.unit, r.source] for r in robots], right={1}))


def print_robot(robot: Robot, as_json: bool) -> None:
    """One robot: its joints (names, types, limits), DH rows, base/tool, unit and source."""
    dh = {k: getattr(robot, k).tolist() for k in ("a", "alpha", "d", "theta")} if robot.is_dh \
        else None
    if as_json:
        joints = [{"name": n, "type": t, "lower": float(lo), "upper": float(hi)} for n, t, lo, hi
                  in zip(robot.joint_names, robot.joint_types, robot.lower, robot.upper,
                         strict=True)]
        print_json({"name": robot.name, "dof": robot.dof, "kind": kind(robot),
                    "unit": robot.unit, "source": robot.source, "joints": joints, "dh": dh,
                    "base": robot.base.tolist(), "tool": robot.tool.tolist()})
        return
    print(f"robot {robot.name}: {robot.dof} DOF, {kind(robot)}, lengths in {robot.unit}")
    print(f"source: {robot.source}")
    width = max(5, *(len(n) for n in robot.joint_names)) + 2
    lower, upper = display_q(robot, robot.lower), display_q(robot, robot.upper)
    head = f"{'#':>3} {'name':<{width}}{'type':<11}{'lower':>12}{'upper':>12}"
    if robot.is_dh:
        head += f"{'a':>12}{'alpha(deg)':>12}{'d':>12}{'theta(deg)':>12}"
    print(f"joints (limits in {q_units(robot)}):")
    print(head)
    for j in range(robot.dof):
        row = (f"{j + 1:>3} {robot.joint_names[j]:<{width}}{robot.joint_types[j]:<11}"
               f"{lower[j]:>12.6g}{upper[j]:>12.6g}")
        if dh is not None:
            row += (f"{dh['a'][j]:>12.6g}{np.degrees(dh['alpha'][j]):>12.6g}"
                    f"{dh['d'][j]:>12.6g}{np.degrees(dh['theta'][j]):>12.6g}")
        print(row)
    for key in ("base", "tool"):
        T = getattr(robot, key)
        if not np.array_equal(T, np.eye(4)):
            print(f"{key}: " + "; ".join(" ".join(repr(float(v)) for v in row) for row in T[:3]))


def print_algorithms(entries: list, as_json: bool) -> None:
    """The registered algorithms: name, kind and source."""
    if as_json:
        print_json({"algorithms": [{"name": e.name, "kind": e.kind, "source": e.source}
                                   for e in entries]})
        return
    print(table(["name", "kind", "source"], [[e.name, e.kind, e.source] for e in entries]))
