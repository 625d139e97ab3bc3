"""The ``moik`` command line.

Subcommands:
    moik robots                      list the robot catalog
    moik fk ROBOT q1 ... qn [--deg]  print the end-effector pose
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

from moik.exceptions import MoikError
from moik.kinematics.orientation import eosma_euler, zyx_euler
from moik.robots import available_robots, get_robot


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
    return parser


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``moik`` console script."""
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except MoikError as exc:
        print(f"moik: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
