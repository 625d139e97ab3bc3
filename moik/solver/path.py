"""``solve_path``: a sequence of targets solved with continuity.

Each target is first refined from the previous solution (a warm start keeps
the arm on the same branch); only if that fails, or the step would exceed
``max_step``, is the target solved globally with :func:`moik.solver.solve_ik`,
preferring the solution nearest the previous configuration. The largest joint
step along the path is reported, so a branch jump cannot pass unnoticed.

Without ``q_start`` the first target's branch is a choice: up to
``first_branches`` distinct solutions of it are found and the one from which
warm starts track the path furthest is kept (a branch that runs into a joint
limit half way would force a jump later).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from moik._validate import integer, keywords, positive
from moik.exceptions import ParameterError, TargetError
from moik.kinematics.tolerance import Tolerance
from moik.problems.targets import as_target, check_unit_range
from moik.robots.chain import Robot
from moik.solver import parallel
from moik.solver.collision import CollisionGuard, collision_guard
from moik.solver.options import SEARCH_DEFAULTS, SearchOptions, seed_sequence
from moik.solver.polish import polish
from moik.solver.session import pose_errors
from moik.solver.solve_ik import solve_ik

PASSED_OPTIONS = tuple(name for name in SEARCH_DEFAULTS if name != "n_solutions")


@dataclass(frozen=True)
class PathResult:
    """Outcome of :func:`solve_path`.

    Attributes:
        Q: Joint vectors ``(n, dof)``, all within the limits.
        position_errors: ``(n,)`` recomputed by FK (robot unit).
        orientation_errors: ``(n,)`` geodesic, rad (0 for position targets).
        success: ``(n,)`` both errors within tolerance.
        statuses: Per target ``"solved"``, ``"unreachable"``, ``"not-converged"`` or
            (with a collision check) ``"collides"``.
        warm_started: ``(n,)`` whether the warm start alone solved the target.
        joint_steps: ``(n - 1,)`` largest absolute joint change between neighbours.
        max_joint_step: ``joint_steps.max()`` (0 for a single target).
        n_eval: FK evaluations in total.
        time: Wall time in seconds.
        min_distances: With a collision check, ``(n,)`` smallest signed distance of each
            row of ``Q`` (recomputed at the end; ``success`` requires the clearance);
            ``None`` without one.
    """

    Q: np.ndarray
    position_errors: np.ndarray
    orientation_errors: np.ndarray
    success: np.ndarray
    statuses: tuple[str, ...]
    warm_started: np.ndarray
    joint_steps: np.ndarray
    max_joint_step: float
    n_eval: int
    time: float
    min_distances: np.ndarray | None = None


def solve_path(robot: Robot, targets, *, q_start=None, max_step: float | None = None,
               seed=0, tol=1e-9, first_branches: int = 4, scene=None,
               self_collision: bool = False, clearance: float = 0.0, collision=None,
               **solve_options) -> PathResult:
    """Solve a sequence of targets keeping the arm on one branch.

    Args:
        robot: The arm.
        targets: Sequence of targets (anything :func:`moik.problems.as_target` takes).
        q_start: Configuration before the first target (warm start and
            nearest-solution preference for it).
        max_step: Largest acceptable change of any joint between neighbouring
            targets; a warm-started solution beyond it is re-solved globally.
        seed: Base seed; target ``i`` uses ``SeedSequence(seed).spawn`` child ``i``.
        tol: As in :func:`moik.solver.solve_ik`.
        first_branches: Without ``q_start``: distinct solutions of the first
            target tried as the path's branch (1: take the first found).
        scene, self_collision, clearance, collision: The collision check of
            :func:`moik.solver.solve_ik` at every waypoint: a warm start whose end
            collides is not taken (the waypoint is solved globally, collision-aware).
        **solve_options: Passed to :func:`moik.solver.solve_ik` (not ``seed``,
            ``q_current``, ``n_solutions``).

    Every argument, ``solve_options`` included, is validated before the first
    target is solved (warm starts alone may never call ``solve_ik``).

    Raises:
        ParameterError: A bad value or an unknown option (the accepted ones listed).
        UnknownNameError: An unknown algorithm or orientation metric.
    """
    t0 = time.perf_counter()
    if isinstance(targets, str | bytes | dict) or not hasattr(targets, "__iter__"):
        raise TargetError(f"targets must be a sequence of targets (positions, poses or "
                          f"Targets), got {type(targets).__name__}")
    targets = [as_target(t) for t in targets]
    if not targets:
        raise ParameterError("targets must hold at least one target")
    for target in targets:
        check_unit_range(target, robot)
    for key in ("seed", "q_current", "n_solutions"):
        if key in solve_options:
            raise ParameterError(f"solve_path sets {key!r} itself; do not pass it")
    keywords("solve_path", solve_options, PASSED_OPTIONS)
    SearchOptions(**{**SEARCH_DEFAULTS, **solve_options})  # validated before any solve
    max_step = None if max_step is None else positive("max_step", max_step)
    first_branches = integer("first_branches", first_branches, minimum=1)
    tolerance = Tolerance.of(tol, robot.reach)
    guard = collision_guard(robot, scene=scene, self_collision=self_collision,
                            clearance=clearance, collision=collision)
    if guard is not None:
        solve_options = {**solve_options, "collision": guard.checker,
                         "clearance": guard.clearance}
    prev = None if q_start is None else robot.check_q(q_start, "q_start")
    seeds = seed_sequence(seed).spawn(len(targets))
    Q: list[np.ndarray] = []
    statuses: list[str] = []
    warm_flags: list[bool] = []
    n_eval = 0
    warm = _WarmStart(robot, tolerance, max_step, guard)
    tracked: list[np.ndarray] = []  # warm-start solutions already found by the branch choice
    for i, target in enumerate(targets):
        q, status, used_warm = None, None, False
        if prev is not None:
            q = tracked[i - 1] if 1 <= i <= len(tracked) else warm.step(target, prev)
            status, used_warm = ("solved", True) if q is not None else (None, False)
        elif first_branches > 1 and len(targets) > 1:
            first = solve_ik(robot, target, seed=seeds[i], tol=tol, n_solutions=first_branches,
                             **{"patience": 5, **solve_options})
            n_eval += first.n_eval
            if first.success:
                q, tracked = warm.furthest(first.solutions, targets[1:])
                status = "solved"
        if q is None:
            res = solve_ik(robot, target, q_current=prev, seed=seeds[i], tol=tol,
                           **solve_options)
            n_eval += res.n_eval
            q, status = res.q, res.status
        assert status is not None  # set by the warm start or by solve_ik
        Q.append(q)
        statuses.append(status)
        warm_flags.append(used_warm)
        prev = q
    Q_path = np.array(Q)
    pos_err, ori_err = pose_errors_all(robot, targets, Q_path)
    steps = (np.max(np.abs(np.diff(Q_path, axis=0)), axis=1) if len(Q_path) > 1
             else np.zeros(0))
    dists = None if guard is None else guard.distances(Q_path)
    success = tolerance.certifies(pos_err, ori_err)
    if dists is not None:
        success &= guard.keeps(dists)  # type: ignore[union-attr]
    return PathResult(Q=Q_path, position_errors=pos_err, orientation_errors=ori_err,
                      success=success, min_distances=dists,
                      statuses=tuple(statuses), warm_started=np.array(warm_flags),
                      joint_steps=steps, max_joint_step=float(steps.max()) if steps.size else 0.0,
                      n_eval=n_eval + warm.n_eval, time=time.perf_counter() - t0)


class _WarmStart:
    """Warm-started refinement from a neighbour's solution, with its FK count."""

    def __init__(self, robot: Robot, tol: Tolerance, max_step: float | None,
                 guard: CollisionGuard | None = None):
        self.robot, self.tol, self.max_step = robot, tol, max_step
        self.guard = guard
        self.n_eval = 0

    def step(self, target, prev: np.ndarray) -> np.ndarray | None:
        """The refined solution of ``target`` from ``prev``, or None if it misses
        the tolerance or moves a joint by more than ``max_step``."""
        out = polish(self.robot, target, prev, length=self.robot.reach,
                     stop_position=self.tol.polish_stop[0],
                     stop_orientation=self.tol.polish_stop[1])
        self.n_eval += out.n_eval
        pos, ori = (float(v[0]) for v in pose_errors(self.robot, target, out.q))
        step = float(np.max(np.abs(out.q - prev)))
        ok = self.tol.certifies(pos, ori)
        if ok and self.guard is not None:
            ok = bool(self.guard.free(out.q)[0])
        return out.q if ok and (self.max_step is None or step <= self.max_step) else None

    def furthest(self, candidates: np.ndarray, rest: list) -> tuple[np.ndarray, list]:
        """The candidate from which warm starts track ``rest`` furthest (first on ties),
        and the solutions those warm starts found."""
        best, best_track = candidates[0], None
        for q0 in candidates:
            track, prev = [], q0
            for target in rest:
                prev = self.step(target, prev)
                if prev is None:
                    break
                track.append(prev)
            if best_track is None or len(track) > len(best_track):
                best, best_track = q0, track
            if len(track) == len(rest):
                break
        return best, best_track if best_track is not None else []


