"""``moik solve ... --pareto CRITERIA``: the Pareto set of exact solutions on the command line.

:func:`run_pareto` is what ``solve`` runs when ``--pareto`` is given (the options are
in :mod:`moik.cli.parser`). It prints the members (joint values in degrees;
prismatic ones in the robot's unit) with their criteria and marks the compromise,
or with ``--json`` one JSON object (joint values in radians); ``--scene FILE`` /
``--self-collision`` (and ``--clearance``) make it collision-aware, as for ``solve``
(:mod:`moik.cli.collision`: each member's distance printed); ``--plot FILE``
draws the front and postures (:func:`moik.plotting.pareto.plot_pareto_ik`), ``--html
FILE`` writes the interactive explorer (:func:`moik.plotting.pareto_explorer`). Exit
status 0 when an exact solution was found, 1 otherwise.
"""

from __future__ import annotations

import argparse
import importlib.util
from pathlib import Path

import numpy as np

from moik.cli import collision
from moik.cli.common import PARETO_OPTIONS, joint_values, library_call, tolerance
from moik.cli.output import print_json
from moik.cli.parser import given
from moik.cli.solutions import euler_angles
from moik.cli.solutions import target as target_of
from moik.cli.timing import Compiling, compiling
from moik.exceptions import ParameterError
from moik.plotting.explorer import pareto_explorer
from moik.plotting.pareto import plot_pareto_ik
from moik.problems.targets import Target
from moik.robots import get_robot
from moik.solver.pareto import ParetoIKResult, solve_ik_pareto
from moik.warmup.beside import beside_pareto


def parse_criteria(text: str) -> tuple[str, ...]:
    """``"joint_motion,manipulability"`` as a tuple of names (validated by the solver)."""
    names = tuple(n.strip() for n in text.split(",") if n.strip())
    if not names:
        raise ParameterError(f"--pareto needs comma-separated criterion names, got {text!r}")
    return names


def run_pareto(args: argparse.Namespace, robot=None) -> int:
    """Solve, print (text or JSON) and optionally plot the Pareto set; the exit status.

    ``robot``: the arm the command line named (a catalog name or a URDF file); by
    default the catalog robot ``args.robot``."""
    robot = get_robot(args.robot) if robot is None else robot
    target = target_of(args)
    html = html_file(args.html)
    rotation = None
    if args.preferred_euler is not None:
        angles = euler_angles(args.preferred_euler, args.deg, "--preferred-euler")
        rotation = Target.from_euler(args.target, angles, convention=args.convention,
                                     degrees=args.deg).rotation
    q_current = (None if args.q_current is None
                 else joint_values(robot, args.q_current, args.deg, "--q-current"))
    options = given(args, "pareto_size", "pareto_method", "seed", "tol")
    if "tol" in options:
        options["tol"] = tolerance(options["tol"])
    criteria = parse_criteria(args.pareto)
    beside_pareto(robot, target, objectives=criteria, q_current=q_current, rotation=rotation,
                  **options)  # on a cold first run: the search algorithm's kernels
    check = collision.checker(args, robot)
    with library_call(PARETO_OPTIONS), collision.option_names(), compiling() as compiled:
        res = solve_ik_pareto(robot, target, objectives=criteria, q_current=q_current,
                              rotation=rotation, **options, **collision.solver_options(check))
    index = res.compromise_index() if len(res.X) else None
    plots = []
    if args.plot and len(res.X):
        path = Path(args.plot)  # a path's dots are not an extension (out.d/fig, ../x/p)
        stem = str(path.with_suffix("") if path.suffix in (".png", ".pdf", ".svg") else path)
        plot_pareto_ik(robot, res.X, res.F, objectives=res.objectives, senses=res.senses,
                       target=target.position, compromise=index, save=stem)
        plots = [f"{stem}.png", f"{stem}.pdf"]
    near = None if check is None else collision.distances(check, res.X)
    clearance = None if check is None else check.clearance
    if args.json:
        print_json(as_json(robot, target, res, index, plots, near, clearance))
    else:
        print(format_result(robot, target, res, index, clearance, compiled=compiled))
        if near:
            collision.print_distances(near, robot.unit, label="member", start=0)
    if plots and not args.json:
        print(f"plot written to {plots[0]} and {plots[1]}")
    if html is not None and len(res.X):
        pareto_explorer(res, robot, html, target=target,
                        scene=None if check is None else check.checker.scene,
                        collision=None if check is None else check.checker)
        if not args.json:
            print(f"explorer written to {html}")
    return 0 if len(res.X) else 1


