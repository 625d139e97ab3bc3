"""``solve_ik_batch``: many targets in one call, each answered as ``solve_ik`` would.

Target ``i`` is solved with its own seed, ``SeedSequence(seed).spawn(n)[i]``
(``SeedSequence(entropy, spawn_key=(i,))``), so its answer depends on ``seed``
and ``i`` only, never on the other targets of the batch: ``solve_ik_batch(robot,
T, seed=s).q[i]`` equals ``solve_ik(robot, T[i], seed=child_i).q`` bit for bit
(tested). The first stage of every target runs in one compiled loop
(:func:`~moik.solver.starts.run_batch`: the same Levenberg-Marquardt starts
``solve_ik`` makes, in the same order); a target it leaves unsolved goes through the whole of
:func:`~moik.solver.solve_ik.solve_ik` (search fallback, front, verdict).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from moik._jit import kernel_array
from moik._validate import finite_array
from moik.exceptions import ParameterError, ShapeError, TargetError
from moik.kinematics.criteria import nearest_copies
from moik.kinematics.orientation import check_rotation
from moik.kinematics.tolerance import Tolerance
from moik.problems.targets import Target
from moik.robots.catalog import as_robot
from moik.solver.collision import collision_guard
from moik.solver.context import ik_context
from moik.solver.options import STARTS_KEY, search_options, seed_sequence
from moik.solver.session import pose_errors
from moik.solver.solve_ik import FIRST_STARTS, solve_ik
from moik.solver.start_streams import draw_rows, start_streams
from moik.solver.starts import PATIENT, run_batch


@dataclass(frozen=True)
class IKBatchResult:
    """Outcome of :func:`solve_ik_batch` (one row per target).

    Attributes:
        q: ``(n, dof)`` joint vectors within the limits (the solution, or the best
            candidate / compromise of an unsolved target).
        status: ``(n,)`` ``"solved"``, ``"unreachable"``, ``"not-converged"`` or (with a
            collision check) ``"collides"``, as :func:`~moik.solver.solve_ik.solve_ik`.
        position_error: ``(n,)`` recomputed by FK (robot unit).
        orientation_error: ``(n,)`` geodesic angle (rad), 0 for position targets.
        success: ``(n,)`` whether each target was solved.
        n_eval: ``(n,)`` FK evaluations spent on each target.
        time: Wall time of the whole call (s).
        min_distance: With a collision check, ``(n,)`` smallest signed distance of each
            ``q`` (recomputed at the end); ``None`` without one.
    """

    q: np.ndarray
    status: np.ndarray
    position_error: np.ndarray
    orientation_error: np.ndarray
    success: np.ndarray
    n_eval: np.ndarray
    time: float
    min_distance: np.ndarray | None = None


def child_seeds(seed, n: int) -> list[np.random.SeedSequence]:
    """The per-target seeds: ``SeedSequence(seed).spawn(n)`` (without spawning from ``seed``)."""
    root = seed_sequence(seed)
    return [_child(root, i) for i in range(n)]


def _child(root: np.random.SeedSequence, i: int) -> np.random.SeedSequence:
    """Target ``i``'s seed (``child_seeds(root, n)[i]``)."""
    return np.random.SeedSequence(root.entropy, spawn_key=(*root.spawn_key, i),
                                  pool_size=root.pool_size)


def _targets(targets) -> tuple[np.ndarray, np.ndarray | None]:
    """Positions ``(n, 3)`` and rotations ``(n, 3, 3)`` (or ``None``) of a batch."""
    arr = finite_array("targets", targets, error=ShapeError)
    if arr.ndim == 3 and arr.shape[1:] == (4, 4):
        if not np.all(np.abs(arr[:, 3] - (0.0, 0.0, 0.0, 1.0)) <= 1e-8):
            bad = int(np.flatnonzero(np.any(np.abs(arr[:, 3] - (0, 0, 0, 1)) > 1e-8, 1))[0])
            raise TargetError(f"targets[{bad}]: pose last row must be [0, 0, 0, 1], got "
                              f"{arr[bad, 3]}")
        positions, rotations = arr[:, :3, 3].copy(), check_rotation(
            np.ascontiguousarray(arr[:, :3, :3]), "target rotations", batch=True)
    elif arr.ndim == 2 and arr.shape[1] == 3:
        positions, rotations = arr, None
    else:
        raise ShapeError(f"targets must have shape (n, 4, 4) (poses) or (n, 3) (positions), "
                         f"got {arr.shape}")
    if len(positions) == 0:
        raise ShapeError("targets is an empty batch: give at least one target")
    return positions, rotations


