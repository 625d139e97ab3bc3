"""F24 of the MChOA paper: weighted pose IK of the ABB IRB-2600 (Eq. 6).

Source: MChOA paper (the team's copy ``mchoa-industrial-robot``),
Section 2.2, Eq. 6 ``f3 = alpha ||dp|| + beta ||dR||`` with the Table 1 arm
(modified DH, mm; :func:`moik.robots.catalog.irb2600`), and Section 4.2:
"establishing the fitness function in the manner of Equation (6) and using a
set of preset numerical values substituted into Equation (2) as the final
position's pose matrix", i.e. the target is the FK pose of preset joint values.
The domain is the joint range of Table 1 (the paper's first way of setting
the bounds).

What the paper leaves open, and what moik chooses (state these numbers beside
any F24 result; the paper's F24 row is not comparable to them):

* ``alpha``, ``beta``: the paper only says that ``||dp||`` is of order 1e3 (mm)
  and ``||dR||`` of order 1 and that the weights must harmonise them. moik takes
  ``alpha = 1`` (per mm) and ``beta = 1000``, so 1 mm of position error weighs
  as much as a Frobenius orientation error of 1e-3.
* the preset joint values: ``q_target_deg = (30, 20, -40, 45, 60, 30)`` degrees,
  inside the joint range and away from the wrist singularity (theta5 != 0).
* ``||dR||`` is the Frobenius norm of ``R(q) - R_target`` (``"frobenius"`` metric).

The known optimum is 0, reached at ``q_target`` (and at the other IK branches).
"""

from __future__ import annotations

import numpy as np

from moik.exceptions import ParameterError
from moik.problems.benchmarks._base import Benchmark
from moik.problems.ik import PoseIK
from moik.robots.catalog import irb2600

DEFAULT_Q_TARGET_DEG = (30.0, 20.0, -40.0, 45.0, 60.0, 30.0)
"""moik's preset joint values (degrees) whose FK pose is the F24 target."""


class IRB2600PoseIK(Benchmark):
    """MChOA F24: ``alpha ||p(q) - p_t|| + beta ||R(q) - R_t||_F`` on the IRB-2600.

    Args:
        alpha: Position weight (per mm), finite and >= 0.
        beta: Orientation weight (Frobenius norm), finite and >= 0; not both 0.
        q_target_deg: Six joint values in degrees, inside the Table 1 joint
            range; their FK pose is the target.

    Raises:
        ParameterError: For negative or non-finite weights, both weights 0, or
            ``q_target_deg`` of the wrong length, non-finite or out of range.
    """

    def __init__(self, *, alpha: float = 1.0, beta: float = 1000.0,
                 q_target_deg=DEFAULT_Q_TARGET_DEG) -> None:
        weights = np.array([alpha, beta], dtype=float)
        if not np.all(np.isfinite(weights)) or np.any(weights < 0) or weights.sum() == 0:
            raise ParameterError(f"F24 weights alpha and beta must be finite and >= 0, not "
                                 f"both 0; got alpha={alpha!r}, beta={beta!r}")
        robot = irb2600()
        q_deg = np.asarray(q_target_deg, dtype=float)
        if q_deg.shape != (robot.dof,) or not np.all(np.isfinite(q_deg)):
            raise ParameterError(f"q_target_deg must be {robot.dof} finite joint values in "
                                 f"degrees, got {q_target_deg!r}")
        q_target = np.deg2rad(q_deg)
        if np.any(q_target < robot.lower - 1e-12) or np.any(q_target > robot.upper + 1e-12):
            raise ParameterError(
                f"q_target_deg {q_deg.tolist()} is outside the IRB-2600 joint range "
                f"{np.rad2deg(robot.lower).round(6).tolist()} .. "
                f"{np.rad2deg(robot.upper).round(6).tolist()} degrees")
        self.alpha, self.beta = float(alpha), float(beta)
        self.ik = PoseIK(robot, robot.fk(q_target), weights=(alpha, beta),
                         orientation="frobenius")
        super().__init__(n_var=robot.dof, xl=robot.lower.copy(), xu=robot.upper.copy(),
                         f_opt=0.0, x_opt=q_target)

    def _evaluate(self, X, out, *args, **kwargs):
        self.ik._evaluate(X, out)
