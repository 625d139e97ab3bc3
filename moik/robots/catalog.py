"""Every robot arm used by the four papers, by name.

Each entry cites the paper and table its DH rows come from, and the public
source used where the paper's text is ambiguous (lost minus signs).

Papers (``shared/papers``):

* EOSMA: Yin et al., "Multi-objective inverse kinematics optimization of 7-DOF
  manipulators using EOSMA/MOEOSMA", Sci. Rep. 2022 (Table 1).
* MO-m-PSO: Rokbani et al., "Multi-objective modified PSO for inverse kinematics
  of a 5-DOF robotic arm", Appl. Sci. 12, 7091 (2022) (Table 1).
* I-BES: improved bald eagle search for manipulator IK, 2024 (Tables 2-7).
* MChOA: multi-strategy chimp optimisation for the ABB IRB-2600 (Table 1).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import numpy as np

from moik.exceptions import ParameterError, UnknownNameError
from moik.robots.chain import Robot
from moik.robots.urdf import load_urdf

DATA = Path(__file__).with_name("data")

PI = np.pi
DEG = PI / 180.0


def _ibes_limits(types: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray]:
    """I-BES Section 5.1.1: revolute [-pi, pi], prismatic [0, 1.0] m."""
    prismatic = np.array([t == "prismatic" for t in types])
    return np.where(prismatic, 0.0, -PI), np.where(prismatic, 1.0, PI)


def _ibes(name: str, rows, source: str, types: tuple[str, ...] | None = None) -> Robot:
    """Build an I-BES arm from rows ``(theta_offset, d, a, alpha)`` in metres."""
    rows = np.asarray(rows, dtype=float)
    types = types or ("revolute",) * len(rows)
    lower, upper = _ibes_limits(types)
    return Robot(
        name=name,
        theta=rows[:, 0],
        d=rows[:, 1],
        a=rows[:, 2],
        alpha=rows[:, 3],
        lower=lower,
        upper=upper,
        joint_types=types,
        unit="m",
        source=source,
    )


def eosma7() -> Robot:
    """7-DOF arm of the EOSMA paper, Table 1 (standard DH, cm).

    The table prints lengths as l1 = 0.5 ... "(m)", but the paper's own FK check
    (Simulation section: (45, 0, 45, 0, 45, 0, 0) deg -> (-24.748737,
    100.961941, 50.0)) and every target are in cm, so lengths are 50, 20, ... cm.
    """
    return Robot(
        name="eosma7",
        a=[0.0, 20.0, 25.0, 30.0, 20.0, 20.0, 10.0],
        alpha=[-PI / 2, PI / 2, -PI / 2, PI / 2, -PI / 2, 0.0, 0.0],
        d=[50.0, 0.0, 0.0, 0.0, 0.0, 0.0, 5.0],
        theta=np.zeros(7),
        lower=np.array([-PI, -PI / 2, -PI / 2, -PI / 2, -PI / 2, -PI / 2, -PI / 6]),
        upper=np.array([PI, PI / 6, 2 * PI / 3, PI / 2, PI / 2, PI / 2, PI / 2]),
        unit="cm",
        source="EOSMA paper (Yin et al. 2022, Sci. Rep.), Table 1; lengths in cm",
    )


def eosma7_m() -> Robot:
    """The EOSMA 7-DOF arm in metres, as Table 1 prints it (l1 = 0.5 m ...).

    For reproducing the paper's Tables 5, 7, 8 and 9: their errors are in metres
    (Table 7's worst 5.55e-17 is one rounding step of a quantity of size 1; in
    cm one rounding step of a 50 cm coordinate is already ~7e-15), and Eq. 28
    adds that length error to an angle error in radians, so the unit decides
    the balance of the two terms. Table 8's HV reference points fit position
    errors in metres (P1: HV ~5.0 in metres, ~2.2 in cm; paper 5.08), and
    Table 9's pose is solved exactly in metres, not in cm. The paper prints
    positions in cm (e.g. (-24.748737, 100.961941, 50) for the start pose), which
    is :func:`eosma7`.
    """
    robot = eosma7()
    return Robot(name="eosma7-m", a=np.asarray(robot.a) / 100.0, alpha=robot.alpha,
                 d=np.asarray(robot.d) / 100.0, theta=robot.theta, lower=robot.lower,
                 upper=robot.upper, unit="m",
                 source="EOSMA paper (Yin et al. 2022, Sci. Rep.), Table 1 as printed (m)")


def rokbani5() -> Robot:
    """3D-printed 5-DOF educational arm of the MO-m-PSO paper, Table 1 (cm).

    alpha1 = alpha3 = alpha4 = +90 deg as printed; the fourth row is printed
    "5" but is joint 4. Limits [0, 180], [0, 170], [0, 135], [0, 180], [0, 180] deg.
    """
    return Robot(
        name="rokbani5",
        a=[1.374, 12.0, 0.0, 0.0, 9.887],
        alpha=[PI / 2, 0.0, PI / 2, PI / 2, 0.0],
        d=[0.0, 0.0, 0.0, 11.965, 0.0],
        theta=np.zeros(5),
        lower=np.zeros(5),
        upper=np.array([180.0, 170.0, 135.0, 180.0, 180.0]) * DEG,
        unit="cm",
        source="MO-m-PSO paper (Rokbani et al. 2022, Appl. Sci. 12:7091), Table 1",
    )


def planar2() -> Robot:
    """I-BES Table 2: 2-DOF planar arm, a = 0.35, 0.30 m."""
    return _ibes("planar2", [(0, 0, 0.35, 0), (0, 0, 0.30, 0)], "I-BES paper (2024), Table 2")


def anthropomorphic3() -> Robot:
    """I-BES Table 3: 3-DOF anthropomorphic arm (alpha1 = +pi/2 as printed)."""
    return _ibes(
        "anthropomorphic3",
        [(0, 0.35, 0, PI / 2), (0, 0, 0.30, 0), (0, 0, 0.25, 0)],
        "I-BES paper (2024), Table 3",
    )


def scara4() -> Robot:
    """I-BES Table 4: SCARA, joint 3 prismatic (rows as in reference-facts.md)."""
    return _ibes(
        "scara4",
        [(0, 0.8, 0.15, 0), (0, 0, 0.40, PI), (0, 0, 0, 0), (0, 0.2, 0, 0)],
        "I-BES paper (2024), Table 4",
        types=("revolute", "revolute", "prismatic", "revolute"),
    )


def youbot5() -> Robot:
    """I-BES Table 5: KUKA youBot arm; twist signs from ARTE's youBot model."""
    return _ibes(
        "youbot5",
        [
            (0, 0.147, 0.033, PI / 2),
            (0, 0, 0.155, 0),
            (0, 0, 0.135, 0),
            (0, 0, 0, -PI / 2),
            (0, 0.218, 0, 0),
        ],
        "I-BES paper (2024), Table 5; alpha signs (+pi/2, -pi/2) from ARTE "
        "(A. Gil, robots/KUKA/YouBot/parameters.m)",
    )


