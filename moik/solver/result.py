"""What :func:`moik.solver.solve_ik` returns, and how the verdict of a solve is reached.

:func:`ik_result` turns a finished :class:`~moik.solver.session.SolveSession` into an
:class:`IKResult`: the solutions (2 pi copies nearest to ``q_current`` first), or, when
none was found, the status ("unreachable" only for a proof or a full search that ended
far from the target, else "not-converged") with the best candidate or the front's
compromise, its errors recomputed by the independent reference FK.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from moik.metrics.compromise import closest_to_utopia
from moik.solver.session import SolveSession, nearest_copies, pose_errors

UNREACHABLE_FACTOR = 1e3  # best error beyond this many tolerances after a full search


@dataclass(frozen=True)
class IKResult:
    """Outcome of :func:`solve_ik`.

    Attributes:
        q: Joint vector (always within the limits): the solution, or the best
            compromise when not solved.
        position_error: ``||p(q) - p_target||`` in the robot's unit, recomputed by FK.
        orientation_error: Geodesic angle (rad) between ``R(q)`` and the target
            rotation, recomputed by FK (0 for position-only targets).
        success: Both errors within tolerance.
        status: ``"solved"``, ``"unreachable"`` or ``"not-converged"``.
        n_eval: Forward-kinematics evaluations (search + polish + front).
        time: Wall time in seconds.
        solutions: Distinct solutions found (``(k, dof)``), nearest to
            ``q_current`` first when it was given.
        front: Pareto front ``(m, 2)`` of (position, orientation) errors (the
            ``orientation`` metric) when a pose was not solved (``None``
            otherwise), with ``front_q`` its joint vectors.
        n_requested: The ``n_solutions`` asked for.
        detail: Empty when the solve delivered what was asked; else why not, e.g.
            ``"found 33 of the 50 distinct solutions requested (...)"``: a solved
            target with fewer solutions than requested (:attr:`fewer_solutions`).
    """

    q: np.ndarray
    position_error: float
    orientation_error: float
    success: bool
    status: str
    n_eval: int
    time: float
    solutions: np.ndarray
    front: np.ndarray | None = None
    front_q: np.ndarray | None = field(default=None, repr=False)
    n_requested: int = 1
    detail: str = ""

    @property
    def fewer_solutions(self) -> bool:
        """Solved, but with fewer distinct solutions than requested."""
        return self.success and len(self.solutions) < self.n_requested


def ik_result(session: SolveSession, q_current, t0: float, searched_out: bool, front, front_q,
              proven: bool = False) -> IKResult:
    """The :class:`IKResult` of a finished solve (``t0``: its start, ``perf_counter``)."""
    robot, target = session.robot, session.target
    errors: tuple[float, float] | None = None
    if session.found:
        sols = np.array(session.found)
        if q_current is not None:  # 2 pi copies nearest to the current configuration first
            sols = nearest_copies(robot, sols, q_current)
            sols = sols[np.argsort(np.linalg.norm(sols - q_current, axis=1), kind="stable")]
        else:
            errors = session.found_errors[0]
        q, status, front, front_q = sols[0], "solved", None, None
    else:
        assert session.best is not None  # every stage considers at least one candidate
        sols = np.empty((0, robot.dof))
        tol = session.tol_pos / robot.reach + session.tol_ori
        far = session.best[0] > UNREACHABLE_FACTOR * tol
        status = "unreachable" if proven or (searched_out and far) else "not-converged"
        q = session.best[1]
        if status == "unreachable" and front is not None:
            q = np.clip(front_q[closest_to_utopia(front)], robot.lower, robot.upper)
    if errors is None:  # unsolved: the independent reference FK has the last word
        pos_v, ori_v = pose_errors(robot, target, q, reference=status != "solved")
        errors = (float(pos_v[0]), float(ori_v[0]))
    pos, ori = errors
    if status != "solved" and pos <= session.tol_pos and ori <= session.tol_ori:
        status, sols = "solved", q[None]  # an answer within tolerance is a solution
    detail = ""
    if status == "solved" and len(sols) < session.wanted:
        why = ("the evaluation budget was spent" if session.n_eval >= session.max_evals
               else "the search stopped finding new ones")
        detail = f"found {len(sols)} of the {session.wanted} distinct solutions requested ({why})"
    return IKResult(q=q, position_error=pos, orientation_error=ori, success=status == "solved",
                    status=status, n_eval=session.n_eval, time=time.perf_counter() - t0,
                    solutions=sols, front=front, front_q=front_q, n_requested=session.wanted,
                    detail=detail)
