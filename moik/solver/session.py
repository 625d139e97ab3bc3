"""Bookkeeping of one :func:`moik.solver.solve_ik` call: tolerances, found solutions.

Every candidate, from any stage (batched Levenberg-Marquardt, least-squares
polish, search), goes through :meth:`SolveSession.consider`, which recomputes
its errors with the reference FK (:func:`pose_errors`, the honest re-check)
and keeps it only if it is within tolerance and distinct from the solutions
already found.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from moik._jit import jit, kernel_array
from moik.kinematics.rotation_metrics import geodesic_angle
from moik.kinematics.tolerance import Tolerance
from moik.problems.targets import Target
from moik.robots.chain import Robot, fk_reference
from moik.solver.collision import CollisionGuard
from moik.solver.context import ik_context
from moik.solver.polish import polish as polish_q
from moik.solver.starts import CHECK, PATIENT, found_table, is_distinct, run_starts
from moik.solver.tested_starts import run_collision_starts


def pose_errors(robot: Robot, target, Q: np.ndarray, *, reference: bool = False
                ) -> tuple[np.ndarray, np.ndarray]:
    """Position error (robot unit) and geodesic orientation error (rad), recomputed by FK.

    The honest re-check: the errors of the returned joint vectors, evaluated anew
    by a forward kinematics pass of their own, never taken from an optimizer's
    bookkeeping. By default the compiled FK (``robot.fk_parts``, tested equal to the
    reference to 1e-12); with ``reference=True`` the plain-numpy ``fk_reference``,
    independent of every kernel (used for the verdict on unsolved targets).
    Orientation error is 0 for position-only targets.

    Args:
        robot: The arm.
        target: One :class:`~moik.problems.targets.Target` for every row, or
            ``(positions (n, 3), rotations (n, 3, 3) or None)``, one target per row.
        Q: Joint vectors ``(n, dof)`` or one ``(dof,)``.
    """
    Q = np.atleast_2d(Q)
    if isinstance(target, Target):
        position, rotation = target.position, None if target.rotation is None else \
            target.rotation[None]
    else:
        position, rotation = target
    if len(Q) == 0:
        return np.zeros(0), np.zeros(0)
    if reference:
        T = fk_reference(robot, Q)
        R, p = np.ascontiguousarray(T[:, :3, :3]), T[:, :3, 3]
    else:
        R, p = robot.fk_parts(Q)
    d = p - position
    pos = np.sqrt(np.einsum("ij,ij->i", d, d))
    if rotation is None:
        return pos, np.zeros_like(pos)
    ori = np.empty(len(Q))
    geodesic_errors(R, kernel_array(rotation), ori)
    return pos, ori


@jit
def geodesic_errors(R, Rts, out):
    """Geodesic angles between ``R[i]`` and ``Rts[i]`` (``Rts[0]`` for all if it has one row)."""
    for i in range(R.shape[0]):
        rot = (R[i, 0, 0], R[i, 0, 1], R[i, 0, 2], R[i, 1, 0], R[i, 1, 1], R[i, 1, 2],
               R[i, 2, 0], R[i, 2, 1], R[i, 2, 2])
        out[i] = geodesic_angle(rot, Rts[0] if Rts.shape[0] == 1 else Rts[i])


class SolveSession:
    """Bookkeeping of one solve: FK evaluations, found solutions, best candidate.

    Args:
        robot, target: The problem.
        tol: The :class:`~moik.kinematics.tolerance.Tolerance` an answer must meet.
        distinct: Joint-space distance above which two solutions are distinct.
        wanted: Number of solutions asked for; no more are kept.
        max_evals: FK evaluation budget (the first stage starts no start past it).
        guard: The collision test (:mod:`moik.solver.collision`): an exact answer that
            fails it is not a solution (reject-and-restart), the farthest from contact
            is kept as :attr:`colliding`.
    """

    def __init__(self, robot, target, tol: Tolerance, distinct, wanted,
                 max_evals: int = 2**62, guard: CollisionGuard | None = None):
        self.robot, self.target = robot, target
        self.tol, self.distinct = tol, distinct
        self.wanted = wanted  # solutions asked for: no more are kept
        self.max_evals = max_evals  # FK budget: the first stage starts no start beyond it
        self.n_eval = 0
        self.found: list[np.ndarray] = []
        self.found_errors: list[tuple[float, float]] = []  # (position, orientation) of each
        self.best: tuple[float, np.ndarray] | None = None  # (scaled error, q)
        self.guard = guard  # the collision test of an answer (None: none)
        # the exact answer rejected for collision with the largest distance: (distance, q)
        self.colliding: tuple[float, np.ndarray] | None = None
        self.n_rejected = 0  # exact answers rejected for collision
        # why no exact answer can keep the clearance: (pair, its distance), set when proven
        self.collision_proof: tuple[tuple[str, str] | None, float] | None = None
        # the start loop's context; with a guard also one with the collision set (the loop
        # runs on one or the other: moik.solver.tested_starts.run_collision_starts)
        self.ctx = ik_context(robot, target, stop=tol.stop, tol=tol, distinct=distinct)
        self._collision_ctx: Any = None

    def refine(self, q0: np.ndarray, do_polish: bool, max_nfev: int = 60) -> None:
        """Least-squares polish of ``q0`` (or only clipping), then :meth:`consider`."""
        if do_polish:
            stop_position, stop_orientation = self.tol.polish_stop
            out = polish_q(self.robot, self.target, q0, length=self.robot.reach,
                           max_nfev=max_nfev, stop_position=stop_position,
                           stop_orientation=stop_orientation)
            self.n_eval += out.n_eval
            q = out.q
        else:
            q = np.clip(q0, self.robot.lower, self.robot.upper)
        self.consider(q[None])

    def local_starts(self, Q0: np.ndarray, patient: bool = False) -> bool:
        """Compiled Levenberg-Marquardt from the rows of ``Q0`` in turn, until
        :attr:`wanted` distinct solutions are known; whether it found any new one.
        ``patient``: no start is abandoned for slow progress (a start near a solution).
        The rows of ``Q0`` are overwritten by the ends (pass a copy to keep them).
        Each converged end is re-checked by an FK pass of its own in the same compiled
        call (:func:`~moik.solver.starts.run_starts`), as :meth:`consider` does; with a
        collision check, an exact end in collision is rejected too (the loop goes on with
        the next start; :func:`~moik.solver.tested_starts.run_collision_starts`), counted in
        :attr:`n_rejected`, the farthest from contact kept as :attr:`colliding`."""
        dof, n_known = self.robot.dof, len(self.found)
        starts = kernel_array(Q0)  # overwritten by the ends: the callers' rows are fresh
        found = found_table(self.wanted, dof, self.found, self.found_errors)
        best = np.empty(dof + 1)
        best[0] = np.inf if self.best is None else self.best[0]
        ends = np.empty((len(starts), 3))
        policy = (CHECK | (PATIENT if patient else 0), max(self.max_evals - self.n_eval, 1))
        if self.guard is None or self.guard.checker.n_pairs == 0:
            n_found, n_eval, used = run_starts(self.ctx, starts, policy, found, best, ends)
        else:
            n_found, n_eval, used = run_collision_starts(
                self.ctx, self.collision_context, self.guard.checker.compiled,
                self.guard.clearance, starts, policy, found, best, ends)
        self.n_eval += int(n_eval)
        for row in found[n_known:n_found]:
            self.found.append(row[:dof])
            self.found_errors.append((float(row[dof]), float(row[dof + 1])))
        if self.best is None or best[0] < self.best[0]:
            self.best = (float(best[0]), best[1:])
        if self.guard is not None:  # exact ends the start loop rejected for collision
            d = ends[:used, 2]  # NaN: an end that was not tested (it failed the pose test)
            rejected = np.flatnonzero(~np.isnan(d) & ~self.guard.keeps(d))
            self.n_rejected += len(rejected)
            if len(rejected):
                k = rejected[np.argmax(d[rejected])]
                if self.colliding is None or d[k] > self.colliding[0]:
                    self.colliding = (float(d[k]), starts[k].copy())
        return len(self.found) > n_known

    def collision_context(self) -> Any:
        """The solve's context with the guard's collision set (built at the first call)."""
        if self._collision_ctx is None:
            assert self.guard is not None
            self._collision_ctx = ik_context(
                self.robot, self.target, stop=self.tol.stop, tol=self.tol,
                distinct=self.distinct, collision=self.guard.checker.compiled,
                clearance=self.guard.clearance)
        return self._collision_ctx

    def _collision_free(self, Q: np.ndarray) -> np.ndarray:
        """Which exact answers keep the clearance; the others are counted, the farthest
        from contact kept as :attr:`colliding`."""
        assert self.guard is not None
        d = self.guard.distances(Q)
        ok = self.guard.keeps(d)
        for k in np.flatnonzero(~ok):
            self.n_rejected += 1
            if self.colliding is None or d[k] > self.colliding[0]:
                self.colliding = (float(d[k]), Q[k].copy())
        return ok

    def consider(self, Q: np.ndarray) -> None:
        """Check candidates with the reference FK; keep the distinct solutions and the best."""
        pos, ori = pose_errors(self.robot, self.target, Q)
        for q, p, o in zip(Q, pos, ori, strict=True):
            err = float(p) / self.robot.reach + float(o)
            if self.best is None or err < self.best[0]:
                self.best = (err, q)
            if (len(self.found) < self.wanted and self.tol.certifies(p, o)
                    and is_distinct(self.robot, q, self.found, self.distinct)
                    and (self.guard is None or self._collision_free(q[None])[0])):
                self.found.append(q)
                self.found_errors.append((float(p), float(o)))
