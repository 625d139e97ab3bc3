"""Bookkeeping of one :func:`moik.solver.solve_ik` call: tolerances, found solutions.

Every candidate, from any stage (batched Levenberg-Marquardt, least-squares
polish, search), goes through :meth:`SolveSession.consider`, which recomputes
its errors with the reference FK (:func:`pose_errors`, the honest re-check)
and keeps it only if it is within tolerance and distinct from the solutions
already found.
"""

from __future__ import annotations

import numpy as np

from moik._validate import positive
from moik.exceptions import ParameterError
from moik.kinematics.orientation import geodesic_error
from moik.problems.targets import Target
from moik.robots.chain import Robot, fk_reference
from moik.solver.batch_lm import batch_lm
from moik.solver.polish import polish as polish_q

BATCH_ITERATIONS = 30  # Levenberg-Marquardt iterations of the first attempt


def tolerances(tol, robot: Robot) -> tuple[float, float]:
    """``(position, orientation)`` tolerances from ``solve_ik``'s ``tol``.

    A number ``t`` means ``t * robot.reach`` and ``t`` rad; a pair is taken as is.
    Each must be a finite number > 0 (bools refused).

    Raises:
        ParameterError: Anything else, naming what was given.
    """
    if isinstance(tol, np.ndarray) and tol.ndim == 0:
        tol = tol.item()
    try:
        shape = np.shape(tol)
    except ValueError:  # ragged sequences
        shape = None
    if shape == ():
        t = positive("tol", tol)
        return t * robot.reach, t
    if shape == (2,):
        return (positive("tol[0] (position tolerance)", tol[0]),
                positive("tol[1] (orientation tolerance)", tol[1]))
    raise ParameterError(f"tol must be a number or (position, orientation), got {tol!r}")


def pose_errors(robot: Robot, target: Target, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Position error (robot unit) and geodesic orientation error (rad), recomputed by FK.

    Uses the straightforward reference FK (``fk_reference``), independent of the
    kernel the optimizers ran on. Orientation error is 0 for position-only targets.
    """
    T = fk_reference(robot, np.atleast_2d(Q))
    pos = np.linalg.norm(T[:, :3, 3] - target.position, axis=1)
    if target.rotation is None:
        return pos, np.zeros_like(pos)
    return pos, geodesic_error(T[:, :3, :3], target.rotation)


def joint_distance(robot: Robot, q: np.ndarray, others: np.ndarray) -> np.ndarray:
    """Joint-space distances from ``q`` to each row of ``others``.

    Revolute differences are wrapped to ``[-pi, pi]``: angles 2*pi apart are
    the same arm configuration (though not the same motion).
    """
    diff = np.atleast_2d(others) - q
    wrapped = (diff + np.pi) % (2 * np.pi) - np.pi
    return np.linalg.norm(np.where(robot.is_prismatic, diff, wrapped), axis=1)


def is_distinct(robot: Robot, q: np.ndarray, others: list[np.ndarray], threshold: float) -> bool:
    """Whether ``q`` is farther than ``threshold`` from every row of ``others``."""
    return not others or bool(np.all(joint_distance(robot, q, np.array(others)) > threshold))


class SolveSession:
    """Bookkeeping of one solve: FK evaluations, found solutions, best candidate.

    Args:
        robot, target: The problem.
        tol_pos, tol_ori: Tolerances (robot unit, rad).
        distinct: Joint-space distance above which two solutions are distinct.
        wanted: Number of solutions asked for; no more are kept.
    """

    def __init__(self, robot, target, tol_pos, tol_ori, distinct, wanted):
        self.robot, self.target = robot, target
        self.tol_pos, self.tol_ori, self.distinct = tol_pos, tol_ori, distinct
        self.wanted = wanted  # solutions asked for: no more are kept
        self.n_eval = 0
        self.found: list[np.ndarray] = []
        self.best: tuple[float, np.ndarray] | None = None  # (scaled error, q)

    def refine(self, q0: np.ndarray, do_polish: bool, max_nfev: int = 60) -> None:
        """Least-squares polish of ``q0`` (or only clipping), then :meth:`consider`."""
        if do_polish:
            out = polish_q(self.robot, self.target, q0, length=self.robot.reach,
                           max_nfev=max_nfev,
                           stop_position=1e-3 * self.tol_pos,
                           stop_orientation=1e-3 * self.tol_ori)
            self.n_eval += out.n_eval
            q = out.q
        else:
            q = np.clip(q0, self.robot.lower, self.robot.upper)
        self.consider(q[None])

    def local_batch(self, Q0: np.ndarray, stop_after: int | None) -> bool:
        """Batched Levenberg-Marquardt from the rows of ``Q0``; whether any converged."""
        out = batch_lm(self.robot, self.target, Q0, length=self.robot.reach,
                       stop_position=1e-3 * self.tol_pos, stop_orientation=1e-3 * self.tol_ori,
                       max_iter=BATCH_ITERATIONS, stop_after=stop_after)
        self.n_eval += out.n_eval
        err = out.position_error / self.robot.reach + out.orientation_error
        order = np.argsort(np.where(out.converged, -1.0, err), kind="stable")
        self.consider(out.Q[order[: max(int(out.converged.sum()), 1)]])
        return bool(out.converged.any())

    def consider(self, Q: np.ndarray) -> None:
        """Check candidates with the reference FK; keep the distinct solutions and the best."""
        pos, ori = pose_errors(self.robot, self.target, Q)
        for q, p, o in zip(Q, pos, ori, strict=True):
            err = float(p) / self.robot.reach + float(o)
            if self.best is None or err < self.best[0]:
                self.best = (err, q)
            if (len(self.found) < self.wanted and p <= self.tol_pos and o <= self.tol_ori
                    and is_distinct(self.robot, q, self.found, self.distinct)):
                self.found.append(q)