def html_file(spec: str | None) -> Path | None:
    """The file ``--html`` writes, checked before any solving (its folder must exist)."""
    if spec is None:
        return None
    path = Path(spec)
    if not spec or path.is_dir():
        raise ParameterError(f"--html needs a file name, got {spec!r}")
    if not path.parent.is_dir():
        raise ParameterError(f"--html folder {str(path.parent)!r} does not exist (create it "
                             "first)")
    if importlib.util.find_spec("plotly") is None:  # before the search, not after it
        raise ParameterError("--html: the explorer needs plotly, which is not installed: pip "
                             "install -e '.[explorer]' in the moik repository (or pip install "
                             "plotly)")
    return path


def as_json(robot, target: Target, res: ParetoIKResult, compromise: int | None,
            plots: list[str] | None = None, collision: list[dict] | None = None,
            clearance: float | None = None) -> dict:
    """The result as plain JSON types, in the schema family of ``solve`` (see :mod:`moik.cli`).

    ``q`` and its errors are the compromise member's (null without a member);
    ``solutions`` every member (with ``--scene`` / ``--self-collision`` also its
    ``min_distance``, ``closest_pair`` and ``collides``, as ``solve`` gives them, and
    ``min_distance`` of ``q`` at the top level); ``status`` ``"solved"`` with members,
    ``"collides"`` without when exact points were found but none keeps the ``clearance``
    of a collision check (as ``solve`` says it), else ``"not-converged"``.
    """
    solved = compromise is not None
    members = [{"q": q.tolist(), "position_error": float(p), "orientation_error": float(o)}
               for q, p, o in zip(res.X, res.position_errors, res.orientation_errors,
                                  strict=True)]
    for member, near in zip(members, collision or [], strict=False):
        member.update(near)
    best = members[compromise] if compromise is not None else None
    return {"command": "pareto", "robot": robot.name, "unit": robot.unit,
            "joint_names": list(robot.joint_names),
            "target": {"position": target.position.tolist(),
                       "rotation": None if target.rotation is None else target.rotation.tolist()},
            "status": _status(res, compromise, clearance), "success": solved,
            "n_eval": res.n_eval, "time_s": res.time,
            "q": None if best is None else best["q"],
            "position_error": None if best is None else best["position_error"],
            "orientation_error": None if best is None else best["orientation_error"],
            "solutions": members, "objectives": list(res.objectives),
            "senses": list(res.senses), "F": res.F.tolist(), "compromise": compromise,
            "redundant": res.redundant, "n_exact": res.n_exact, "plots": plots or [],
            **({} if collision is None else
               {"min_distance": None if best is None else best["min_distance"]})}


def _status(res: ParetoIKResult, compromise: int | None, clearance: float | None) -> str:
    if compromise is not None:
        return "solved"
    return "collides" if clearance is not None and res.n_exact else "not-converged"


def format_result(robot, target: Target, res: ParetoIKResult, compromise: int | None,
                  clearance: float | None = None, *, compiled: Compiling | None = None) -> str:
    """The members as a table: criteria, then joint values in degrees (``clearance``: that
    of a collision check, for the verdict when no member keeps it)."""
    kind = "pose" if target.rotation is not None else "position"
    how = (f"memetic search over {res.n_exact} exact points" if res.redundant
           else f"the non-dominated of {res.n_exact} branches")
    lines = [f"robot {robot.name}: {kind} target {np.round(target.position, 6).tolist()} "
             f"{robot.unit}",
             f"{len(res.X)} exact solutions, mutually non-dominated ({how}, {res.n_eval} FK "
             f"evaluations, {(compiled or Compiling()).time_text(res.time)})"]
    if not len(res.X):
        if _status(res, compromise, clearance) == "collides":
            return "\n".join(lines + [f"status: collides (no exact point keeps the clearance "
                                       f"{clearance:g} {robot.unit}; {res.n_exact} exact "
                                       "points evaluated)"])
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