def puma560() -> Robot:
    """I-BES Table 6: Puma 560; twist signs from Corke's standard-DH Puma 560."""
    return _ibes(
        "puma560",
        [
            (0, 0, 0, PI / 2),
            (0, 0, 0.431, 0),
            (0, 0.150, 0.020, -PI / 2),
            (0, 0.432, 0, PI / 2),
            (0, 0, 0, -PI / 2),
            (0, 0, 0, 0),
        ],
        "I-BES paper (2024), Table 6; alpha signs from Corke, Robotics Toolbox "
        "mdl_puma560 (pi/2, 0, -pi/2, pi/2, -pi/2, 0)",
    )


def puma560_kalra() -> Robot:
    """The Puma 560 of the solutions in I-BES Table 9 (after Kalra et al.).

    Table 9's joint angles do not reach its 5 targets on the Table 6 arm (other
    lengths and twist signs). A least-squares fit of a2, a3, d3, d4 to the
    paper's 16 I-BES solutions of targets T2-T5 (printed to 8 decimals; wrist
    centre, joints 4-6 at 0; the ``dh-fit`` table of the ``ibes-table9``
    report) gives a2 = 0.4318, a3 = -0.02032, d3 = 0.14909, d4 = 0.43307 m with
    residuals of 3e-9 m, with alpha1 = -pi/2, alpha3 = +pi/2; T1's solutions
    then reach (0.6, 0.14909, 0.2), so its printed y = 0.15 is d3 rounded.
    alpha4, alpha5 (-pi/2, +pi/2) do not move the wrist centre; limits
    [-pi, pi] as in the paper's simulations.
    """
    return _ibes(
        "puma560-kalra",
        [
            (0, 0, 0, -PI / 2),
            (0, 0, 0.4318, 0),
            (0, 0.14909, -0.02032, PI / 2),
            (0, 0.43307, 0, -PI / 2),
            (0, 0, 0, PI / 2),
            (0, 0, 0, 0),
        ],
        "I-BES paper (2024), Table 9 (Kalra et al.'s Puma); a2, a3, d3, d4 from a "
        "least-squares fit to the paper's I-BES solutions of T2-T5 (residual 3e-9 m; "
        "ibes-table9 report, dh-fit table)",
    )


