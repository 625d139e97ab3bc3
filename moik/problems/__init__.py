"""IK problems and targets (vectorized pymoo Problems)."""

from moik.problems.ik import BiObjectiveIK, PoseIK, PositionIK
from moik.problems.motion_ik import PoseMotionIK
from moik.problems.pareto_ik import ParetoIK
from moik.problems.registry import available, get_problem
from moik.problems.targets import Target, as_target, circle_path, random_reachable_targets

__all__ = [
    "BiObjectiveIK",
    "ParetoIK",
    "PoseIK",
    "PoseMotionIK",
    "PositionIK",
    "Target",
    "as_target",
    "available",
    "get_problem",
    "circle_path",
    "random_reachable_targets",
]
