"""``solve_ik``: the practical IK solver (compiled local solver + global search fallback).

First stage: the compiled multi-start Levenberg-Marquardt (:mod:`moik.solver.lm`)
from ``q_current`` and then from seeded random configurations in turn, until
``n_solutions`` distinct solutions (modulo 2 pi) are found; nearly every
reachable pose ends there in well under a millisecond. The hard tail goes on to
the memetic design of BioIK: a registered metaheuristic (EOSMA by default)
searches the joint space with a small population for a few generations; the
best distinct candidates are then refined with bounded least squares and the
analytic Jacobian (:mod:`moik.solver.polish`). Rounds repeat with fresh
derived seeds until enough distinct solutions are found or the budget is spent.

Honesty rules: the returned errors are recomputed by FK (never taken from an
optimizer; the plain-numpy reference FK for unsolved targets); ``q`` is always
within the joint limits. A target is called ``"unreachable"`` either when it
lies beyond the provable reach bound (:mod:`moik.solver.front`: a proof, no
search needed), or when two independent global searches found nothing within
tolerance: the single-objective rounds ran until ``patience`` rounds brought no
progress (not until the budget ran out) and a multi-objective run (MOEOSMA)
whose best member was refined as well; and the best error is more than 1000
tolerances away. The latter is the solver's verdict, not a proof; a near miss,
or a search cut short by ``max_evals``, is ``"not-converged"``. For a pose the
Pareto front of (position error, orientation error) is returned, its ends and
members polished by compiled weighted-sum scalarisations, with its compromise
closest to the utopia point as ``q``.
"""

from __future__ import annotations

import time

import numpy as np
from pymoo.optimize import minimize

from moik._validate import seed as check_seed
from moik.exceptions import ShapeError
from moik.kinematics.tolerance import Tolerance
from moik.problems.ik import BiObjectiveIK, PoseIK, PositionIK
from moik.problems.targets import Target, as_target, check_unit_range
from moik.robots.catalog import as_robot
from moik.robots.chain import Robot
from moik.solver.collision import collision_guard
from moik.solver.front import FRONT_STARTS, polished_front, reach_excess
from moik.solver.options import (
    SEARCH_DEFAULTS,
    SearchOptions,
    algorithm_registry,
    seed_sequence,
    start_generator,
    starts_sequence,
)
from moik.solver.result import IKResult, ik_result
from moik.solver.session import SolveSession
from moik.solver.starts import front as lm_front
from moik.solver.starts import is_distinct

STATUSES = ("solved", "unreachable", "not-converged", "collides")
FINAL_NFEV = 300  # extended refinement of the best candidate before giving up
FIRST_STARTS = 8  # random starts drawn first; the remaining ``starts`` only when needed
FOUND_PATIENCE = 1  # idle search rounds once all starts found some, not all, solutions
BODY_EXTENT = 10.0  # a bound on the last body's geometry's distance from the end effector (x reach)
QUICK_NFEV = 12  # a good start converges in ~5-10 evaluations; a bad one is dropped early


def _search_problem(robot: Robot, target: Target, orientation: str):
    if target.rotation is None:
        return PositionIK(robot, target)
    return PoseIK(robot, target, weights=(1.0 / robot.reach, 1.0), orientation=orientation)


def _population(algorithm) -> tuple[np.ndarray, np.ndarray]:
    """Current candidates (X, F) of a run, for ArrayAlgorithms and pymoo's own."""
    X, F = getattr(algorithm, "X", None), getattr(algorithm, "F", None)
    if isinstance(X, np.ndarray) and isinstance(F, np.ndarray):
        return X, F.reshape(len(X), -1)[:, 0]
    return algorithm.pop.get("X"), algorithm.pop.get("F")[:, 0]


_D = SEARCH_DEFAULTS  # solve_ik's defaults are SearchOptions' field defaults


