"""The practical IK solver: :func:`solve_ik` for one target, :func:`solve_ik_batch` for many,
:func:`solve_path` for a sequence.

Modules: :mod:`~moik.solver.solve_ik` (the stages and the verdict),
:mod:`~moik.solver.session` (per-solve bookkeeping, the honest FK re-check),
:mod:`~moik.solver.lm` and :mod:`~moik.solver.multistart` (compiled multi-start
Levenberg-Marquardt),
:mod:`~moik.solver.front` (reach bound, polished error fronts),
:mod:`~moik.solver.batch` (many targets in one call),
:mod:`~moik.solver.polish` (bounded least-squares refinement) and
:mod:`~moik.solver.path` (a path kept on one branch).
"""

from moik.solver.batch import IKBatchResult, solve_ik_batch
from moik.solver.pareto import ParetoIKResult, solve_ik_pareto
from moik.solver.path import PathResult, solve_path
from moik.solver.solve_ik import IKResult, solve_ik

__all__ = ["IKBatchResult", "IKResult", "ParetoIKResult", "PathResult", "solve_ik",
           "solve_ik_batch", "solve_ik_pareto", "solve_path"]
