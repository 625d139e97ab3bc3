"""``moik robots [ROBOT]``: the robot catalog, or one robot's joints, DH rows, unit and source."""

from __future__ import annotations

import argparse

from moik.cli import output
from moik.cli.common import robot
from moik.robots import available_robots, get_robot


def cmd_robots(args: argparse.Namespace) -> int:
    """The catalog, or one robot (a catalog name or a URDF file)."""
    if args.robot is not None:
        output.print_robot(robot(args), args.json)
    else:
        output.print_robot_list([get_robot(name) for name in available_robots()], args.json)
    return 0