def solve_ik(robot: Robot, target, *, method: str = _D["method"],
             orientation: str = _D["orientation"], polish: bool = _D["polish"],
             n_solutions: int = _D["n_solutions"], q_current=None, seed=0, tol=1e-9,
             max_evals: int = _D["max_evals"], starts: int = _D["starts"],
             pop_size: int | None = _D["pop_size"], generations: int = _D["generations"],
             candidates_per_round: int = _D["candidates_per_round"],
             distinct: float = _D["distinct"], patience: int = _D["patience"],
             front_method: str = _D["front_method"], front_evals: int = _D["front_evals"],
             scene=None, self_collision: bool = False, clearance: float = 0.0, collision=None
             ) -> IKResult:
    """Solve IK for one target.

    Args:
        robot: The arm (a Robot, or a catalog name such as ``"eosma7"``).
        target: 3-vector position, 4x4 pose, ``(position, rotation)`` or Target.
        method: Registered single-objective algorithm for the global search.
        orientation: Orientation metric of the search objective and of the
            front (reported errors are always geodesic).
        polish: Refine candidates with least squares (else search only).
        n_solutions: Number of distinct solutions wanted.
        q_current: Current configuration: the first start, and the solutions
            are returned nearest to it first, each revolute joint shifted by the
            multiple of 2 pi (within the limits) that brings it nearest to
            ``q_current`` (EOSMA Eq. 31 idea).
        seed: Seed (int or ``numpy.random.SeedSequence``) of every random
            choice: the same seed gives the same result bit for bit. The random
            starts draw from their own stream of it (``options.STARTS_KEY``), not
            the stream ``random_reachable_targets(..., seed=seed)`` draws from.
        tol: Tolerance: a number ``t`` means position <= ``t * robot.reach`` and
            orientation <= ``t`` rad; or a pair (position in robot unit, rad).
        max_evals: FK evaluation budget of the first stage, the search and the
            polish (a started Levenberg-Marquardt run or search round is finished,
            none begins past it); the front of an unsolved pose has its own,
            ``front_evals``.
        starts: Random configurations (seeded) from which the compiled
            Levenberg-Marquardt first stage starts in turn, after ``q_current``,
            until enough solutions are found (0: go straight to the global search).
        pop_size: Search population size (default 20, or 40 when several
            solutions are wanted: a wider population lands in more branches).
        generations: Search generations per round.
        candidates_per_round: Distinct candidates polished per round.
        distinct: Joint-space distance above which two solutions are distinct.
        patience: Stop after this many search rounds without a new solution (at
            most 1 when every start of the first stage ran and found some but not all
            of the ``n_solutions``: hundreds of Levenberg-Marquardt starts rarely miss
            a branch that exists, and the search then rarely adds one).
        front_method: Multi-objective algorithm for the front of unreachable poses.
        front_evals: Evaluation budget of that front: of its multi-objective run, and
            again of its polish by weighted-sum scalarisations (no start begins past
            it), so an unsolved pose spends at most about ``max_evals + 2 *
            front_evals``.

    Every argument is validated before any stage runs (:class:`SearchOptions`),
    whichever stage would end the solve.

    Raises:
        ParameterError: A value out of range or of the wrong kind (integers
            refuse bools and floats such as ``2.0``), or an algorithm of the
            wrong kind for ``method`` / ``front_method``.
        UnknownNameError: An unknown algorithm or orientation metric.
        TargetError, ShapeError, NonFiniteError: A malformed target or ``q_current``.
        GeometryError: A scene or collision geometry of the wrong type or robot.
    """
    t0 = time.perf_counter()
    robot = as_robot(robot)
    target = as_target(target)
    check_unit_range(target, robot)
    tolerance = Tolerance.of(tol, robot.reach)
    opts = SearchOptions.of(method=method, orientation=orientation, polish=polish,
                            n_solutions=n_solutions, max_evals=max_evals, starts=starts,
                            pop_size=pop_size, generations=generations,
                            candidates_per_round=candidates_per_round, distinct=distinct,
                            patience=patience, front_method=front_method,
                            front_evals=front_evals)
    seed = check_seed("seed", seed)
    # an integer seed's SeedSequence is made only if a stage spawns from it
    seeds = None if isinstance(seed, int) else seed_sequence(seed)
    q_current = None if q_current is None else robot.check_q(q_current, "q_current")
    if q_current is not None and q_current.ndim != 1:
        raise ShapeError(f"q_current must be one joint vector ({robot.dof},), got "
                         f"{q_current.shape}")
    guard = (None if scene is None and self_collision is False and collision is None
             and clearance == 0.0 and type(clearance) is float
             else collision_guard(robot, scene=scene, self_collision=self_collision,
                                  clearance=clearance, collision=collision))
    session = SolveSession(robot, target, tolerance, opts.distinct, opts.n_solutions,
                           opts.max_evals, guard=guard)
    if seeds is None:  # the first stage's generator; later stages spawn from the seed
        with start_generator(seed) as starts_rng:
            return _solve(session, opts, starts_rng, q_current, seed, t0)
    return _solve(session, opts, np.random.Generator(np.random.PCG64(starts_sequence(seeds))),
                  q_current, seeds, t0)


