"""moik: multi-objective inverse kinematics of robot arms with metaheuristics, on pymoo.

Public API: :func:`get_robot` (the papers' arms), :func:`load_urdf`,
:func:`solve_ik`, :func:`solve_ik_batch`, :func:`solve_ik_pareto` and
:func:`solve_path` (the practical solver), the IK problems in :mod:`moik.problems`
and the algorithms in :mod:`moik.algorithms`.

``import moik`` loads only the exceptions and the version; each name below loads its
module at first use (``moik.solve_ik``, ``from moik import get_robot``). numba, pymoo
and scipy take about half a second to import, which a script that only reads
``moik.__version__`` or a ``--help`` need not pay.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from moik._lazy import lazy_names
from moik._version import __version__
from moik.exceptions import MoikError

if TYPE_CHECKING:
    from moik import algorithms, problems
    from moik.robots import Robot, available_robots, get_robot
    from moik.robots.urdf import load_urdf
    from moik.solver import (
        IKBatchResult,
        IKResult,
        ParetoIKResult,
        PathResult,
        solve_ik_batch,
        solve_ik_pareto,
        solve_path,
    )
    from moik.solver.solve_ik import solve_ik

_LAZY: dict[str, tuple[str, str | None]] = {
    "IKBatchResult": ("moik.solver.batch", "IKBatchResult"),
    "IKResult": ("moik.solver", "IKResult"),
    "ParetoIKResult": ("moik.solver.pareto", "ParetoIKResult"),
    "PathResult": ("moik.solver.path", "PathResult"),
    "Robot": ("moik.robots", "Robot"),
    "algorithms": ("moik.algorithms", None),
    "available_robots": ("moik.robots", "available_robots"),
    "get_robot": ("moik.robots", "get_robot"),
    "load_urdf": ("moik.robots.urdf", "load_urdf"),
    "problems": ("moik.problems", None),
    "solve_ik": ("moik.solver", "solve_ik"),
    "solve_ik_batch": ("moik.solver.batch", "solve_ik_batch"),
    "solve_ik_pareto": ("moik.solver.pareto", "solve_ik_pareto"),
    "solve_path": ("moik.solver.path", "solve_path"),
}
"""Public name -> (module, attribute); None: the module itself."""

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


__getattr__, __dir__ = lazy_names("moik", _LAZY, globals(), __all__)