def sawyer7() -> Robot:
    """I-BES Table 7: Rethink Sawyer; twist signs from Corke's DH Sawyer model."""
    return _ibes(
        "sawyer7",
        [
            (0, 0.3170, 0.081, -PI / 2),
            (0, 0.1925, 0, -PI / 2),
            (0, 0.4000, 0, -PI / 2),
            (0, 0.1685, 0, -PI / 2),
            (0, 0.4000, 0, -PI / 2),
            (0, 0.1363, 0, -PI / 2),
            (0, 0.1338, 0, 0),
        ],
        "I-BES paper (2024), Table 7; alpha signs (-pi/2 x6, 0) from Corke, "
        "roboticstoolbox-python models/DH/Sawyer.py (after Layeghi 2017)",
    )


def irb2600() -> Robot:
    """ABB IRB-2600-12/1.65 of the MChOA paper, Table 1: modified DH, mm.

    Joint 2 carries the printed offset theta2 + 90 deg; limits in degrees
    [-180, 180], [-95, 150], [-180, 75], [-400, 400], [-120, 120], [-400, 400].
    """
    return Robot(
        name="irb2600",
        a=[0.0, 150.0, -700.0, -115.0, 0.0, 0.0],
        alpha=np.array([0.0, -90.0, 0.0, 90.0, -90.0, 90.0]) * DEG,
        d=[445.0, 0.0, 0.0, 795.0, 0.0, 85.0],
        theta=np.array([0.0, 90.0, 0.0, 0.0, 0.0, 0.0]) * DEG,
        lower=np.array([-180.0, -95.0, -180.0, -400.0, -120.0, -400.0]) * DEG,
        upper=np.array([180.0, 150.0, 75.0, 400.0, 120.0, 400.0]) * DEG,
        convention="modified",
        unit="mm",
        source="MChOA paper (IRB-2600-12/1.65), Table 1, modified DH",
    )


def _shipped(file: str, name: str, tip: str | None, origin: str) -> Callable[[], Robot]:
    """A catalog entry for a URDF shipped in ``moik/robots/data`` (see its README.md)."""

    def build() -> Robot:
        robot = load_urdf(DATA / file, tip_link=tip, name=name, package_dirs=[DATA / "packages"])
        return replace(robot, source=f"{robot.source} ({origin})")

    build.__doc__ = f"{name}: {file} ({origin}), chain to {tip or 'its last movable link'}."
    return build


iiwa14 = _shipped("lbr_iiwa_14_r820.urdf", "iiwa14", "tool0",
                  "KUKA LBR iiwa 14 R820, ROS-Industrial, via rtb-data 2.0.0")
panda = _shipped("panda.urdf", "panda", "panda_hand_tcp",
                 "Franka Emika Panda, franka_description, via example-robot-data 6.0.0")
ur5 = _shipped("ur5_robot.urdf", "ur5", "tool0",
               "Universal Robots UR5, ROS-Industrial, via example-robot-data 6.0.0")
puma560_urdf = _shipped("puma560_robot.urdf", "puma560-urdf", None,
                        "Unimation Puma 560, via rtb-data 2.0.0")


_CATALOG: dict[str, Callable[[], Robot]] = {
    "eosma7": eosma7,
    "eosma7-m": eosma7_m,
    "rokbani5": rokbani5,
    "planar2": planar2,
    "anthropomorphic3": anthropomorphic3,
    "scara4": scara4,
    "youbot5": youbot5,
    "puma560": puma560,
    "puma560-kalra": puma560_kalra,
    "sawyer7": sawyer7,
    "irb2600": irb2600,
    "iiwa14": iiwa14,
    "panda": panda,
    "ur5": ur5,
    "puma560-urdf": puma560_urdf,
}


def available_robots() -> list[str]:
    """Names accepted by :func:`get_robot`."""
    return list(_CATALOG)


def as_robot(robot) -> Robot:
    """``robot`` itself if it is a :class:`Robot`, the catalog robot if it is a name.

    Raises:
        UnknownNameError: An unknown name (lists the valid ones).
        ParameterError: Anything else.
    """
    if isinstance(robot, Robot):
        return robot
    if isinstance(robot, str):
        return get_robot(robot)
    raise ParameterError(f"robot must be a moik Robot or a catalog robot name, got "
                         f"{type(robot).__name__}")


def get_robot(name: str) -> Robot:
    """The catalog robot called ``name``.

    Raises:
        UnknownNameError: listing the valid names.
    """
    try:
        return _CATALOG[name]()
    except (KeyError, TypeError):
        raise UnknownNameError("robot", name, _CATALOG) from None
