"""The ``moik`` command line.

Subcommands:
    moik robots                      list the robot catalog
    moik algorithms                  list the registered algorithms (name, kind, source)
    moik fk ROBOT q1 ... qn [--deg]  print the end-effector pose
    moik solve ROBOT --target x y z [--euler a b c [--deg]] ...   solve IK
    moik experiment list             list the papers' experiments
    moik experiment run NAME [--quick] [--workers N] [--resume] [--out DIR] [--dask-scheduler A]
    moik experiment run --config FILE [...]   run your own config file
    moik report DIR                  Markdown report of a results folder
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np

from moik.algorithms import available, entry
from moik.exceptions import MoikError
from moik.experiments.commands import add_subcommands
from moik.kinematics.orientation import eosma_euler, zyx_euler
from moik.problems.targets import Target
from moik.robots import available_robots, get_robot
from moik.solver import solve_ik


def _cmd_robots(args: argparse.Namespace) -> int:
    print(f"{'name':<18}{'dof':>4}  {'DH':<9}{'unit':<5} source")
    for name in available_robots():
        r = get_robot(name)
        print(f"{name:<18}{r.dof:>4}  {r.convention:<9}{r.unit:<5} {r.source}")
    return 0


def _format_pose(robot, T: np.ndarray) -> str:
    R = T[:3, :3]
    lines = [f"robot {robot.name} ({robot.dof} DOF, {robot.convention} DH, {robot.unit})",
             "pose T:"]
    lines += ["  " + "  ".join(f"{v:12.6f}" for v in row) for row in T]
    pos = ", ".join(f"{v:.6f}" for v in T[:3, 3])
    lines.append(f"position ({robot.unit}): ({pos})")
    zyx = ", ".join(f"{v:.4f}" for v in np.degrees(zyx_euler(R)))
    eos = ", ".join(f"{v:.4f}" for v in np.degrees(eosma_euler(R)))
    lines.append(f"ZYX Euler (alpha, beta, gamma) deg: ({zyx})")
    lines.append(f"EOSMA Eq. 26 Euler (alpha, beta, gamma) deg: ({eos})")
    return "\n".join(lines)


def _cmd_fk(args: argparse.Namespace) -> int:
    robot = get_robot(args.robot)
    q = np.asarray(args.q, dtype=float)
    if q.shape != (robot.dof,):
        raise MoikError(f"robot {robot.name!r} needs {robot.dof} joint values, got {q.size}")
    if args.deg:
        q = np.where(robot.is_prismatic, q, np.radians(q))
    outside = ~robot.within_limits(q)[0]
    print(_format_pose(robot, robot.fk(q)))
    if outside:
        print("warning: q is outside the joint limits", file=sys.stderr)
    return 0


def _cmd_algorithms(args: argparse.Namespace) -> int:
    print(f"{'name':<10}{'kind':<18}source")
    for name in available():
        e = entry(name)
        print(f"{name:<10}{e.kind:<18}{e.source}")
    return 0


def _cmd_solve(args: argparse.Namespace) -> int:
    robot = get_robot(args.robot)
    if args.euler is None:
        target = Target(args.target)
    else:
        target = Target.from_euler(args.target, args.euler, convention=args.convention,
                                   degrees=args.deg)
    res = solve_ik(robot, target, method=args.algorithm, seed=args.seed,
                   n_solutions=args.n_solutions, starts=args.starts)
    kind = "pose" if target.has_orientation else "position"
    print(f"robot {robot.name}: {kind} target {np.round(target.position, 6).tolist()} "
          f"{robot.unit}")
    print(f"status: {res.status}  ({res.n_eval} FK evaluations, {res.time * 1e3:.1f} ms)")
    q_deg = np.where(robot.is_prismatic, res.q, np.degrees(res.q))
    print("q: " + " ".join(f"{v:.6f}" for v in q_deg) + "  (deg; prismatic in "
          f"{robot.unit})")
    print(f"position error: {res.position_error:.3e} {robot.unit}")
    if target.has_orientation:
        print(f"orientation error: {res.orientation_error:.3e} rad (geodesic)")
    for k, q in enumerate(res.solutions[1:], start=2):
        print(f"solution {k}: " + " ".join(f"{v:.6f}" for v in np.degrees(q)))
    if res.front is not None:
        print(f"Pareto front of (position, orientation) errors: {len(res.front)} points; "
              "q above is the compromise closest to the utopia point")
    if args.plot:
        from moik.plotting import plot_robot

        stem = args.plot.rsplit(".", 1)[0]
        Q = res.solutions if len(res.solutions) else res.q[None]
        labels = ([f"solution {k}" for k in range(1, len(Q) + 1)] if len(res.solutions)
                  else [f"best ({res.status})"])
        plot_robot(robot, Q, labels=labels, target=target.position, save=stem)
        print(f"plot written to {stem}.png and {stem}.pdf")
    return 0 if res.success else 1


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``moik`` command."""
    parser = argparse.ArgumentParser(prog="moik", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("robots", help="list the robot catalog")
    p.set_defaults(func=_cmd_robots)
    p = sub.add_parser("fk", help="forward kinematics of one joint vector")
    p.add_argument("robot", help="catalog name (see `moik robots`)")
    p.add_argument("q", nargs="+", type=float, help="joint values (rad, or deg with --deg)")
    p.add_argument("--deg", action="store_true", help="revolute joint values in degrees")
    p.set_defaults(func=_cmd_fk)
    p = sub.add_parser("algorithms", help="list the registered algorithms (name, kind, source)")
    p.set_defaults(func=_cmd_algorithms)
    p = sub.add_parser("solve", help="solve inverse kinematics for one target")
    p.add_argument("robot", help="catalog name (see `moik robots`)")
    p.add_argument("--target", nargs=3, type=float, required=True, metavar=("X", "Y", "Z"),
                   help="target position in the robot's length unit")
    p.add_argument("--euler", nargs=3, type=float, metavar=("A", "B", "C"),
                   help="target orientation as Euler angles (alpha, beta, gamma)")
    p.add_argument("--convention", default="zyx-euler", choices=["zyx-euler", "eosma-euler"],
                   help="Euler convention (default zyx-euler: Rz(a) Ry(b) Rx(c))")
    p.add_argument("--deg", action="store_true", help="Euler angles in degrees")
    p.add_argument("--algorithm", default="eosma",
                   help="global search algorithm, used when the local starts fail (default eosma)")
    p.add_argument("--starts", type=int, default=16,
                   help="random starts of the batched Levenberg-Marquardt first attempt "
                        "(default 16; 0: the global search only)")
    p.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    p.add_argument("--n-solutions", type=int, default=1, help="distinct solutions wanted")
    p.add_argument("--plot", metavar="FILE", help="save a 3-D drawing (FILE.png and .pdf)")
    p.set_defaults(func=_cmd_solve)
    add_subcommands(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``moik`` console script."""
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except MoikError as exc:
        print(f"moik: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. `moik experiment list | head`: stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
