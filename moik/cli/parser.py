"""The ``moik`` command's argument parser: every subcommand and option, nothing heavy imported.

Each subcommand names its handler (``handler="solve:run"``, see :mod:`moik.cli.main`).
Options are validated where they are used (by :mod:`moik._validate`, naming the
option: ``--seed must be an integer >= 0``), so that this module needs no numpy.
"""

from __future__ import annotations

import argparse
from typing import NoReturn

from moik._version import __version__

CRITERIA_NAMES = ("joint_motion", "manipulability", "limit_margin", "orientation")
"""The built-in ``--pareto`` criteria, for the help text (:data:`moik.kinematics.criteria.CRITERIA`;
a test keeps the two equal)."""

EXPERIMENTS_ENV = "MOIK_EXPERIMENTS_PATH"
"""The folders of a user's own configs (:data:`moik.experiments.registry.ENV_VAR`)."""


def positive_int(text: str) -> int:
    """An argparse type: ``text`` as an integer >= 1 (``"2.0"``, ``"0"`` and ``"x"`` refused)."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}")
    return value


def nonempty(text: str) -> str:
    """An argparse type: a file, folder or list given on the command line is not empty
    (``--out ""`` must not silently mean the default)."""
    if not text:
        raise argparse.ArgumentTypeError("expected a non-empty value, got ''")
    return text


LIBRARY_DEFAULTS = {"max_evals": ("solve_ik", "max_evals"), "method": ("solve_ik", "method"),
                    "starts": ("solve_ik", "starts"), "seed": ("solve_ik", "seed"),
                    "n_solutions": ("solve_ik", "n_solutions"),
                    "clearance": ("solve_ik", "clearance"), "tol": ("solve_ik", "tol"),
                    "pareto_size": ("solve_ik_pareto", "n_solutions"),
                    "pareto_method": ("solve_ik_pareto", "method")}
"""``solve`` options left None when not given (the library's default applies), by
argparse ``dest``: the function and keyword they give. The library's signature is
the one place a default is written; the help text reads it from there."""


def library_default(dest: str):
    """The default of the library keyword behind the ``solve`` option ``dest``.

    Imported when help is shown, not when the parser is built (``moik --help`` and
    ``moik robots`` need no solver).
    """
    import inspect

    from moik import solver

    function, keyword = LIBRARY_DEFAULTS[dest]
    return inspect.signature(getattr(solver, function)).parameters[keyword].default


def given(args: argparse.Namespace, *dests: str) -> dict:
    """``{library keyword: value}`` of the options ``dests`` the command line gave (a
    missing one is left to the library's default)."""
    return {LIBRARY_DEFAULTS[d][1]: getattr(args, d) for d in dests
            if getattr(args, d, None) is not None}


class LibraryDefaultsFormatter(argparse.HelpFormatter):
    """Help text whose ``{default}`` is :func:`library_default` of the option."""

    def _get_help_string(self, action: argparse.Action) -> str | None:
        text = action.help
        if text and "{default}" in text:
            text = text.replace("{default}", str(library_default(action.dest)))
        return text


def _robot_arguments(p: argparse.ArgumentParser, optional: bool = False) -> None:
    p.add_argument("robot", nargs="?" if optional else None, type=nonempty,
                   help="catalog name (see `moik robots`) or URDF file")
    p.add_argument("--base", metavar="LINK", type=nonempty, help="URDF: first link of the chain")
    p.add_argument("--tip", metavar="LINK", type=nonempty, help="URDF: last link of the chain")
    _urdf_files(p)
    p.add_argument("--json", action="store_true",
                   help="print JSON (see `python -m pydoc moik.cli`)")


def _urdf_files(p: argparse.ArgumentParser) -> None:
    """A URDF arm's mesh packages and SRDF."""
    p.add_argument("--package-dir", action="append", metavar="DIR", dest="package_dirs",
                   type=nonempty,
                   help="URDF: a folder holding the packages its package:// meshes name "
                        "(repeatable; ROS_PACKAGE_PATH is searched too)")
    p.add_argument("--srdf", metavar="FILE", type=nonempty,
                   help="URDF: the robot's MoveIt SRDF; the link pairs it disables are not "
                        "checked for self-collision")


def _check_arguments(p: argparse.ArgumentParser) -> None:
    """The collision check and the tolerance of ``solve`` and ``batch``."""
    p.add_argument("--scene", metavar="FILE", type=nonempty,
                   help="JSON scene of obstacles: solve for solutions free of them and report "
                        "each one's distance; status collides (exit 1) if all exact ones collide "
                        "(with --self-collision: the arm's self pairs too)")
    p.add_argument("--self-collision", action="store_true",
                   help="solve for solutions free of self-collision (a URDF arm's own "
                        "<collision> geometry, its meshes measured on their convex pieces, "
                        "panda, ur5 and iiwa14 included; the shipped capsule models of the "
                        "other catalog arms that have one)")
    p.add_argument("--clearance", type=float, metavar="D",
                   help="with --scene or --self-collision: the smallest accepted distance "
                        "(robot unit, >= 0; default {default})")
    p.add_argument("--allow-missing-geometry", action="store_true",
                   help="URDF: check the links that have <collision> geometry and leave those "
                        "without it unchecked (named in the output); without it such a link is "
                        "an error")
    p.add_argument("--tol", nargs="+", type=float, metavar="TOL",
                   help="tolerance: one number t (position t*reach, orientation t rad; default "
                        "{default}) or two (position in the robot's unit, orientation in rad)")


def _solve_arguments(p: argparse.ArgumentParser) -> None:
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
                   help="current joint values (rad, deg with --deg): the first start; "
                        "solutions nearest to it first; needed by --pareto joint_motion")
    _check_arguments(p)
    p.add_argument("--max-evals", type=int, help="FK evaluation budget (default {default})")
    p.add_argument("--algorithm", dest="method",
                   help="global search algorithm, used when the local starts fail (default "
                        "{default})")
    p.add_argument("--starts", type=int,
                   help="random starts of the compiled Levenberg-Marquardt first stage, tried "
                        "in turn until solved (default {default}; 0: the global search only)")
    p.add_argument("--seed", type=int, help="random seed, an integer >= 0 (default {default})")
    p.add_argument("--n-solutions", type=int,
                   help="distinct solutions wanted (default {default})")
    p.add_argument("--plot", metavar="FILE", type=nonempty,
                   help="save a 3-D drawing: FILE.png, .pdf or .svg (no extension: .png and .pdf)")
    p.add_argument("--html", metavar="FILE", type=nonempty,
                   help="write the interactive explorer, one self-contained HTML file (needs "
                        "the explorer extra): the Pareto set with --pareto, else the error front "
                        "of an unreachable pose; a click on a point shows its posture")
    p.add_argument("--pareto", metavar="CRITERIA", type=nonempty,
                   help="the Pareto set of exact solutions over these comma-separated "
                        f"criteria ({', '.join(CRITERIA_NAMES)}; clearance with --scene or "
                        "--self-collision: the smallest distance, maximised)")
    p.add_argument("--preferred-euler", nargs=3, type=float, metavar=("A", "B", "C"),
                   help="with --pareto: preferred orientation of a position target (the "
                        "'orientation' criterion), Euler angles as --euler")
    p.add_argument("--pareto-size", type=int,
                   help="most members returned with --pareto (default {default})")
    p.add_argument("--pareto-method",
                   help="multi-objective algorithm of the --pareto search (default {default})")


def _batch_arguments(sub) -> None:
    p = sub.add_parser("batch", help="solve inverse kinematics for a file of targets",
                       formatter_class=LibraryDefaultsFormatter,
                       description="Solve every target of a .npy file (poses (n, 4, 4) or "
                                   "positions (n, 3)) or a CSV file (x y z [roll pitch yaw]: "
                                   "R = Rz(yaw) Ry(pitch) Rx(roll)) on every core; write the "
                                   "joint vectors, statuses, errors (and distances) to --out. "
                                   "Exit status 0 when every target is solved, 1 otherwise, "
                                   "2 for bad input (a file, an option).")
    p.add_argument("robot", help="catalog name (see `moik robots`) or URDF file")
    p.add_argument("--base", metavar="LINK", help="URDF: first link of the chain")
    p.add_argument("--tip", metavar="LINK", help="URDF: last link of the chain")
    _urdf_files(p)
    p.add_argument("targets", metavar="TARGETS", help="the targets: FILE.npy or FILE.csv")
    p.add_argument("--out", metavar="RESULT", required=True,
                   help="results file: RESULT.npz (arrays) or RESULT.csv (one line per target)")
    p.add_argument("--workers", type=positive_int, default=None,
                   help="CPUs to use (default: every core; the answers are the same for any "
                        "number)")
    p.add_argument("--deg", action="store_true", help="CSV roll, pitch, yaw in degrees")
    _check_arguments(p)
    p.add_argument("--seed", type=int, help="random seed, an integer >= 0 (default {default})")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(handler="batch:cmd_batch")


def _experiment_arguments(sub) -> None:
    p = sub.add_parser("experiment", help="list or run the papers' experiments",
                       description="List or run the experiments that regenerate the papers' "
                                   "tables and figures.")
    esub = p.add_subparsers(dest="experiment_command", required=True)
    q = esub.add_parser("list", help="list the experiments (trials full / quick size)")
    q.set_defaults(handler="experiment:cmd_list")
    q = esub.add_parser("run", help="run an experiment; results are stored trial by trial",
                        description="Run an experiment. Each finished trial is stored at once; "
                                    "Ctrl-C loses only the trials in flight; --resume continues.")
    which = q.add_mutually_exclusive_group(required=True)
    which.add_argument("name", nargs="?",
                       help="experiment name (see `moik experiment list`) or config file")
    which.add_argument("--config", metavar="FILE", type=nonempty,
                       help="run the experiment defined by this TOML config file (your own; "
                            f"the folders in {EXPERIMENTS_ENV} are listed by name too)")
    q.add_argument("--quick", action="store_true", help="the seconds-long smoke-test size")
    q.add_argument("--workers", type=positive_int, default=None,
                   help="worker processes (default: the number of cores; 1 = serial)")
    q.add_argument("--resume", action="store_true",
                   help="continue the results in --out, skipping finished trials")
    q.add_argument("--out", metavar="DIR", type=nonempty,
                   help="results folder (default results/NAME or results/NAME-quick)")
    q.add_argument("--dask-scheduler", metavar="ADDRESS", type=nonempty,
                   help="run on a Dask distributed scheduler (needs the dask extra)")
    q.add_argument("--limit", type=positive_int, default=None,
                   help="run at most this many pending trials, then stop")
    q.add_argument("--by-run", action="store_true",
                   help="run trials run by run (run 0 of every algorithm and target first), so "
                        "a partial run compares every algorithm")
    q.add_argument("--no-progress", action="store_true", help="no progress bar")
    q.set_defaults(handler="experiment:cmd_run")
    p = sub.add_parser("report", help="write a Markdown report of results folders, or the docs",
                       description="Write DIR/report.md: tables beside the paper's numbers, "
                                   "and figures. DIR is a results folder or a folder of them. "
                                   "With --docs DOCS: write DOCS/results/NAME.md per experiment "
                                   "and regenerate its blocks in DOCS/reproducing.md.")
    p.add_argument("folder", metavar="DIR", type=nonempty, nargs="+",
                   help="results folder (or a folder of them)")
    p.add_argument("--no-figures", action="store_true", help="tables only")
    p.add_argument("--output", metavar="FILE", type=nonempty,
                   help="report file (default DIR/report.md)")
    p.add_argument("--docs", metavar="DOCS", type=nonempty,
                   help="docs folder to regenerate from the results (e.g. docs/); refused "
                        "while moik's code has uncommitted changes (the pages' stamps name "
                        "the commit that wrote them)")
    p.add_argument("--force", action="store_true",
                   help="with --docs: write them from a tree with uncommitted changes (the "
                        "stamps then say so)")
    p.add_argument("--html", metavar="FILE", nargs="?", const="",
                   help="write the interactive report instead (fronts linked to postures, "
                        "convergence, the tables; needs the explorer extra): FILE, default "
                        "DIR/report.html")
    p.set_defaults(handler="report:cmd_report")


class OneLineParser(argparse.ArgumentParser):
    """An argument parser whose errors are one line on stderr and exit status 2, as every
    other error of the command (the usage is one ``--help`` away)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"moik: error: {self.prog}: {message} (see `{self.prog} --help`)\n")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``moik`` command."""
    parser = OneLineParser(prog="moik",
                           description="The ``moik`` command line (also ``python -m moik``).",
                           epilog="JSON schemas and exit codes: python -m pydoc moik.cli")
    parser.add_argument("--version", action="version", version=f"moik {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("robots", help="list the robot catalog, or describe one robot")
    _robot_arguments(p, optional=True)
    p.set_defaults(handler="catalog:cmd_robots")
    p = sub.add_parser("fk", help="forward kinematics of one joint vector")
    _robot_arguments(p)
    p.add_argument("q", nargs="+", type=float, help="joint values (rad, or deg with --deg)")
    p.add_argument("--deg", action="store_true", help="revolute joint values in degrees")
    p.set_defaults(handler="fk:cmd_fk")
    p = sub.add_parser("problems", help="list the IK benchmark problems (moik.problems.available)"
                       " and their reference fronts")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(handler="problems:cmd_problems")
    p = sub.add_parser("algorithms", help="list the registered algorithms (name, kind, source)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(handler="algorithms:cmd_algorithms")
    p = sub.add_parser("solve", help="solve inverse kinematics for one target",
                       formatter_class=LibraryDefaultsFormatter)
    _solve_arguments(p)
    p.set_defaults(handler="solve:cmd_solve")
    _batch_arguments(sub)
    p = sub.add_parser("compile", help="compile every kernel family once, in parallel "
                                       "processes (the first solves then only load them)")
    p.add_argument("--processes", type=int, default=None,
                   help="processes at once (default: the number of cores)")
    p.set_defaults(handler="kernels:cmd_compile")
    _experiment_arguments(sub)
    return parser