def pose_errors_all(robot: Robot, targets, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Errors of ``Q[i]`` w.r.t. ``targets[i]``, recomputed by FK."""
    errs = [pose_errors(robot, t, q) for t, q in zip(targets, Q, strict=True)]
    return (np.array([e[0][0] for e in errs]), np.array([e[1][0] for e in errs]))


def solve_paths(robot: Robot, paths, *, workers: int | None = None,
                **path_options) -> list[PathResult]:
    """:func:`solve_path` of each of ``paths``, on a process pool of ``workers`` processes.

    Path ``k``'s result is ``solve_path(robot, paths[k], **path_options)`` bit for bit (its
    ``time`` aside), whatever ``workers`` is: each path is solved from its own targets and
    the same options and seed.

    Args:
        robot: The arm.
        paths: A sequence of paths, each a sequence of targets.
        workers: Processes (default ``None``: every core this process may run on; a
            single path, or one worker, runs in this process).
        **path_options: The keywords of :func:`solve_path`.

    Raises:
        ParameterError, TargetError: As :func:`solve_path`, for the first path that has
            one; a bad ``workers``; ``paths`` not a sequence of paths.
    """
    n_workers = parallel.worker_count(workers)
    if isinstance(paths, str | bytes | dict) or not hasattr(paths, "__len__"):
        raise TargetError(f"paths must be a sequence of paths, got {type(paths).__name__}")
    return parallel.map_processes(_one_path, (robot, list(paths), path_options),
                                  range(len(paths)), n_workers)


def _one_path(shared, k: int) -> PathResult:
    robot, paths, options = shared
    return solve_path(robot, paths[k], **options)
