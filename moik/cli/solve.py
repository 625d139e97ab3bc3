"""``moik solve ROBOT --target x y z [--euler a b c] ...``: inverse kinematics of one target.

With ``--pareto CRITERIA`` the command is :mod:`moik.cli.pareto` instead.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import numpy as np

from moik._validate import integer
from moik.cli import collision, pareto, solutions
from moik.cli.common import SOLVE_OPTIONS, joint_values, library_call, robot, tolerance
from moik.cli.parser import given
from moik.cli.solutions import target
from moik.cli.timing import compiling
from moik.exceptions import ParameterError
from moik.plotting.explorer import pareto_explorer
from moik.problems.targets import Target
from moik.robots import Robot
from moik.solver import solve_ik
from moik.solver.session import pose_errors
from moik.warmup.beside import beside_solve
from moik.warmup.beside_collision import beside_collision, beside_collision_early

PLOT_FORMATS = (".png", ".pdf", ".svg")


def plot_files(spec: str | None) -> list[Path]:
    """The files ``--plot`` writes, checked before any solving.

    ``.png``, ``.pdf`` or ``.svg``: that file; no extension: ``.png`` and ``.pdf``.
    """
    if spec is None:
        return []
    path = Path(spec)
    suffix = path.suffix.lower()
    if path.is_dir() or not path.name:
        raise ParameterError(f"--plot needs a file name, got the folder {spec!r}")
    if suffix and suffix not in PLOT_FORMATS:
        raise ParameterError(f"--plot file must end in {', '.join(PLOT_FORMATS)} (or have no "
                             f"extension for .png and .pdf), got {spec!r}")
    folder = path.parent
    if folder.exists() and not folder.is_dir():
        raise ParameterError(f"--plot folder {str(folder)!r} is a file, not a folder")
    if not folder.is_dir():
        raise ParameterError(f"--plot folder {str(folder)!r} does not exist (create it first)")
    if not os.access(folder, os.W_OK):
        raise ParameterError(f"--plot folder {str(folder)!r} is not writable")
    return [path] if suffix else [path.with_name(path.name + ext) for ext in (".png", ".pdf")]


def cmd_solve(args: argparse.Namespace) -> int:
    """Solve, print (text or JSON), optionally plot; 0 when solved, 1 otherwise (``collides``
    included)."""
    if args.pareto:
        return pareto.run_pareto(args, robot=robot(args))
    search = given(args, "method", "n_solutions", "starts", "max_evals", "seed", "tol")
    if "seed" in search:
        integer("--seed", search["seed"], minimum=0)
    if "tol" in search:
        search["tol"] = tolerance(search["tol"])
    plots = plot_files(args.plot)
    html = pareto.html_file(args.html)
    arm = robot(args)
    scene = getattr(args, "scene", None) is not None
    # on a cold first run: the distance kernels, compiled while the checker is built
    early = (beside_collision_early(arm, scene=scene)
             if scene or getattr(args, "self_collision", False) else None)
    goal = target(args)
    q_current = (None if args.q_current is None
                 else joint_values(arm, args.q_current, args.deg, "--q-current"))
    check = collision.checker(args, arm)
    if check is None:
        beside_solve(arm, goal)  # on a cold first run: the leaf kernels of its path
    else:
        beside_collision(check.checker, early=early)  # that child, or one on the checker
    with library_call(SOLVE_OPTIONS), compiling() as compiled:
        res = solve_ik(arm, goal, q_current=q_current, **search,
                       **collision.solver_options(check))
    Q = res.solutions if len(res.solutions) else res.q[None]
    pos, ori = pose_errors(arm, goal, Q[1:]) if len(Q) > 1 else ((), ())
    errors = [(res.position_error, res.orientation_error)] + [
        (float(p), float(o)) for p, o in zip(pos, ori, strict=True)]
    if plots:
        _plot(arm, goal, Q, res.status, plots)
    near = None if check is None else collision.distances(check, Q)
    if args.json:
        solutions.print_solve_json(arm, goal, res, errors, plots, res.n_requested,
                                   collision=near)
    else:
        solutions.print_solve(arm, goal, res, Q, errors, plots, compiled=compiled)
        if near is not None:
            collision.print_distances(near, arm.unit)
        if res.unchecked_links:
            print(f"not checked (no collision geometry): {', '.join(res.unchecked_links)}")
    if html is not None:
        _explore(arm, goal, res, html, quiet=args.json)
    return 0 if res.success else 1


def _explore(arm: Robot, goal: Target, res, html: Path, *, quiet: bool) -> None:
    """``--html`` without ``--pareto``: the error front of an unreachable pose, if any."""
    if res.front is None:
        print(f"moik: --html: no front to explore (status {res.status}: fronts come with "
              "unreachable poses; --pareto gives the Pareto set of a reachable one)",
              file=sys.stderr)
        return
    pareto_explorer(res, arm, html, target=goal,
                           title=f"{arm.name}: error front of an unreachable pose")
    if not quiet:
        print(f"explorer written to {html}")


def _plot(robot: Robot, target: Target, Q: np.ndarray, status: str, files: list[Path]) -> None:
    import matplotlib.pyplot as plt  # lazy: keeps the command's start-up fast

    from moik.plotting import plot_robot

    labels = ([f"solution {k}" for k in range(1, len(Q) + 1)] if status == "solved"
              else [f"best ({status})"])
    ax = plot_robot(robot, Q, labels=labels, target=target)
    for path in files:
        ax.figure.savefig(path, dpi=120, bbox_inches="tight")  # the legend sits outside
    plt.close(ax.figure)
