"""moik: multi-objective inverse kinematics of robot arms with metaheuristics, on pymoo.

Public API: :func:`get_robot` (the papers' arms), :func:`load_urdf`,
:func:`solve_ik`, :func:`solve_ik_batch` and :func:`solve_path` (the practical
solver), the IK problems in :mod:`moik.problems` and the algorithms in
:mod:`moik.algorithms`.
"""

from moik import algorithms, problems
from moik._version import __version__
from moik.exceptions import MoikError
from moik.robots import Robot, available_robots, get_robot
from moik.robots.urdf import load_urdf
from moik.solver import (
    IKBatchResult,
    IKResult,
    ParetoIKResult,
    PathResult,
    solve_ik,
    solve_ik_batch,
    solve_ik_pareto,
    solve_path,
)

__all__ = [
    "IKBatchResult",
    "IKResult",
    "MoikError",
    "ParetoIKResult",
    "PathResult",
    "Robot",
    "__version__",
    "algorithms",
    "available_robots",
    "get_robot",
    "load_urdf",
    "problems",
    "solve_ik",
    "solve_ik_batch",
    "solve_ik_pareto",
    "solve_path",
]
