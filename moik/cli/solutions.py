"""The target a solving command reads, and how poses and solutions print (text or JSON).

The JSON documents are described in :mod:`moik.cli`.
"""

from __future__ import annotations

import argparse

import numpy as np

from moik.cli.output import display_q, floats, kind, print_json, q_units
from moik.cli.timing import Compiling
from moik.exceptions import TargetError
from moik.kinematics.orientation import eosma_euler, zyx_euler
from moik.problems.targets import Target
from moik.robots import Robot


def target(args: argparse.Namespace) -> Target:
    """The target of ``--target`` and ``--euler`` (``--convention``, ``--deg``)."""
    if args.euler is None:
        return Target(args.target)
    return Target.from_euler(args.target, euler_angles(args.euler, args.deg, "--euler"),
                             convention=args.convention, degrees=args.deg)


def euler_angles(angles: list[float], degrees: bool, option: str) -> list[float]:
    """``angles`` as given; refused in the command's words when, without ``--deg``, one
    exceeds 2 pi (the library says ``degrees=True``)."""
    if not degrees and any(abs(a) > 2 * np.pi + 1e-9 for a in angles):
        raise TargetError(f"{option} angles {angles} exceed 2 pi in magnitude; they are "
                          "radians: add --deg to give degrees")
    return angles


def print_pose(robot: Robot, q: np.ndarray, T: np.ndarray, inside: bool, as_json: bool) -> None:
    """The pose ``T`` of joint vector ``q``: matrix, position and Euler angles, full precision."""
    R = T[:3, :3]
    if as_json:
        print_json({"command": "fk", "robot": robot.name, "unit": robot.unit,
                    "joint_names": list(robot.joint_names), "q": q.tolist(),
                    "pose": T.tolist(), "position": T[:3, 3].tolist(),
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


def print_solve_json(robot: Robot, target: Target, res, errors: list, plots: list,
                     n_solutions: int, collision: list | None = None) -> None:
    """The ``solve`` document: status, q, errors, every solution with its errors, front
    (and with ``--scene`` ``q``'s ``min_distance``, the ``unchecked_links`` (no geometry,
    left unchecked by ``--allow-missing-geometry``) and each solution's ``min_distance``,
    ``closest_pair``, ``collides``)."""
    extra = collision or []
    print_json({
        "command": "solve", "robot": robot.name, "unit": robot.unit,
        "joint_names": list(robot.joint_names),
        "target": {"position": target.position.tolist(),
                   "rotation": None if target.rotation is None else target.rotation.tolist()},
        "status": res.status, "success": res.success, "n_eval": res.n_eval,
        "n_solutions": n_solutions, "fewer_solutions": bool(res.fewer_solutions),
        "detail": res.detail,
        "time_s": res.time, "q": res.q.tolist(), "position_error": res.position_error,
        "orientation_error": res.orientation_error,
        **({} if res.min_distance is None else {"min_distance": res.min_distance,
                                                  "unchecked_links": list(res.unchecked_links)}),
        "solutions": [{"q": q.tolist(), "position_error": p, "orientation_error": o,
                       **(extra[k] if k < len(extra) else {})}
                      for k, (q, (p, o)) in enumerate(zip(res.solutions, errors,
                                                          strict=False))],
        "front": None if res.front is None else res.front.tolist(),
        "plots": [str(p) for p in plots]})


def print_solve(robot: Robot, target: Target, res, Q: np.ndarray, errors: list, plots: list,
                *, compiled: Compiling | None = None) -> None:
    """Every solution (or the best candidate / the compromise) with its errors, in words
    that say what an unsolved ``q`` is; the time without the compiling of ``compiled``."""
    what = "pose" if target.has_orientation else "position"
    print(f"robot {robot.name}: {what} target {floats(target.position)} {robot.unit}")
    spent = (compiled or Compiling()).time_text(res.time)
    print(f"status: {res.status}  ({res.n_eval} FK evaluations, {spent})")
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
    if res.fewer_solutions:  # the solver's words: found k of the n requested (why)
        print(f"note: {res.detail or 'fewer distinct solutions than --n-solutions asked for'}")
    if plots:
        print("plot written to " + " and ".join(str(p) for p in plots))
