"""``solve_ik_batch``: many targets in one call, each answered as ``solve_ik`` would.

Target ``i`` is solved with its own seed, ``SeedSequence(seed).spawn(n)[i]``
(``SeedSequence(entropy, spawn_key=(i,))``), so its answer depends on ``seed``
and ``i`` only, never on the other targets of the batch: ``solve_ik_batch(robot,
T, seed=s).q[i]`` equals ``solve_ik(robot, T[i], seed=child_i).q`` bit for bit
(tested). The first stage of every target runs in one compiled loop
(:func:`~moik.solver.starts.run_batch`: the same Levenberg-Marquardt starts
``solve_ik`` makes, in the same order); a target it leaves unsolved goes through the whole of
:func:`~moik.solver.solve_ik.solve_ik` (search fallback, front, verdict). Rows ``lo .. hi - 1``
of a batch need only the seeds ``lo .. hi - 1`` (:class:`BatchJob`), so the batch is solved
in chunks, on threads and processes or on a Dask cluster (:mod:`moik.solver.parallel`),
with the answers of the serial run.
"""

from __future__ import annotations

import contextlib
import copy
import dataclasses
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from moik._jit import kernel_array
from moik._validate import optional_callable
from moik.collision.compiled import collision_set
from moik.exceptions import ParameterError, ShapeError
from moik.kinematics.criteria import nearest_copies
from moik.kinematics.tolerance import Tolerance
from moik.problems.targets import Target, batch_targets, check_batch_reach
from moik.robots.catalog import as_robot
from moik.robots.chain import Robot
from moik.solver import parallel
from moik.solver.collision import CollisionGuard, collision_guard
from moik.solver.context import ik_context
from moik.solver.options import STARTS_KEY, search_options, seed_sequence
from moik.solver.session import pose_errors
from moik.solver.solve_ik import FIRST_STARTS, STATUSES, solve_ik
from moik.solver.start_streams import draw_rows, start_streams, streams_match
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
            ``q``; ``None`` without one. Each answer's clearance is re-checked at the end
            of the call (the verdict); the exact distances of the answers that keep it
            (a full measure of every pair, most of a mesh arm's cost) are computed at the
            first read of this attribute, once.
        distances: The record behind :attr:`min_distance` (:class:`BatchDistances`).
        unchecked_links: With a collision check, the arm's links without geometry, not
            checked (as :attr:`IKResult.unchecked_links <moik.solver.result.IKResult>`).
    """

    q: np.ndarray
    status: np.ndarray
    position_error: np.ndarray
    orientation_error: np.ndarray
    success: np.ndarray
    n_eval: np.ndarray
    time: float
    distances: BatchDistances | None = field(default=None, repr=False, compare=False)

    @property
    def min_distance(self) -> np.ndarray | None:
        """See the class docstring (``None`` without a collision check)."""
        return None if self.distances is None else self.distances.values()

    @property
    def unchecked_links(self) -> tuple[str, ...]:
        """See the class docstring (empty without a collision check)."""
        return () if self.distances is None else self.distances.unchecked_links


class BatchDistances:
    """The smallest signed distance of each answer of a batch, exact at the first read.

    ``known`` rows hold exact values (the hard tail's, from ``solve_ik``, and the answers
    below the clearance); the others hold what the clearance test measured (a number at
    least the clearance, :func:`~moik.collision.kernels.distance_below`) until
    :meth:`values` measures them in full (:meth:`CollisionGuard.distances`).
    """

    def __init__(self, guard: CollisionGuard, q: np.ndarray, values: np.ndarray,
                 known: np.ndarray) -> None:
        self._guard, self._q, self._values, self._known = guard, q, values, known
        self.unchecked_links = guard.checker.model.unchecked_links

    def values(self) -> np.ndarray:
        """``(n,)`` exact smallest signed distances (measured once)."""
        rows = np.flatnonzero(~self._known)
        if len(rows):
            self._values[rows] = self._guard.distances(self._q[rows])
            self._known[rows] = True
        return self._values


def child_seeds(seed, n: int) -> list[np.random.SeedSequence]:
    """The per-target seeds: ``SeedSequence(seed).spawn(n)`` (without spawning from ``seed``)."""
    root = seed_sequence(seed)
    return [_child(root, i) for i in range(n)]


def _child(root: np.random.SeedSequence, i: int) -> np.random.SeedSequence:
    """Target ``i``'s seed (``child_seeds(root, n)[i]``)."""
    return np.random.SeedSequence(root.entropy, spawn_key=(*root.spawn_key, i),
                                  pool_size=root.pool_size)


def solve_ik_batch(robot, targets, *, seed=0, q_current=None, tol=1e-9, scene=None,
                   self_collision: bool = False, clearance: float = 0.0, collision=None,
                   workers: int | None = None, client=None,
                   progress: Callable[[int], None] | None = None,
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
        workers: CPUs to use (default ``None``: every core this process may run on). The
            compiled first stage runs on that many threads over chunks of targets (it
            releases the GIL), the hard tail on a process pool of that many (at most one
            process per CPU this process may run on); a batch too
            small for it to pay runs in this thread. The answers are the same bit for bit
            for every value: each depends on its target and its own seed only. Inside a
            process pool of your own, pass ``workers=1`` (your pool already uses the cores).
        client: A ``dask.distributed.Client``: the batch is cut into chunks, each solved
            on a worker of its cluster (``workers`` is then not used) and gathered in order;
            the same answers again. A chunk whose worker is lost is run again.
        progress: Called with a number of targets each time that many are answered
            (the first stage's solved targets chunk by chunk, then each target of the
            hard tail); the numbers add up to ``n``, or slightly more when the final
            re-check sends a first-stage answer on to the tail.
        **options: Any other keyword of ``solve_ik`` except ``n_solutions``.

    Raises:
        ShapeError, NonFiniteError, TargetError: Malformed targets (empty batch,
            wrong shape, NaN, non-rotations) or ``q_current``.
        ParameterError, UnknownNameError: As ``solve_ik`` for its options, or a bad
            ``workers``, ``client`` or ``progress``.
    """
    t0 = time.perf_counter()
    robot = as_robot(robot)
    if "n_solutions" in options:
        raise ParameterError("solve_ik_batch returns one joint vector per target: n_solutions "
                             "is not an option here (call solve_ik per target for branches)")
    search_options("solve_ik_batch", options)
    n_workers = parallel.worker_count(workers)
    optional_callable("progress", progress)
    collision_args = {"scene": scene, "self_collision": self_collision, "clearance": clearance,
                      "collision": collision}
    guard = collision_guard(robot, **collision_args)  # validated before the targets
    Tolerance.of(tol, robot.reach)
    positions, rotations = batch_targets(targets)
    check_batch_reach(robot, positions)
    n = len(positions)
    qc = None
    if q_current is not None:
        qc = robot.check_q(q_current, "q_current")
        if qc.ndim == 1:
            qc = np.tile(qc, (n, 1))
        elif qc.shape[0] != n:
            raise ShapeError(f"q_current must be ({robot.dof},) or ({n}, {robot.dof}), got "
                             f"{qc.shape}")
    job = BatchJob(robot=robot, positions=positions, rotations=rotations, q_current=qc,
                   root=seed_sequence(seed), first=0, tol=tol, collision=_portable(guard),
                   options=options)
    if client is not None:
        rows = _on_client(parallel.check_client(client), job, progress)
    else:
        rows = solve_rows(job, workers=n_workers, progress=progress)
    q, status, pos, ori, success, n_evals, dist, known = rows
    return IKBatchResult(q=q, status=status_names(status), position_error=pos,
                         orientation_error=ori, success=success, n_eval=n_evals,
                         time=time.perf_counter() - t0,
                         distances=None if guard is None else BatchDistances(guard, q, dist,
                                                                              known))


@dataclass(frozen=True, kw_only=True)
class BatchJob:
    """Validated targets ``first .. first + n - 1`` of a batch and how to solve them (picklable:
    a chunk travels to a process or a Dask worker as one of these)."""

    robot: Robot
    positions: np.ndarray
    rotations: np.ndarray | None
    q_current: np.ndarray | None
    root: np.random.SeedSequence
    first: int
    tol: Any
    collision: dict[str, Any]
    options: dict[str, Any]

    def rows(self, lo: int, hi: int) -> BatchJob:
        """The job of this job's rows ``lo .. hi - 1``."""
        return dataclasses.replace(
            self, positions=self.positions[lo:hi],
            rotations=None if self.rotations is None else self.rotations[lo:hi],
            q_current=None if self.q_current is None else self.q_current[lo:hi],
            first=self.first + lo)


def _portable(guard) -> dict[str, Any]:
    """The collision arguments that rebuild ``guard``'s check in another process (a checker's
    compiled pairs do not pickle; its model, scene and self-pair flag do, and give the
    same checker)."""
    if guard is None:
        return {}
    checker = guard.checker
    return {"scene": checker.scene, "self_collision": checker.self_collision,
            "collision": checker.model, "clearance": guard.clearance}


Rows = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray,
             np.ndarray]


def _on_client(client, job: BatchJob, progress) -> Rows:
    """The job's rows solved in chunks on a Dask ``client``, gathered in order."""
    n = len(job.positions)
    bounds = parallel.chunk_bounds(n, parallel.client_workers(client))
    done = None if progress is None else (lambda rows: progress(len(rows[0])))
    parts = parallel.map_client(client, _solve_chunk, [job.rows(lo, hi) for lo, hi in bounds],
                                progress=done)
    return tuple(np.concatenate([part[k] for part in parts])  # type: ignore[return-value]
                 for k in range(8))


def _solve_chunk(job: BatchJob) -> Rows:
    """A Dask task: one chunk on one thread of its worker."""
    return solve_rows(job, workers=1)


TAIL_HERE_MAX_WORKERS = 3
"""Up to this many workers, this thread solves each ended chunk's hard tail while the other
chunks run (one core's worth more of the batch's work: faster at 2 workers with a
collision check, docs/batch.md); with more, its Python would hold the GIL that every chunk
thread needs back from each compiled call (each waits up to the interpreter's switch
interval), and the tail goes to processes instead: with a collision check (a tail is
expected: targets whose every start ends in collision) to a
:class:`~moik.solver.parallel.TaskPool` started before the chunks, chunk by chunk as they
end; else after the chunks (:func:`~moik.solver.parallel.map_processes`)."""


def solve_rows(job: BatchJob, *, workers: int = 1, progress=None) -> Rows:
    """The answers of the job's targets (seeds ``first + i``): ``(q, status code (an index of
    :data:`~moik.solver.solve_ik.STATUSES`), position error,
    orientation error, success, n_eval, min distance, whether that distance is exact)``, the
    first stage on ``workers`` threads, the hard tail on as many processes (or, up to
    :data:`TAIL_HERE_MAX_WORKERS`, the tail of a chunk that has ended in this thread while
    other chunks still run). A first-stage
    answer's distance is its clearance test's (:meth:`CollisionGuard.below`: exact below
    the clearance, else a number at least it); :class:`BatchDistances` completes them."""
    robot, n = job.robot, len(job.positions)
    opts = search_options("solve_ik_batch", job.options)
    guard = collision_guard(robot, **job.collision)
    tolerance = Tolerance.of(job.tol, robot.reach)
    positions, rotations, qc = job.positions, job.rotations, job.q_current
    out_Q, solved = np.empty((n, robot.dof)), np.zeros(n, dtype=np.bool_)
    n_evals = np.zeros(n, dtype=np.int64)
    pos, ori, dist = np.zeros(n), np.zeros(n), np.full(n, np.nan)
    known = np.zeros(n, dtype=np.bool_)  # rows whose distance is exact (the tail's)
    status = np.full(n, STATUSES.index("not-converged"), dtype=np.int8)  # (status_names)
    early: dict[int, tuple] = {}  # tail answers found while chunks still ran
    chunked = workers > 1 and n > parallel.MIN_CHUNK and opts.polish and (
        qc is not None or opts.starts)
    here = workers <= TAIL_HERE_MAX_WORKERS  # the tail beside the chunks in this thread
    pool = (parallel.TaskPool(_tail_target, job, workers, n)  # before the chunks' threads
            if chunked and not here and guard is not None and parallel.can_fork() else None)

    def settle(lo: int, hi: int, busy) -> None:  # this thread, as each chunk ends
        k = lo + np.flatnonzero(solved[lo:hi])
        if len(k):  # the honest re-check, as solve_ik does it
            p_k, o_k = pose_errors(robot, (positions[k], None if rotations is None
                                           else rotations[k]), out_Q[k])
            ok = tolerance.certifies(p_k, o_k)
            if guard is not None:  # each q's clearance, tested again by its chunk's thread
                ok &= guard.keeps(dist[k])
            pos[k], ori[k], solved[k] = p_k, o_k, ok
            status[k[ok]] = STATUSES.index("solved")
        if pool is not None:  # its tail, to the processes, beside the chunks left
            pool.submit(map(int, lo + np.flatnonzero(~solved[lo:hi])))
            return
        for i in lo + np.flatnonzero(~solved[lo:hi]):  # its tail, beside the chunks left
            if not (here and busy()):
                break
            early[int(i)] = _tail_target(job, int(i))

    with pool or contextlib.nullcontext():
        if opts.polish and (qc is not None or opts.starts):
            # once for every chunk (Python that would hold the GIL once per chunk)
            common = (Target(positions[0], None if rotations is None else rotations[0]),
                      streams_match(job.root, STARTS_KEY, job.first))

            def chunk(lo: int, hi: int) -> None:  # a thread's rows: compiled calls, no GIL
                own = None if guard is None else _own_guard(guard)
                _first_stage(robot, (positions[lo:hi], None if rotations is None
                                     else rotations[lo:hi]), None if qc is None else qc[lo:hi],
                             opts, tolerance, (job.root, job.first + lo, common), own,
                             (out_Q[lo:hi], solved[lo:hi], n_evals[lo:hi]))
                done = lo + np.flatnonzero(solved[lo:hi])
                if qc is not None and len(done):
                    out_Q[done] = nearest_copies(robot, out_Q[done], qc[done])
                if own is not None and len(done):  # the re-check's clearance test (below)
                    dist[done] = own.below(out_Q[done])
                if progress is not None:
                    progress(len(done))

            parallel.map_chunks(chunk, n, workers, then=settle)
        if pool is not None:
            early = pool.results()
    tail = np.flatnonzero(~solved)  # the hard tail: the whole of solve_ik
    rest = [int(i) for i in tail if i not in early]
    answers = dict(zip(rest, parallel.map_processes(_tail_target, job, rest, workers),
                       strict=True))
    for i in map(int, tail):
        q, st, p, o, ne, ok, d = early[i] if i in early else answers[i]
        out_Q[i], status[i], pos[i], ori[i], n_evals[i], solved[i], dist[i] = \
            q, STATUSES.index(st), p, o, ne, ok, d
    known[tail] = True
    if progress is not None and len(tail):
        progress(len(tail))
    return out_Q, status, pos, ori, solved, n_evals, dist, known


def status_names(codes: np.ndarray) -> np.ndarray:
    """The statuses of codes (indices of :data:`~moik.solver.solve_ik.STATUSES`), as a
    string array as wide as its longest (numpy's ``astype(str)`` of the names; a string per
    row would be Python work per target)."""
    present = np.flatnonzero(np.bincount(codes, minlength=len(STATUSES)))
    width = max(len(STATUSES[c]) for c in present) if len(present) else 1
    return np.array(STATUSES, dtype=f"<U{width}")[codes]


def _own_guard(guard: CollisionGuard) -> CollisionGuard:
    """``guard`` with compiled pairs of its own (the same arrays, the same distances): threads
    sharing one compiled value would share its reference counts, atomic operations on one
    cache line at every distance they compute."""
    twin = copy.copy(guard.checker)
    twin.__dict__["compiled"] = collision_set(chain=twin.robot.new_chain_model(),
                                              **twin.compiled_arrays)
    return CollisionGuard(twin, guard.clearance)


def _tail_target(job: BatchJob, i: int) -> tuple:
    """Row ``i`` of the job through the whole of ``solve_ik`` (its seed: ``first + i``)."""
    robot = job.robot
    guard = collision_guard(robot, **job.collision)
    check: dict[str, Any] = ({} if guard is None else
                             {"collision": guard.checker, "clearance": guard.clearance})
    target = Target(job.positions[i], None if job.rotations is None else job.rotations[i])
    res = solve_ik(robot, target, seed=_child(job.root, job.first + i), tol=job.tol,
                   q_current=None if job.q_current is None else job.q_current[i], **check,
                   **job.options)
    return (res.q, res.status, res.position_error, res.orientation_error, res.n_eval,
            res.success, np.nan if guard is None else res.min_distance)


def _first_stage(robot, targets, qc, opts, tol, seeds, guard, out):
    """The Levenberg-Marquardt starts ``solve_ik`` makes, for every target in compiled loops
    (:func:`~moik.solver.starts.run_batch`): ``q_current[i]`` (patient), then the first
    :data:`~moik.solver.solve_ik.FIRST_STARTS` random starts, then the rest for the unsolved.
    With a collision ``guard`` an end in collision is rejected inside the loop, as
    ``solve_ik``'s start loop does. ``targets = (positions, rotations)``; ``seeds = (root,
    first, (target, checked))``: row ``i``'s starts are those of child ``first + i`` of
    ``root``; ``target``, any target of the batch (the context's first, replaced row by
    row), and ``checked``, :func:`~moik.solver.start_streams.streams_match` of the batch,
    are the same for every chunk; ``out = (out_Q, solved, n_evals)``, written. Its own
    context: threads run it on chunks."""
    (positions, rotations), (root, first_child, (first, checked)) = targets, seeds
    out_Q, solved, n_evals = out
    n, dof = len(positions), robot.dof
    ctx = ik_context(robot, first, stop=tol.stop, distinct=opts.distinct,
                     chain=robot.new_chain_model(),  # the thread's own (module doc)
                     collision=None if guard is None else guard.checker.compiled,
                     clearance=0.0 if guard is None else guard.clearance)
    targets = (kernel_array(np.tile(np.eye(3), (n, 1, 1)) if rotations is None else rotations),
               kernel_array(positions))
    found = np.full((n, 1, dof + 2), np.nan)
    if qc is not None:
        current = np.array(qc[:, None], dtype=np.float64, copy=True)  # run_batch moves it
        run_batch(ctx, current, targets, (PATIENT, opts.max_evals), found, n_evals)
    states = start_streams(root, STARTS_KEY, n, first_child,  # solve_ik's start generators
                           checked=checked)
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
