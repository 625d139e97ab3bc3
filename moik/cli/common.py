"""What several subcommands read from the command line: the robot and joint values."""

from __future__ import annotations

import argparse
import re
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from moik.exceptions import (
    DegreesWarning,
    MoikError,
    ParameterError,
    UnknownNameError,
    URDFError,
)
from moik.robots import Robot, available_robots, get_robot
from moik.robots.checks import warn_if_joint_degrees
from moik.robots.urdf import load_urdf


def robot(args: argparse.Namespace) -> Robot:
    """The catalog robot or the URDF chain named by ``args.robot`` (``--base``/``--tip``)."""
    spec, base, tip = args.robot, args.base, args.tip
    packages = getattr(args, "package_dirs", None)
    srdf = getattr(args, "srdf", None)
    if spec in available_robots():
        if base is not None or tip is not None or packages or srdf is not None:
            raise ParameterError(f"--base/--tip select links of a URDF file (--package-dir its "
                                 f"meshes' packages, --srdf its SRDF); {spec!r} is a catalog "
                                 "robot")
        return get_robot(spec)
    if Path(spec).suffix.lower() in (".urdf", ".xml") or Path(spec).is_file():
        try:
            return load_urdf(spec, base_link=base, tip_link=tip, package_dirs=packages,
                             srdf=srdf)
        except URDFError as exc:  # the library's keywords, in the command's words
            text = str(exc).replace("pass tip_link=", "give --tip").replace(
                "pass base_link=", "give --base")
            raise URDFError(text) from None
    err = UnknownNameError("robot", spec, available_robots())
    err.args = (f"{err.args[0]}; or a URDF file (.urdf)",)
    raise err


def joint_values(robot: Robot, values, degrees: bool, what: str) -> np.ndarray:
    """``values`` as the robot's joint vector in radians (degrees converted with ``--deg``).

    Warns (:class:`~moik.exceptions.DegreesWarning`, naming ``what``) when values given
    in radians look like degrees; the library's own warning about the same values is
    then not repeated (:func:`library_call`).
    """
    q = np.asarray(values, dtype=float)
    if q.shape != (robot.dof,):
        raise ParameterError(f"robot {robot.name!r} needs {robot.dof} joint values, got "
                             f"{q.size}{'' if what == 'q' else f' ({what})'}")
    if degrees:
        return np.where(robot.is_prismatic, q, np.radians(q))
    warn_if_joint_degrees(robot.name, robot.joint_names, robot.lower, robot.upper,
                          robot.is_prismatic, q, "the joint values" if what == "q" else what,
                          stacklevel=2, hint="add --deg to give degrees")
    return q


def tolerance(values: list[float]) -> float | tuple[float, ...]:
    """``--tol``'s one number (relative) or two (position, orientation) as ``tol=``."""
    if len(values) > 2:
        raise ParameterError(f"--tol takes 1 number (relative) or 2 (position in the robot's "
                             f"unit, orientation in rad), got {len(values)}")
    return values[0] if len(values) == 1 else tuple(values)


SOLVE_OPTIONS = {"q_current": "--q-current", "n_solutions": "--n-solutions",
                 "max_evals": "--max-evals", "starts": "--starts", "tol": "--tol",
                 "seed": "--seed", "method": "--algorithm"}
"""``solve_ik``'s keywords and the ``solve`` options that give them."""

PARETO_OPTIONS = {"q_current": "--q-current", "n_solutions": "--pareto-size", "tol": "--tol",
                  "seed": "--seed", "method": "--pareto-method"}
"""``solve_ik_pareto``'s keywords and the ``solve --pareto`` options that give them."""


@contextmanager
def library_call(options: dict[str, str] | None = None) -> Iterator[None]:
    """Run a library call whose joint values :func:`joint_values` has already checked.

    A :class:`~moik.exceptions.MoikError` raised inside names the library's keywords
    (``n_solutions must be ...``); it is raised again, of the same class, with each
    keyword of ``options`` replaced by its option (``--n-solutions must be ...``), and an
    unknown algorithm name prefixed with the option of ``method`` (``--algorithm: unknown
    algorithm 'x'; ...``).
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DegreesWarning)
        try:
            yield
        except MoikError as exc:
            if not options or not exc.args or not isinstance(exc.args[0], str):
                raise
            if exc.args[0].startswith("unknown algorithm ") and "method" in options:
                exc.args = (f"{options['method']}: {exc.args[0]}", *exc.args[1:])
                raise  # the one algorithm name a command passes (--algorithm, --pareto-method)
            # a keyword with an underscore anywhere; a plain word only as the subject
            names = "|".join(map(re.escape, options))
            text = re.sub(rf"^({names}) must ", lambda m: f"{options[m.group(1)]} must ",
                          exc.args[0])
            keys = "|".join(re.escape(k) for k in options if "_" in k)
            if keys:
                text = re.sub(rf"(?<![\w-])({keys})(?![\w-])", lambda m: options[m.group(1)],
                              text)
            if text == exc.args[0]:
                raise
            exc.args = (text, *exc.args[1:])
            raise
