"""``moik solve ... --pareto CRITERIA``: the Pareto set of exact solutions on the command line.

:func:`add_pareto_arguments` registers the options on the ``solve`` subcommand's
parser; :func:`run_pareto` is what ``solve`` runs when ``--pareto`` is given. It
prints the members (joint values in degrees; prismatic ones in the robot's unit)
with their criteria and marks the compromise, or with ``--json`` one JSON object
(joint values in radians); ``--plot FILE`` draws the front and postures
(:func:`moik.plotting.pareto.plot_pareto_ik`). Exit status 0 when an exact
solution was found, 1 otherwise.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from moik.exceptions import ParameterError
from moik.kinematics.criteria import CRITERIA
from moik.plotting.pareto import plot_pareto_ik
from moik.problems.targets import Target
from moik.robots import get_robot
from moik.solver.pareto import ParetoIKResult, solve_ik_pareto


def add_pareto_arguments(parser: argparse.ArgumentParser) -> None:
    """Register ``--pareto``, ``--preferred-euler``, ``--pareto-size`` and ``--pareto-method``
    on the ``solve`` parser, and ``--json`` / ``--q-current`` unless it has them already."""
    known = parser._option_string_actions  # argparse's registry of option strings
    parser.add_argument("--pareto", metavar="CRITERIA",
                        help="the Pareto set of exact solutions over these comma-separated "
                             f"criteria ({', '.join(CRITERIA)})")
    if "--json" not in known:
        parser.add_argument("--json", action="store_true",
                            help="with --pareto: print one JSON object (joint values in rad)")
    if "--q-current" not in known:
        parser.add_argument("--q-current", nargs="+", type=float, metavar="Q",
                            help="current configuration (rad, deg with --deg; needed by "
                                 "joint_motion)")
    parser.add_argument("--preferred-euler", nargs=3, type=float, metavar=("A", "B", "C"),
                        help="preferred orientation of a position target (the 'orientation' "
                             "criterion), Euler angles as --euler")
    parser.add_argument("--pareto-size", type=int, default=20,
                        help="most members returned with --pareto (default 20)")
    parser.add_argument("--pareto-method", default="moeosma",
                        help="multi-objective algorithm of the --pareto search (default moeosma)")


def parse_criteria(text: str) -> tuple[str, ...]:
    """``"joint_motion,manipulability"`` as a tuple of names (validated by the solver)."""
    names = tuple(n.strip() for n in text.split(",") if n.strip())
    if not names:
        raise ParameterError(f"--pareto needs comma-separated criterion names, got {text!r}")
    return names


def _target(args: argparse.Namespace) -> Target:
    if args.euler is None:
        return Target(args.target)
    return Target.from_euler(args.target, args.euler, convention=args.convention,
                             degrees=args.deg)


def _q_current(args: argparse.Namespace, robot) -> np.ndarray | None:
    if args.q_current is None:
        return None
    q = np.asarray(args.q_current, dtype=float)
    if q.shape != (robot.dof,):
        raise ParameterError(f"--q-current needs {robot.dof} joint values for robot "
                             f"{robot.name!r}, got {q.size}")
    return np.where(robot.is_prismatic, q, np.radians(q)) if args.deg else q


def run_pareto(args: argparse.Namespace, robot=None) -> int:
    """Solve, print (text or JSON) and optionally plot the Pareto set; the exit status.

    ``robot``: the arm the command line named (a catalog name or a URDF file); by
    default the catalog robot ``args.robot``."""
    robot = get_robot(args.robot) if robot is None else robot
    target = _target(args)
    rotation = None
    if args.preferred_euler is not None:
        rotation = Target.from_euler(args.target, args.preferred_euler,
                                     convention=args.convention, degrees=args.deg).rotation
    res = solve_ik_pareto(robot, target, objectives=parse_criteria(args.pareto),
                          q_current=_q_current(args, robot), n_solutions=args.pareto_size,
                          seed=args.seed, method=args.pareto_method, rotation=rotation)
    index = res.compromise_index() if len(res.X) else None
    print(json.dumps(as_json(robot, target, res, index)) if args.json
          else format_result(robot, target, res, index))
    if args.plot and len(res.X):
        path = Path(args.plot)  # a path's dots are not an extension (out.d/fig, ../x/p)
        stem = str(path.with_suffix("") if path.suffix in (".png", ".pdf", ".svg") else path)
        plot_pareto_ik(robot, res.X, res.F, objectives=res.objectives, senses=res.senses,
                       target=target.position, compromise=index, save=stem)
        if not args.json:
            print(f"plot written to {stem}.png and {stem}.pdf")
    return 0 if len(res.X) else 1


def as_json(robot, target: Target, res: ParetoIKResult, compromise: int | None) -> dict:
    """The result as plain JSON types (joint values in rad, prismatic in the robot's unit)."""
    return {"robot": robot.name, "unit": robot.unit, "target_position": target.position.tolist(),
            "target_rotation": None if target.rotation is None else target.rotation.tolist(),
            "objectives": list(res.objectives), "senses": list(res.senses),
            "X": res.X.tolist(), "F": res.F.tolist(),
            "position_errors": res.position_errors.tolist(),
            "orientation_errors": res.orientation_errors.tolist(), "compromise": compromise,
            "redundant": res.redundant, "n_exact": res.n_exact, "n_eval": res.n_eval,
            "time": res.time}


def format_result(robot, target: Target, res: ParetoIKResult, compromise: int | None) -> str:
    """The members as a table: criteria, then joint values in degrees."""
    kind = "pose" if target.rotation is not None else "position"
    how = (f"memetic search over {res.n_exact} exact points" if res.redundant
           else f"the non-dominated of {res.n_exact} branches")
    lines = [f"robot {robot.name}: {kind} target {np.round(target.position, 6).tolist()} "
             f"{robot.unit}",
             f"{len(res.X)} exact solutions, mutually non-dominated ({how}, {res.n_eval} FK "
             f"evaluations, {res.time * 1e3:.1f} ms)"]
    if not len(res.X):
        return "\n".join(lines + ["no exact solution found"])
    heads = [f"{n} ({'max' if s == 'max' else 'min'})" for n, s in
             zip(res.objectives, res.senses, strict=True)]
    lines.append("   # " + " ".join(f"{h:>22}" for h in heads) + "   q (deg; prismatic in "
                 f"{robot.unit})")
    for i, (q, f) in enumerate(zip(res.X, res.F, strict=True)):
        q_shown = np.where(robot.is_prismatic, q, np.degrees(q))
        mark = "*" if i == compromise else " "
        lines.append(f"{mark}{i:>3} " + " ".join(f"{v:>22.6g}" for v in f) + "   "
                     + " ".join(f"{v:.4f}" for v in q_shown))
    lines.append(f"* compromise (closest to the utopia point); largest errors: position "
                 f"{res.position_errors.max():.2e} {robot.unit}, orientation "
                 f"{res.orientation_errors.max():.2e} rad")
    return "\n".join(lines)