def _solve(session: SolveSession, opts: SearchOptions, starts_rng: np.random.Generator,
           q_current, seed, t0: float) -> IKResult:
    """The stages of :func:`solve_ik` (``seed``: an integer or a SeedSequence)."""
    robot, target = session.robot, session.target
    n_solutions, polish = opts.n_solutions, opts.polish
    out_of_reach = reach_excess(robot, target) > 0
    if out_of_reach:  # proven out of reach: no start or search can help
        return _out_of_reach(session, opts, starts_rng, q_current, t0)
    if polish and (q_current is not None or opts.starts):
        if q_current is not None:  # the user's hint: never abandoned for slow progress
            session.local_starts(q_current[None].copy(), patient=True)
        first = min(opts.starts, FIRST_STARTS)  # most poses need one or two starts: draw
        Q0 = robot.random_q(first, rng=starts_rng)  # the rest only when they are needed
        if len(session.found) < n_solutions and first and session.n_eval < opts.max_evals:
            session.local_starts(Q0)
        if (len(session.found) < n_solutions and opts.starts > first
                and session.n_eval < opts.max_evals  # no start begins past the budget
                and not collision_proven(session)):
            session.local_starts(robot.random_q(opts.starts - first, rng=starts_rng))
    elif q_current is not None:
        session.consider(np.clip(q_current, robot.lower, robot.upper)[None])
    if len(session.found) >= n_solutions:  # the usual end: the first stage solved it
        return ik_result(session, q_current, t0, False, None, None)
    if collision_proven(session):  # the target alone collides: no search can do better
        return ik_result(session, q_current, t0, True, None, None)
    problem = _search_problem(robot, target, opts.orientation)
    seeds = np.random.SeedSequence(seed) if isinstance(seed, int) else seed
    idle_rounds, patience = 0, opts.patience
    if ((session.found or session.colliding is not None)  # every start ran and found some
            and opts.starts > FIRST_STARTS):  # branches (or only colliding ones): the rest
        patience = min(patience, FOUND_PATIENCE)  # most likely do not exist
    while (len(session.found) < n_solutions and session.n_eval < opts.max_evals
           and idle_rounds < patience):
        n_found = len(session.found)
        _search_round(session, problem, opts, int(seeds.spawn(1)[0].generate_state(1)[0]))
        idle_rounds = 0 if len(session.found) > n_found else idle_rounds + 1
    searched_out = idle_rounds >= patience  # ended for lack of progress, not for budget
    exact = session.colliding is not None  # reached exactly, only in collision
    if (not session.found and not exact and session.best is not None and polish
            and session.n_eval < opts.max_evals):  # a near miss may need more iterations
        session.refine(session.best[1], polish, max_nfev=FINAL_NFEV)
    front = front_q = None
    if not session.found and not exact and target.rotation is not None:
        front, front_q = _front(session, opts, seeds)
        if polish and not session.found:
            front, front_q, n = polished_front(robot, target, opts.orientation,
                                               robot.random_q(FRONT_STARTS, rng=starts_rng),
                                               front_q, budget=opts.front_evals)
            session.n_eval += n
    return ik_result(session, q_current, t0, searched_out, front, front_q)


