"""The ``moik`` command line (also ``python -m moik``).

Subcommands:
    moik robots [ROBOT]              list the catalog, or one robot's joints, DH rows, unit, source
    moik algorithms                  list the registered algorithms (name, kind, source)
    moik fk ROBOT q1 ... qn [--deg]  print the end-effector pose (full precision)
    moik solve ROBOT --target x y z [--euler a b c [--deg]] ...   solve IK
    moik experiment list             list the papers' experiments
    moik experiment run NAME [--quick] [--workers N] [--resume] [--out DIR] [--dask-scheduler A]
    moik experiment run --config FILE [...]   run your own config file
    moik report DIR [DIR ...]        Markdown report of each results folder (DIR/report.md)
    moik report DIR [DIR ...] --docs DOCS   regenerate DOCS/results/NAME.md and the generated
                                     blocks of DOCS/reproducing.md from the results

ROBOT is a catalog name (``moik robots``) or a URDF file (``--base``/``--tip``
name the chain's first and last links). Joint values on the command line are
radians, or degrees with ``--deg`` (prismatic joints always in the robot's unit).

``--json`` (robots, algorithms, fk, solve) prints one JSON object on stdout for
scripts; lengths are in the robot's unit, angles and revolute joint values in
radians, prismatic joint values in the robot's unit:

* ``robots``: ``{"robots": [{"name", "dof", "kind", "unit", "source"}]}``;
  ``robots ROBOT``: ``{"name", "dof", "kind", "unit", "source", "joints": [{"name",
  "type", "lower", "upper"}], "dh": {"a", "alpha", "d", "theta"} or null, "base", "tool"}``.
* ``algorithms``: ``{"algorithms": [{"name", "kind", "source"}]}``.
* ``fk``: ``{"robot", "unit", "joint_names", "q", "pose" (4x4), "position", "rotation",
  "zyx_euler", "eosma_euler", "within_limits"}``.
* ``solve``: ``{"robot", "unit", "joint_names", "target": {"position", "rotation"},
  "status", "success", "n_eval", "time_s", "q", "position_error", "orientation_error"
  (geodesic, rad), "solutions": [{"q", "position_error", "orientation_error"}], "front":
  [[position_error, orientation_error], ...] or null, "plots": [files]}``.

Exit status: 0 done (``solve``: solved), 1 ``solve`` not solved, 2 bad input or an
unusable file or folder (one line on stderr, never a traceback). The printing
itself (text and JSON) is :mod:`moik.cli_output`.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import numpy as np

from moik import cli_output as output
from moik._validate import integer
from moik._version import __version__
from moik.algorithms import available, entry
from moik.exceptions import MoikError, ParameterError, UnknownNameError
from moik.experiments.commands import add_subcommands
from moik.kinematics.orientation import orientation_error
from moik.pareto_cli import add_pareto_arguments, run_pareto
from moik.problems.targets import Target
from moik.robots import Robot, available_robots, get_robot
from moik.robots.urdf import load_urdf
from moik.solver import solve_ik

PLOT_FORMATS = (".png", ".pdf", ".svg")


def _robot(args: argparse.Namespace) -> Robot:
    """The catalog robot or the URDF chain named by ``args.robot`` (``--base``/``--tip``)."""
    spec, base, tip = args.robot, args.base, args.tip
    if spec in available_robots():
        if base is not None or tip is not None:
            raise ParameterError(f"--base/--tip select links of a URDF file; {spec!r} is a "
                                 "catalog robot")
        return get_robot(spec)
    if Path(spec).suffix.lower() in (".urdf", ".xml") or Path(spec).is_file():
        return load_urdf(spec, base_link=base, tip_link=tip)
    err = UnknownNameError("robot", spec, available_robots())
    err.args = (f"{err.args[0]}; or a URDF file (.urdf)",)
    raise err


def _cmd_robots(args: argparse.Namespace) -> int:
    if args.robot is not None:
        output.print_robot(_robot(args), args.json)
    else:
        output.print_robot_list([get_robot(name) for name in available_robots()], args.json)
    return 0


def _cmd_algorithms(args: argparse.Namespace) -> int:
    output.print_algorithms([entry(name) for name in available()], args.json)
    return 0


def _joint_values(robot: Robot, values, degrees: bool, what: str) -> np.ndarray:
    q = np.asarray(values, dtype=float)
    if q.shape != (robot.dof,):
        raise ParameterError(f"robot {robot.name!r} needs {robot.dof} joint values, got "
                             f"{q.size}{'' if what == 'q' else f' ({what})'}")
    return np.where(robot.is_prismatic, q, np.radians(q)) if degrees else q


def _cmd_fk(args: argparse.Namespace) -> int:
    robot = _robot(args)
    q = _joint_values(robot, args.q, args.deg, "q")
    inside = bool(robot.within_limits(q)[0])
    output.print_pose(robot, q, robot.fk(q), inside, args.json)
    if not inside:
        print("warning: q is outside the joint limits", file=sys.stderr)
    return 0


def _plot_files(spec: str | None) -> list[Path]:
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


def _errors(robot: Robot, target: Target, Q: np.ndarray) -> list[tuple[float, float]]:
    """Position error (robot unit) and geodesic orientation error (rad) of each row, by FK."""
    if len(Q) == 0:
        return []
    T = robot.fk(Q)
    pos = np.linalg.norm(T[:, :3, 3] - target.position, axis=1)
    ori = (np.zeros(len(Q)) if target.rotation is None
           else np.atleast_1d(orientation_error(T[:, :3, :3], target.rotation, "geodesic")))
    return [(float(p), float(o)) for p, o in zip(pos, ori, strict=True)]


def _tol(values: list[float] | None):
    if values is None:
        return 1e-9
    if len(values) > 2:
        raise ParameterError(f"--tol takes 1 number (relative) or 2 (position in the robot's "
                             f"unit, orientation in rad), got {len(values)}")
    return values[0] if len(values) == 1 else tuple(values)


def _cmd_solve(args: argparse.Namespace) -> int:
    if args.pareto:
        return run_pareto(args, robot=_robot(args))
    seed = integer("--seed", args.seed, minimum=0)
    plots = _plot_files(args.plot)
    robot = _robot(args)
    if args.euler is None:
        target = Target(args.target)
    else:
        target = Target.from_euler(args.target, args.euler, convention=args.convention,
                                   degrees=args.deg)
    q_current = (None if args.q_current is None
                 else _joint_values(robot, args.q_current, args.deg, "--q-current"))
    res = solve_ik(robot, target, method=args.algorithm, seed=seed, tol=_tol(args.tol),
                   n_solutions=args.n_solutions, starts=args.starts, max_evals=args.max_evals,
                   q_current=q_current)
    Q = res.solutions if len(res.solutions) else res.q[None]
    errors = [(res.position_error, res.orientation_error)] + _errors(robot, target, Q[1:])
    if plots:
        _plot(robot, target, Q, res.status, plots)
    if args.json:
        output.print_solve_json(robot, target, res, errors, plots)
    else:
        output.print_solve(robot, target, res, Q, errors, plots)
    return 0 if res.success else 1


def _plot(robot: Robot, target: Target, Q: np.ndarray, status: str, files: list[Path]) -> None:
    import matplotlib.pyplot as plt  # lazy: keeps the command's start-up fast

    from moik.plotting import plot_robot

    labels = ([f"solution {k}" for k in range(1, len(Q) + 1)] if status == "solved"
              else [f"best ({status})"])
    ax = plot_robot(robot, Q, labels=labels, target=target)
    for path in files:
        ax.figure.savefig(path, dpi=120, bbox_inches="tight")  # the legend sits outside
    plt.close(ax.figure)


def _robot_arguments(p: argparse.ArgumentParser, optional: bool = False) -> None:
    p.add_argument("robot", nargs="?" if optional else None,
                   help="catalog name (see `moik robots`) or URDF file")
    p.add_argument("--base", metavar="LINK", help="URDF: first link of the chain")
    p.add_argument("--tip", metavar="LINK", help="URDF: last link of the chain")
    p.add_argument("--json", action="store_true", help="print JSON (see `moik --help`)")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``moik`` command."""
    parser = argparse.ArgumentParser(prog="moik", description=__doc__.splitlines()[0],
                                     epilog="JSON schemas and exit codes: pydoc moik.cli")
    parser.add_argument("--version", action="version", version=f"moik {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("robots", help="list the robot catalog, or describe one robot")
    _robot_arguments(p, optional=True)
    p.set_defaults(func=_cmd_robots)
    p = sub.add_parser("fk", help="forward kinematics of one joint vector")
    _robot_arguments(p)
    p.add_argument("q", nargs="+", type=float, help="joint values (rad, or deg with --deg)")
    p.add_argument("--deg", action="store_true", help="revolute joint values in degrees")
    p.set_defaults(func=_cmd_fk)
    p = sub.add_parser("algorithms", help="list the registered algorithms (name, kind, source)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(func=_cmd_algorithms)
    p = sub.add_parser("solve", help="solve inverse kinematics for one target")
    _robot_arguments(p)
    p.add_argument("--target", nargs=3, type=float, required=True, metavar=("X", "Y", "Z"),
                   help="target position in the robot's length unit")
    p.add_argument("--euler", nargs=3, type=float, metavar=("A", "B", "C"),
                   help="target orientation as Euler angles (alpha, beta, gamma)")
    p.add_argument("--convention", default="zyx-euler", choices=["zyx-euler", "eosma-euler"],
                   help="Euler convention (default zyx-euler: Rz(a) Ry(b) Rx(c))")
    p.add_argument("--deg", action="store_true",
                   help="Euler angles and revolute --q-current values in degrees")
    p.add_argument("--q-current", nargs="+", type=float, metavar="Q",
                   help="current joint values: the first start; solutions nearest to it first")
    p.add_argument("--tol", nargs="+", type=float, metavar="TOL",
                   help="tolerance: one number t (position t*reach, orientation t rad; default "
                        "1e-9) or two (position in the robot's unit, orientation in rad)")
    p.add_argument("--max-evals", type=int, default=50_000,
                   help="FK evaluation budget (default 50000)")
    p.add_argument("--algorithm", default="eosma",
                   help="global search algorithm, used when the local starts fail (default eosma)")
    p.add_argument("--starts", type=int, default=500,
                   help="random starts of the compiled Levenberg-Marquardt first stage, tried "
                        "in turn until solved (default 500; 0: the global search only)")
    p.add_argument("--seed", type=int, default=0, help="random seed, an integer >= 0 (default 0)")
    p.add_argument("--n-solutions", type=int, default=1, help="distinct solutions wanted")
    p.add_argument("--plot", metavar="FILE",
                   help="save a 3-D drawing: FILE.png, .pdf or .svg (no extension: .png and .pdf)")
    add_pareto_arguments(p)
    p.set_defaults(func=_cmd_solve)
    add_subcommands(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``moik`` console script and of ``python -m moik``."""
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except MoikError as exc:
        print(f"moik: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. `moik experiment list | head`: stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except OSError as exc:  # a folder or file that cannot be written (--out, --plot)
        what = f"cannot use {exc.filename}: " if exc.filename else ""
        print(f"moik: error: {what}{exc.strerror or exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
