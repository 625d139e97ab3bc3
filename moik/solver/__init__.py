"""The practical IK solver: :func:`solve_ik` for one target, :func:`solve_ik_batch` for many,
:func:`solve_path` for a sequence.

Modules: :mod:`~moik.solver.solve_ik` (the stages and the verdict),
:mod:`~moik.solver.session` (per-solve bookkeeping, the honest FK re-check),
:mod:`~moik.solver.context` (the constants of one solve, the LM scratch),
:mod:`~moik.solver.lm` and :mod:`~moik.solver.starts` (compiled multi-start
Levenberg-Marquardt, the one start loop),
:mod:`~moik.solver.front` (reach bound, polished error fronts),
:mod:`~moik.solver.batch` (many targets in one call),
:mod:`~moik.solver.polish` (bounded least-squares refinement) and
:mod:`~moik.solver.path` (a path kept on one branch).
"""

from typing import TYPE_CHECKING

from moik._lazy import lazy_names

# imported here, not lazily: the submodule's name is the function's, and a lazy name would
# be shadowed by the submodule once anything imports it
from moik.solver.result import IKResult
from moik.solver.solve_ik import solve_ik

if TYPE_CHECKING:
    from moik.solver.batch import IKBatchResult, solve_ik_batch
    from moik.solver.pareto import ParetoIKResult, solve_ik_pareto
    from moik.solver.path import PathResult, solve_path, solve_paths

_LAZY: dict[str, tuple[str, str | None]] = {
    "IKBatchResult": ("moik.solver.batch", "IKBatchResult"),
    "solve_ik_batch": ("moik.solver.batch", "solve_ik_batch"),
    "ParetoIKResult": ("moik.solver.pareto", "ParetoIKResult"),
    "solve_ik_pareto": ("moik.solver.pareto", "solve_ik_pareto"),
    "PathResult": ("moik.solver.path", "PathResult"),
    "solve_path": ("moik.solver.path", "solve_path"),
    "solve_paths": ("moik.solver.path", "solve_paths"),
}
"""Public name -> (module, attribute): each loads at first use (start-up time: the
single-pose solver need not import the search, Pareto and path machinery)."""

__all__ = ["IKBatchResult", "IKResult", "ParetoIKResult", "PathResult", "solve_ik",
           "solve_ik_batch", "solve_ik_pareto", "solve_path", "solve_paths"]

__getattr__, __dir__ = lazy_names("moik.solver", _LAZY, globals(), __all__)
