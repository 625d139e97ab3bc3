"""``moik fk ROBOT q1 ... qn [--deg]``: the end-effector pose of one joint vector."""

from __future__ import annotations

import argparse
import sys

from moik.cli import solutions
from moik.cli.common import joint_values, library_call, robot


def cmd_fk(args: argparse.Namespace) -> int:
    """Print the pose (full precision); warn when ``q`` is outside the joint limits
    (naming the joints)."""
    arm = robot(args)
    q = joint_values(arm, args.q, args.deg, "q")
    outside = arm.outside_limits(q)
    with library_call():
        T = arm.fk(q)
    solutions.print_pose(arm, q, T, not outside, args.json)
    if outside:
        print(f"moik: warning: q is outside the joint limits: {outside}", file=sys.stderr)
    return 0
