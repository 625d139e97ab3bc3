"""Three objectives: position error, orientation error and joint motion.

The bi-objective IK problem (MO-m-PSO Eq. 15) with EOSMA's joint-displacement term
(Eq. 31) as a third objective of its own instead of a weighted addition:
``F = (||p(q) - p_t||, e_R(q), ||q - q_start||)``.
"""

from __future__ import annotations

import numpy as np

from moik.exceptions import ParameterError
from moik.problems.ik import BiObjectiveIK
from moik.robots.chain import Robot


class PoseMotionIK(BiObjectiveIK):
    """Position error, orientation error and ``||q - q_start||`` (EOSMA Eq. 31's term).

    Args:
        robot: The arm.
        target: Pose with an orientation.
        q_start: The configuration the motion is measured from (required).
        orientation: Orientation metric name.

    ``pareto_front()`` is not available: the reference fronts of :mod:`moik.fronts`
    cover the two pose errors only (it raises :class:`ParameterError`).
    """

    n_obj_ik = 3

    def __init__(self, robot: Robot, target, *, q_start, orientation: str = "geodesic"):
        if q_start is None:
            raise ParameterError("PoseMotionIK needs q_start (the motion is measured from it)")
        super().__init__(robot, target, orientation=orientation, q_start=q_start)

    def _evaluate(self, X, out, *args, **kwargs):
        X = np.atleast_2d(X)
        pos, ori = self.errors(X)
        motion = np.linalg.norm(self.robot.kernel_batch(X) - self._q_start, axis=1)
        out["F"] = np.column_stack([pos, ori, motion])

    def reference_front(self, *, use_cache: bool = True):
        """Not available for three objectives.

        Raises:
            ParameterError: Always.
        """
        raise ParameterError("no reference front for PoseMotionIK: moik.fronts computes "
                             "bi-objective (position, orientation) fronts only")
