"""Named multi-objective IK benchmark problems, with reference fronts.

``available()`` lists them, ``get_problem(name)`` builds one (as pymoo's ``get_problem``
does for ZDT/DTLZ). The bi-objective ones (:class:`moik.problems.BiObjectiveIK`) have
``pareto_front()`` (:mod:`moik.fronts`), shipped as package data for these poses and
computed and cached for any other, so pymoo's IGD, IGD+, GD and HV apply.

* ``eosma-p1``, ``eosma-p2``: EOSMA paper (Yin et al. 2022) Table 8's poses on
  ``eosma7-m`` (metres), Eq. 26/30 Euler error: P1 = (-0.25, 1.00, 0.50) m and
  P2 = (0.50, -0.25, 0.75) m, both with Euler angles (0, 0, 0).
* ``mpso-eq16``: MO-m-PSO paper (Rokbani et al. 2022) Section 4.2 / Eq. 16 on
  ``rokbani5`` (cm): position FK((30, 60, 45, 60, 60) deg), ZYX angles
  (0, -30, -23.8) deg, Eq. 14 error.
* ``<arm>-reachable``, ``<arm>-unreachable`` for the six paper arms of :data:`ARMS`
  (geodesic error): the FK pose of ``q = lower + 0.3 (upper - lower)``, and a pose
  out of reach (position along that pose's direction at 1.1 times the arm's reach bound,
  rotation of ``q = lower + 0.7 (upper - lower)``).
* ``eosma-p1-motion``: ``eosma-p1`` with the joint motion ``||q||`` from ``q = 0`` as a
  third objective (:class:`~moik.problems.motion_ik.PoseMotionIK`; its reference front is
  three-objective, :func:`moik.fronts.motion.motion_front`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from pymoo.core.problem import Problem

from moik.exceptions import UnknownNameError
from moik.kinematics.orientation import rotation_from_eosma_euler, rotation_from_zyx
from moik.problems.ik import BiObjectiveIK
from moik.problems.motion_ik import PoseMotionIK
from moik.robots.catalog import get_robot

ARMS = ("eosma7-m", "rokbani5", "irb2600", "puma560", "sawyer7", "youbot5")
EOSMA_P1 = (-0.25, 1.00, 0.50)
EOSMA_P2 = (0.50, -0.25, 0.75)


def _eosma(position) -> Callable[[], Problem]:
    def build() -> Problem:
        return BiObjectiveIK(get_robot("eosma7-m"),
                             (np.array(position), rotation_from_eosma_euler(0.0, 0.0, 0.0)),
                             orientation="eosma-euler")
    return build


def _mpso_eq16() -> Problem:
    robot = get_robot("rokbani5")
    position = robot.fk(np.deg2rad([30.0, 60.0, 45.0, 60.0, 60.0]))[:3, 3]
    rotation = rotation_from_zyx(0.0, np.deg2rad(-30.0), np.deg2rad(-23.8))
    return BiObjectiveIK(robot, (position, rotation), orientation="zyx-euler")


def _arm(name: str, reachable: bool) -> Callable[[], Problem]:
    def build() -> Problem:
        robot = get_robot(name)
        T = robot.fk(robot.lower + 0.3 * (robot.upper - robot.lower))
        if reachable:
            return BiObjectiveIK(robot, T)
        p = T[:3, 3]
        position = p / np.linalg.norm(p) * 1.1 * robot.reach
        R = robot.fk(robot.lower + 0.7 * (robot.upper - robot.lower))[:3, :3]
        return BiObjectiveIK(robot, (position, R))
    return build


def _p1_motion() -> Problem:
    robot = get_robot("eosma7-m")
    return PoseMotionIK(robot, (np.array(EOSMA_P1), rotation_from_eosma_euler(0.0, 0.0, 0.0)),
                        q_start=np.zeros(robot.dof), orientation="eosma-euler")


_REGISTRY: dict[str, Callable[[], Problem]] = {
    "eosma-p1": _eosma(EOSMA_P1),
    "eosma-p2": _eosma(EOSMA_P2),
    "mpso-eq16": _mpso_eq16,
    **{f"{arm}-{kind}": _arm(arm, kind == "reachable") for arm in ARMS
       for kind in ("reachable", "unreachable")},
    "eosma-p1-motion": _p1_motion,
}


def available() -> list[str]:
    """The names :func:`get_problem` accepts."""
    return list(_REGISTRY)


def get_problem(name: str) -> Problem:
    """The registered IK benchmark problem ``name`` (a new instance).

    Raises:
        UnknownNameError: listing the valid names.
    """
    try:
        factory = _REGISTRY[name]
    except (KeyError, TypeError):
        raise UnknownNameError("IK problem", name, _REGISTRY) from None
    return factory()
