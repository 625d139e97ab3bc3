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
from typing import NamedTuple

import numpy as np

from moik.kinematics.criteria import nearest_copies
from moik.metrics.compromise import closest_to_utopia
from moik.solver.session import SolveSession, pose_errors

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
        status: ``"solved"``, ``"unreachable"``, ``"not-converged"`` or, with a
            collision check (``scene=`` / ``self_collision=``), ``"collides"``: exact
            solutions were found but every one is closer than ``clearance`` (``q`` is
            the one farthest from contact, :attr:`min_distance` its distance); never
            ``"solved"`` for an answer in collision.
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
        min_distance: With a collision check, the smallest signed distance of ``q``
            (robot unit; recomputed at the end by the compiled checker; ``inf`` when
            no pair is checked); ``None`` without one.
        distances: With a collision check, that distance for each row of
            ``solutions`` (all >= the clearance); ``None`` without one.
        unchecked_links: With a collision check, the arm's links that have no geometry
            and so were not checked (a model built with ``missing="ignore"``); empty
            otherwise. "Collision-free" says nothing about these links.
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
    min_distance: float | None = None
    distances: np.ndarray | None = field(default=None, repr=False)
    unchecked_links: tuple[str, ...] = ()

    @property
    def fewer_solutions(self) -> bool:
        """Solved, but with fewer distinct solutions than requested."""
        return self.success and len(self.solutions) < self.n_requested


class Verdict(NamedTuple):
    """What a finished solve concluded (:func:`verdict`), before its result is assembled.

    Attributes:
        status: As :attr:`IKResult.status`.
        q: The answer (a solution, the farthest-from-contact exact answer, or the best
            candidate).
        solutions: The distinct solutions kept ``(k, dof)`` (ordered as returned).
        errors: ``(position, orientation)`` of ``q``, recomputed by FK.
        distances: With a collision check, the smallest distance of each solution
            (``None`` without one).
        min_distance: With a collision check, that of ``q`` (``None`` without one).
        front, front_q: The front of an unsolved pose (``None`` otherwise).
    """

    status: str
    q: np.ndarray
    solutions: np.ndarray
    errors: tuple[float, float]
    distances: np.ndarray | None
    min_distance: float | None
    front: np.ndarray | None
    front_q: np.ndarray | None


def verdict(session: SolveSession, q_current, searched_out: bool, front, front_q,
            proven: bool = False) -> Verdict:
    """The verdict of a finished solve; the session is not changed.

    Solutions closer than the clearance (recomputed at the end, as the errors are) are
    dropped; with none left, exact answers in collision make ``"collides"``, else the
    status is "unreachable" only for a proof or a full search that ended far from the
    target (its errors re-checked by the independent reference FK), else "not-converged".
    """
    robot, target, guard, tol = session.robot, session.target, session.guard, session.tol
    found, found_errors = session.found, session.found_errors
    dists = None  # the solutions' distances, recomputed at the end as the errors are
    if found and guard is not None:
        dists = guard.distances(np.array(found))
        keep = guard.keeps(dists)
        found = [q for q, k in zip(found, keep, strict=True) if k]
        found_errors = [e for e, k in zip(found_errors, keep, strict=True) if k]
        dists = dists[keep]
    errors: tuple[float, float] | None = None
    if found:
        sols = np.array(found)
        if q_current is not None:  # 2 pi copies nearest to the current configuration first
            sols = nearest_copies(robot, sols, q_current)
            order = np.argsort(np.linalg.norm(sols - q_current, axis=1), kind="stable")
            sols = sols[order]
            dists = None if dists is None else dists[order]
        else:
            errors = found_errors[0]
        q, status, front, front_q = sols[0], "solved", None, None
    elif session.colliding is not None:  # exact answers, all in collision
        sols, status, front, front_q = np.empty((0, robot.dof)), "collides", None, None
        q = session.colliding[1]
    else:
        assert session.best is not None  # every stage considers at least one candidate
        sols = np.empty((0, robot.dof))
        far = session.best[0] > UNREACHABLE_FACTOR * tol.scaled(robot.reach)
        status = "unreachable" if proven or (searched_out and far) else "not-converged"
        q = session.best[1]
        if status == "unreachable" and front is not None:
            q = np.clip(front_q[closest_to_utopia(front)], robot.lower, robot.upper)
    if errors is None:  # unsolved: the independent reference FK has the last word
        pos_v, ori_v = pose_errors(robot, target, q, reference=status != "solved")
        errors = (float(pos_v[0]), float(ori_v[0]))
    d_q = (None if guard is None else float(dists[0]) if dists is not None and len(dists)
           else float(guard.distances(q)[0]))
    if status != "solved" and tol.certifies(*errors):
        if guard is not None and d_q is not None and not guard.keeps(d_q):
            status = "collides"  # exact, but in collision: never a solution
        else:
            status, sols = "solved", q[None]  # an answer within tolerance is a solution
            dists = None if d_q is None else np.array([d_q])
    return Verdict(status=status, q=q, solutions=sols, errors=errors, distances=dists,
                   min_distance=d_q, front=front, front_q=front_q)


def ik_result(session: SolveSession, q_current, t0: float, searched_out: bool, front, front_q,
              proven: bool = False) -> IKResult:
    """The :class:`IKResult` of a finished solve (``t0``: its start, ``perf_counter``):
    its :func:`verdict` and why it delivered less than was asked."""
    v = verdict(session, q_current, searched_out, front, front_q, proven)
    robot, guard = session.robot, session.guard
    detail = ""
    if v.status == "solved" and len(v.solutions) < session.wanted:
        why = ("the evaluation budget was spent" if session.n_eval >= session.max_evals
               else "the search stopped finding new ones")
        detail = (f"found {len(v.solutions)} of the {session.wanted} distinct solutions "
                  f"requested ({why})")
    elif v.status == "collides" and guard is not None:
        detail = (f"{max(session.n_rejected, 1)} exact answer(s) rejected for collision; the "
                  f"farthest from contact is at {v.min_distance:.4g} {robot.unit}, below the "
                  f"clearance {guard.clearance:g}")
        if session.collision_proof is not None:  # solve_ik.collision_proven
            pair, _ = session.collision_proof
            detail += (f"; proven, no exact answer can keep it: {' and '.join(pair or ())}, "
                       "placed by the target alone, are closer than that")
    distances = None if guard is None else v.distances if len(v.solutions) else np.zeros(0)
    return IKResult(q=v.q, position_error=v.errors[0], orientation_error=v.errors[1],
                    success=v.status == "solved", status=v.status, n_eval=session.n_eval,
                    time=time.perf_counter() - t0, solutions=v.solutions, front=v.front,
                    front_q=v.front_q, n_requested=session.wanted, detail=detail,
                    min_distance=v.min_distance, distances=distances,
                    unchecked_links=() if guard is None else guard.checker.model.unchecked_links)
