"""Three objectives: position error, orientation error and joint motion.

The bi-objective IK problem (MO-m-PSO Eq. 15) with EOSMA's joint-displacement term
(Eq. 31) as a third objective of its own instead of a weighted addition:
``F = (||p(q) - p_t||, e_R(q), ||q - q_start||)``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from moik._lazy import lazy_module
from moik.exceptions import ParameterError
from moik.problems.ik import BiObjectiveIK
from moik.robots.chain import Robot

if TYPE_CHECKING:
    from moik.fronts import cache as front_cache
else:  # loaded at the first reference front (moik._lazy)
    front_cache = lazy_module("moik.fronts.cache")


class PoseMotionIK(BiObjectiveIK):
    """Position error, orientation error and ``||q - q_start||`` (EOSMA Eq. 31's term).

    Args:
        robot: The arm.
        target: Pose with an orientation.
        q_start: The configuration the motion is measured from (required).
        orientation: Orientation metric name.

    ``pareto_front()`` is the three-objective reference front
    (:func:`moik.fronts.motion.motion_front`, shipped for ``eosma-p1-motion``, else
    computed on first use and cached on disk).
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
        """The three-objective reference front (:func:`moik.fronts.cache.cached_motion_front`):
        computed on first use (seconds), then read from the disk cache.

        Raises:
            ParameterError: For a ZYX Euler orientation metric (its kinks need the lifted
                subproblems, written for two objectives only).
        """
        return front_cache.cached_motion_front(self.robot, self.target.position,
                                               self.target.rotation, self._q_start,
                                               metric=self.orientation, use_cache=use_cache)