def solve_ik_batch(robot, targets, *, seed=0, q_current=None, tol=1e-9, scene=None,
                   self_collision: bool = False, clearance: float = 0.0, collision=None,
                   **options) -> IKBatchResult:
    """Solve IK for a batch of targets; each answer independent of the others.

    Args:
        robot: The arm (a Robot or a catalog name).
        targets: Poses ``(n, 4, 4)`` or positions ``(n, 3)`` in the robot's unit.
        seed: Root seed; target ``i`` uses ``child_seeds(seed, n)[i]``.
        q_current: ``None``, one joint vector ``(dof,)`` for every target, or ``(n, dof)``.
        tol: As in :func:`~moik.solver.solve_ik.solve_ik`.
        scene, self_collision, clearance, collision: The collision check of
            :func:`~moik.solver.solve_ik.solve_ik`, per target the same verdict: the
            compiled first stage rejects ends in collision and tries the next start; a
            target it leaves without a collision-free answer goes through the whole of
            ``solve_ik``.
        **options: Any other keyword of ``solve_ik`` except ``n_solutions``.

    Raises:
        ShapeError, NonFiniteError, TargetError: Malformed targets (empty batch,
            wrong shape, NaN, non-rotations) or ``q_current``.
        ParameterError, UnknownNameError: As ``solve_ik`` for its options.
    """
    t0 = time.perf_counter()
    robot = as_robot(robot)
    if "n_solutions" in options:
        raise ParameterError("solve_ik_batch returns one joint vector per target: n_solutions "
                             "is not an option here (call solve_ik per target for branches)")
    opts = search_options("solve_ik_batch", options)
    guard = collision_guard(robot, scene=scene, self_collision=self_collision,
                            clearance=clearance, collision=collision)
    check: dict[str, Any] = ({} if guard is None else
                             {"collision": guard.checker, "clearance": guard.clearance})
    tolerance = Tolerance.of(tol, robot.reach)
    positions, rotations = _targets(targets)
    n = len(positions)
    qc = None
    if q_current is not None:
        qc = robot.check_q(q_current, "q_current")
        if qc.ndim == 1:
            qc = np.tile(qc, (n, 1))
        elif qc.shape[0] != n:
            raise ShapeError(f"q_current must be ({robot.dof},) or ({n}, {robot.dof}), got "
                             f"{qc.shape}")
    root = seed_sequence(seed)  # target i's seed: _child(root, i), made only if needed
    out_Q, solved = np.empty((n, robot.dof)), np.zeros(n, dtype=np.bool_)
    n_evals = np.zeros(n, dtype=np.int64)
    if opts.polish and (qc is not None or opts.starts):
        _first_stage(robot, positions, rotations, qc, opts, tolerance, root,
                     guard, (out_Q, solved, n_evals))
    if qc is not None:
        out_Q[solved] = nearest_copies(robot, out_Q[solved], qc[solved])
    status = np.full(n, "not-converged", dtype=object)
    pos, ori, dist = np.zeros(n), np.zeros(n), np.full(n, np.nan)
    if solved.any():  # the honest re-check, as solve_ik does it
        k = np.flatnonzero(solved)
        p_k, o_k = pose_errors(robot, (positions[k], None if rotations is None
                                       else rotations[k]), out_Q[k])
        ok = tolerance.certifies(p_k, o_k)
        if guard is not None:
            dist[k] = guard.distances(out_Q[k])
            ok &= guard.keeps(dist[k])
        pos[k], ori[k], solved[k] = p_k, o_k, ok
        status[k[ok]] = "solved"
    for i in np.flatnonzero(~solved):  # the hard tail: the whole of solve_ik
        target = Target(positions[i], None if rotations is None else rotations[i])
        res = solve_ik(robot, target, seed=_child(root, int(i)), tol=tol,
                       q_current=None if qc is None else qc[i], **check, **options)
        out_Q[i], status[i], pos[i], ori[i] = res.q, res.status, res.position_error, \
            res.orientation_error
        n_evals[i], solved[i] = res.n_eval, res.success
        if guard is not None:
            dist[i] = res.min_distance
    return IKBatchResult(q=out_Q, status=status.astype(str), position_error=pos,
                         orientation_error=ori, success=solved, n_eval=n_evals,
                         time=time.perf_counter() - t0,
                         min_distance=None if guard is None else dist)


def _first_stage(robot, positions, rotations, qc, opts, tol, root, guard, out):
    """The Levenberg-Marquardt starts ``solve_ik`` makes, for every target in compiled loops
    (:func:`~moik.solver.starts.run_batch`): ``q_current[i]`` (patient), then the first
    :data:`~moik.solver.solve_ik.FIRST_STARTS` random starts, then the rest for the unsolved.
    With a collision ``guard`` an end in collision is rejected inside the loop, as
    ``solve_ik``'s start loop does. ``out = (out_Q, solved, n_evals)``, written."""
    out_Q, solved, n_evals = out
    n, dof = len(positions), robot.dof
    first = Target(positions[0], None if rotations is None else rotations[0])
    ctx = ik_context(robot, first, stop=tol.stop, distinct=opts.distinct,
                     collision=None if guard is None else guard.checker.compiled,
                     clearance=0.0 if guard is None else guard.clearance)
    targets = (kernel_array(np.tile(np.eye(3), (n, 1, 1)) if rotations is None else rotations),
               kernel_array(positions))
    found = np.full((n, 1, dof + 2), np.nan)
    if qc is not None:
        current = np.array(qc[:, None], dtype=np.float64, copy=True)  # run_batch moves it
        run_batch(ctx, current, targets, (PATIENT, opts.max_evals), found, n_evals)
    states = start_streams(root, STARTS_KEY, n)  # solve_ik's start generators, compiled
    first_n = min(opts.starts, FIRST_STARTS)  # then the rest, for the unsolved only
    run_batch(ctx, draw_rows(states, np.arange(n), first_n, robot.lower, robot.upper),
              targets, (0, opts.max_evals), found, n_evals)
    rest = np.flatnonzero(np.isnan(found[:, 0, 0]))
    if opts.starts > first_n and len(rest):
        Q1 = draw_rows(states, rest, opts.starts - first_n, robot.lower, robot.upper)
        found_r, n_r = found[rest], n_evals[rest]
        run_batch(ctx, Q1, (kernel_array(targets[0][rest]), kernel_array(targets[1][rest])),
                  (0, opts.max_evals), found_r, n_r)
        found[rest], n_evals[rest] = found_r, n_r
    solved[:] = ~np.isnan(found[:, 0, 0])
    out_Q[solved] = found[solved, 0, :dof]
