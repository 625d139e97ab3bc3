"""IK problems and targets (vectorized pymoo Problems)."""

from moik.problems.ik import BiObjectiveIK, PoseIK, PositionIK
from moik.problems.targets import Target, as_target, circle_path, random_reachable_targets

__all__ = [
    "BiObjectiveIK",
    "PoseIK",
    "PositionIK",
    "Target",
    "as_target",
    "circle_path",
    "random_reachable_targets",
]
