"""Bookkeeping of one :func:`moik.solver.solve_ik` call: tolerances, found solutions.

Every candidate, from any stage (batched Levenberg-Marquardt, least-squares
polish, search), goes through :meth:`SolveSession.consider`, which recomputes
its errors with the reference FK (:func:`pose_errors`, the honest re-check)
and keeps it only if it is within tolerance and distinct from the solutions
already found.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit, kernel_array
from moik._validate import positive
from moik.exceptions import ParameterError
from moik.kinematics.rotation_metrics import geodesic_angle
from moik.problems.targets import Target
from moik.robots.chain import Robot, fk_reference
from moik.solver.collision import CollisionGuard
from moik.solver.context import ik_context
from moik.solver.polish import polish as polish_q
from moik.solver.starts import CHECK, PATIENT, found_table, is_distinct, run_starts

LM_ITERATIONS = 30  # Levenberg-Marquardt iterations per start of the first attempt
STOP_FRACTION = 0.1  # a start stops at this fraction of the tolerances (margin for the re-check)
MIN_TOL = 1e-14  # smallest tolerance (relative to reach; rad): ~45 eps, above FK's rounding


def tolerances(tol, robot: Robot) -> tuple[float, float]:
    """``(position, orientation)`` tolerances from ``solve_ik``'s ``tol``.

    A number ``t`` means ``t * robot.reach`` and ``t`` rad; a pair is taken as is.
    Each must be a finite number, at least :data:`MIN_TOL` (times ``robot.reach`` for a
    position): float64 FK computes a pose to a few ``eps * reach`` (``eps`` = 2.2e-16,
    times the number of joints), so a smaller tolerance could not be certified by the
    re-check, and a reachable pose would be called unreachable.

    Raises:
        ParameterError: Anything else, naming what was given and the smallest accepted value.
    """
    if type(tol) is float and MIN_TOL <= tol < np.inf:  # the usual case, checked as below
        return tol * robot.reach, tol
    if isinstance(tol, np.ndarray) and tol.ndim == 0:
        tol = tol.item()
    try:
        shape = np.shape(tol)
    except ValueError:  # ragged sequences
        shape = None
    if shape == ():
        t = _at_least("tol", tol, MIN_TOL, "")
        return t * robot.reach, t
    if shape == (2,):
        return (_at_least("tol[0] (position tolerance)", tol[0], MIN_TOL * robot.reach,
                          f" ({MIN_TOL:g} x reach {robot.reach:g})"),
                _at_least("tol[1] (orientation tolerance)", tol[1], MIN_TOL, " rad"))
    raise ParameterError(f"tol must be a number or (position, orientation), got {tol!r}")


def _at_least(name: str, value, smallest: float, unit: str) -> float:
    value = positive(name, value)
    if value < smallest:
        raise ParameterError(f"{name} must be at least {smallest:g}{unit}, the smallest "
                             f"tolerance float64 forward kinematics can certify, got {value!r}")
    return value


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
        tol_pos, tol_ori: Tolerances (robot unit, rad).
        distinct: Joint-space distance above which two solutions are distinct.
        wanted: Number of solutions asked for; no more are kept.
        max_evals: FK evaluation budget (the first stage starts no start past it).
        guard: The collision test (:mod:`moik.solver.collision`): an exact answer that
            fails it is not a solution (reject-and-restart), the farthest from contact
            is kept as :attr:`colliding`.
    """

    def __init__(self, robot, target, tol_pos, tol_ori, distinct, wanted,
                 max_evals: int = 2**62, guard: CollisionGuard | None = None):
        self.robot, self.target = robot, target
        self.tol_pos, self.tol_ori, self.distinct = tol_pos, tol_ori, distinct
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
        self.ctx = ik_context(robot, target, stop=(STOP_FRACTION * tol_pos,
                                                   STOP_FRACTION * tol_ori),
                              tol=(tol_pos, tol_ori), distinct=distinct,
                              max_iter=LM_ITERATIONS,
                              collision=None if guard is None else guard.checker.compiled,
                              clearance=0.0 if guard is None else guard.clearance)

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

    def local_starts(self, Q0: np.ndarray, patient: bool = False) -> bool:
        """Compiled Levenberg-Marquardt from the rows of ``Q0`` in turn, until
        :attr:`wanted` distinct solutions are known; whether it found any new one.
        ``patient``: no start is abandoned for slow progress (a start near a solution).
        The rows of ``Q0`` are overwritten by the ends (pass a copy to keep them).
        Each converged end is re-checked by an FK pass of its own in the same compiled
        call (:func:`~moik.solver.starts.run_starts`), as :meth:`consider` does; with a
        collision check, an exact end in collision is rejected there too (the loop goes on
        with the next start), counted in :attr:`n_rejected`, the farthest from contact kept
        as :attr:`colliding`."""
        dof, n_known = self.robot.dof, len(self.found)
        starts = kernel_array(Q0)  # overwritten by the ends: the callers' rows are fresh
        found = found_table(self.wanted, dof, self.found, self.found_errors)
        best = np.empty(dof + 1)
        best[0] = np.inf if self.best is None else self.best[0]
        ends = np.empty((len(starts), 3))
        policy = (CHECK | (PATIENT if patient else 0), max(self.max_evals - self.n_eval, 1))
        n_found, n_eval, used = run_starts(self.ctx, starts, policy, found, best, ends)
        self.n_eval += int(n_eval)
        for row in found[n_known:n_found]:
            self.found.append(row[:dof])
            self.found_errors.append((float(row[dof]), float(row[dof + 1])))
        if self.best is None or best[0] < self.best[0]:
            self.best = (float(best[0]), best[1:])
        if self.guard is not None:  # exact ends the start loop rejected for collision
            d = ends[:used, 2]
            rejected = np.flatnonzero(d < self.guard.clearance)
            self.n_rejected += len(rejected)
            if len(rejected):
                k = rejected[np.argmax(d[rejected])]
                if self.colliding is None or d[k] > self.colliding[0]:
                    self.colliding = (float(d[k]), starts[k].copy())
        return len(self.found) > n_known

    def _collision_free(self, Q: np.ndarray) -> np.ndarray:
        """Which exact answers keep the clearance; the others are counted, the farthest
        from contact kept as :attr:`colliding`."""
        assert self.guard is not None
        d = self.guard.distances(Q)
        ok = d >= self.guard.clearance
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
            if (len(self.found) < self.wanted and p <= self.tol_pos and o <= self.tol_ori
                    and is_distinct(self.robot, q, self.found, self.distinct)
                    and (self.guard is None or self._collision_free(q[None])[0])):
                self.found.append(q)
                self.found_errors.append((float(p), float(o)))
