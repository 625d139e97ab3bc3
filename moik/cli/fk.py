"""``moik fk ROBOT q1 ... qn [--deg]``: the end-effector pose of one joint vector."""

from __future__ import annotations

import argparse
import sys

from moik.cli import solutions
from moik.cli.common import joint_values, robot


def cmd_fk(args: argparse.Namespace) -> int:
    """Print the pose (full precision); warn when ``q`` is outside the joint limits."""
    arm = robot(args)
    q = joint_values(arm, args.q, args.deg, "q")
    inside = bool(arm.within_limits(q)[0])
    solutions.print_pose(arm, q, arm.fk(q), inside, args.json)
    if not inside:
        print("warning: q is outside the joint limits", file=sys.stderr)
    return 0