def collision_proven(session: SolveSession) -> bool:
    """Whether every exact answer collides and none can be farther from contact than the
    one found: no answer found, an exact one rejected for collision, and a pair placed by
    the target alone (:meth:`~moik.solver.collision.CollisionGuard.target_bound`) below the
    clearance and attaining that answer's smallest distance, both up to the slack the
    pose tolerance allows (two exact answers place the last body up to twice the tolerance
    apart; a point of it up to :data:`BODY_EXTENT` reaches from the end effector). The
    proof is kept as ``session.collision_proof`` (the pair and its distance)."""
    guard, colliding = session.guard, session.colliding
    if guard is None or colliding is None or session.found:
        return False
    bound, pair, least = guard.target_bound(colliding[1], session.target.rotation is not None)
    tol, reach = session.tol, session.robot.reach
    slack = 2.0 * (tol.position + tol.orientation * BODY_EXTENT * reach)
    if not (bound < guard.clearance - slack and least >= bound - slack):
        return False
    session.collision_proof = (pair, bound)
    return True


def _out_of_reach(session: SolveSession, opts: SearchOptions, rng: np.random.Generator,
                  q_current, t0: float) -> IKResult:
    """The verdict for a target beyond the provable reach bound, with its polished front
    (a pose) or the position-only optimum (a position target)."""
    robot, target = session.robot, session.target
    starts = robot.random_q(FRONT_STARTS, rng=rng)
    if q_current is not None:
        starts = np.vstack([q_current, starts])
    front = front_q = None
    if target.rotation is not None and opts.polish:
        front, front_q, n = polished_front(robot, target, opts.orientation, starts,
                                           budget=opts.front_evals)
        session.n_eval += n
        session.consider(front_q)
    elif opts.polish:  # the position-only scalarisation (w = 1; the rotation is ignored)
        Q, n = lm_front(robot, Target(target.position, np.eye(3)), starts, np.ones(1))
        session.n_eval += n
        session.consider(Q)
    else:
        session.consider(np.clip(starts, robot.lower, robot.upper))
    return ik_result(session, q_current, t0, True, front, front_q, proven=True)


def _search_round(session: SolveSession, problem, opts: SearchOptions, run_seed: int) -> None:
    """One search run; the best candidate of the initial population is polished
    at once (early stop when that already solves the target), the best
    ``opts.candidates_per_round`` distinct ones after the last generation."""
    generations, n_solutions = opts.generations, opts.n_solutions
    algorithm = algorithm_registry().get_algorithm(opts.method, pop_size=opts.pop_size)
    algorithm.setup(problem, termination=("n_gen", generations), seed=run_seed)
    robot, gen = session.robot, 0
    while algorithm.has_next() and len(session.found) < n_solutions:
        algorithm.next()
        gen += 1
        if gen not in (1, generations):
            continue
        X, F = _population(algorithm)
        picked: list[np.ndarray] = []
        for i in np.argsort(F, kind="stable"):
            if len(picked) == (1 if gen == 1 else opts.candidates_per_round):
                break
            if is_distinct(robot, X[i], picked + session.found, session.distinct):
                picked.append(X[i])
        for q0 in picked:  # a quick try after gen 1; a full refinement at the end
            session.refine(q0, opts.polish, max_nfev=QUICK_NFEV if gen == 1 else 60)
            if len(session.found) >= n_solutions:
                break
    session.n_eval += algorithm.evaluator.n_eval


def _front(session: SolveSession, opts: SearchOptions, seeds) -> tuple[np.ndarray, np.ndarray]:
    """Pareto front of (position, orientation) errors; its member with the
    smallest combined error is refined too (a second, independent global search:
    if it reaches the pose after all, the target is solved)."""
    robot, target = session.robot, session.target
    problem = BiObjectiveIK(robot, target, orientation=opts.orientation)
    algorithm = algorithm_registry().get_algorithm(opts.front_method)
    run_seed = int(seeds.spawn(1)[0].generate_state(1)[0])
    res = minimize(problem, algorithm, ("n_eval", opts.front_evals), seed=run_seed,
                   copy_algorithm=False)
    session.n_eval += algorithm.evaluator.n_eval
    front, front_q = np.atleast_2d(res.F), np.atleast_2d(res.X)
    best = int(np.argmin(front[:, 0] / robot.reach + front[:, 1]))
    session.refine(front_q[best], opts.polish, max_nfev=FINAL_NFEV)
    return front, front_q
