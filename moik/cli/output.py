"""How the ``moik`` command prints: text for people, one JSON object for scripts.

The JSON documents are described in :mod:`moik.cli`; in them, angles and revolute
joint values are radians, lengths and prismatic joint values the robot's unit.
The text shows revolute joints in degrees and prismatic joints in the robot's unit
(never through degrees), and poses in full precision (``repr`` of floats), so a
pose printed by ``moik fk`` can be pasted into ``moik solve``.
"""

from __future__ import annotations

import json

import numpy as np

from moik.kinematics.orientation import eosma_euler, zyx_euler
from moik.problems.targets import Target
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
    """``obj`` as one line of JSON (floats in full precision)."""
    print(json.dumps(obj))


def floats(values) -> str:
    """``(v1, v2, ...)`` with each float's ``repr`` (every digit; no ``-0.0``)."""
    return "(" + ", ".join(repr(float(v) + 0.0) for v in values) + ")"


def print_robot_list(robots: list[Robot], as_json: bool) -> None:
    """The catalog: name, DOF, kind, unit and source of each robot."""
    if as_json:
        print_json({"robots": [{"name": r.name, "dof": r.dof, "kind": kind(r), "unit": r.unit,
                                "source": r.source} for r in robots]})
        return
    print(f"{'name':<18}{'dof':>4}  {'kind':<15}{'unit':<5} source")
    for r in robots:
        print(f"{r.name:<18}{r.dof:>4}  {kind(r):<15}{r.unit:<5} {r.source}")


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
    print(f"{'name':<10}{'kind':<18}source")
    for e in entries:
        print(f"{e.name:<10}{e.kind:<18}{e.source}")


def print_pose(robot: Robot, q: np.ndarray, T: np.ndarray, inside: bool, as_json: bool) -> None:
    """The pose ``T`` of joint vector ``q``: matrix, position and Euler angles, full precision."""
    R = T[:3, :3]
    if as_json:
        print_json({"robot": robot.name, "unit": robot.unit, "joint_names": robot.joint_names,
                    "q": q.tolist(), "pose": T.tolist(), "position": T[:3, 3].tolist(),
                    "rotation": R.tolist(), "zyx_euler": zyx_euler(R).tolist(),
                    "eosma_euler": eosma_euler(R).tolist(), "within_limits": inside})
        return
    print(f"robot {robot.name} ({robot.dof} DOF, {kind(robot)}, {robot.unit})")
    print("pose T:")
    for row in T:
        print("  " + floats(row))
    print(f"position ({robot.unit}): {floats(T[:3, 3])}")
    print(f"ZYX Euler (alpha, beta, gamma) deg: {floats(np.degrees(zyx_euler(R)))}")
    print(f"EOSMA Eq. 26 Euler (alpha, beta, gamma) deg: {floats(np.degrees(eosma_euler(R)))}")


def print_solve_json(robot: Robot, target: Target, res, errors: list, plots: list) -> None:
    """The ``solve`` document: status, q, errors, every solution with its errors, front."""
    print_json({
        "robot": robot.name, "unit": robot.unit, "joint_names": robot.joint_names,
        "target": {"position": target.position.tolist(),
                   "rotation": None if target.rotation is None else target.rotation.tolist()},
        "status": res.status, "success": res.success, "n_eval": res.n_eval,
        "time_s": res.time, "q": res.q.tolist(), "position_error": res.position_error,
        "orientation_error": res.orientation_error,
        "solutions": [{"q": q.tolist(), "position_error": p, "orientation_error": o}
                      for q, (p, o) in zip(res.solutions, errors, strict=False)],
        "front": None if res.front is None else res.front.tolist(),
        "plots": [str(p) for p in plots]})


def print_solve(robot: Robot, target: Target, res, Q: np.ndarray, errors: list, plots: list
                ) -> None:
    """Every solution (or the best candidate / the compromise) with its errors, in words
    that say what an unsolved ``q`` is."""
    what = "pose" if target.has_orientation else "position"
    print(f"robot {robot.name}: {what} target {floats(target.position)} {robot.unit}")
    print(f"status: {res.status}  ({res.n_eval} FK evaluations, {res.time * 1e3:.1f} ms)")
    print(f"joints: {' '.join(robot.joint_names)}  ({q_units(robot)})")
    if res.success:
        labels = [f"solution {k}" for k in range(1, len(Q) + 1)]
    elif res.status == "unreachable" and res.front is not None:
        labels = ["compromise"]
    else:
        labels = ["best candidate"]
    for label, q, (pos, ori) in zip(labels, Q, errors, strict=True):
        print(f"{label}: " + " ".join(f"{v:.6f}" for v in display_q(robot, q)))
        line = f"  position error {pos:.3e} {robot.unit}"
        if target.has_orientation:
            line += f", orientation error {ori:.3e} rad (geodesic)"
        print(line)
    if res.status == "unreachable":
        if res.front is not None:
            print(f"Pareto front of (position, orientation) errors: {len(res.front)} points; "
                  "the compromise above is the one closest to the utopia point")
        else:
            print("the target is out of reach; the best candidate above comes closest")
    elif res.status == "not-converged":
        front = "" if res.front is None else (f" (Pareto front of (position, orientation) "
                                              f"errors: {len(res.front)} points)")
        print(f"not converged: the best candidate above is the closest found{front}; more "
              "--max-evals, --starts or another --seed may solve it")
    if plots:
        print("plot written to " + " and ".join(str(p) for p in plots))
