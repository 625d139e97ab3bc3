"""What several subcommands read from the command line: the robot and joint values."""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from moik.exceptions import ParameterError, UnknownNameError
from moik.robots import Robot, available_robots, get_robot
from moik.robots.urdf import load_urdf


def robot(args: argparse.Namespace) -> Robot:
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


def joint_values(robot: Robot, values, degrees: bool, what: str) -> np.ndarray:
    """``values`` as the robot's joint vector in radians (degrees converted with ``--deg``)."""
    q = np.asarray(values, dtype=float)
    if q.shape != (robot.dof,):
        raise ParameterError(f"robot {robot.name!r} needs {robot.dof} joint values, got "
                             f"{q.size}{'' if what == 'q' else f' ({what})'}")
    return np.where(robot.is_prismatic, q, np.radians(q)) if degrees else q
