"""IK problems and targets (vectorized pymoo Problems)."""

from moik.problems.ik import BiObjectiveIK, PoseIK, PositionIK
from moik.problems.pareto_ik import ParetoIK
from moik.problems.targets import Target, as_target, circle_path, random_reachable_targets

__all__ = [
    "BiObjectiveIK",
    "ParetoIK",
    "PoseIK",
    "PositionIK",
    "Target",
    "as_target",
    "circle_path",
    "random_reachable_targets",
]
