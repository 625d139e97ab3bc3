"""``solve_ik_pareto``: the exact IK solutions of one target that are Pareto-optimal in
secondary criteria.

A redundant arm (more joints than the task has dimensions: 7 for a pose, 4 for a
position) has a continuum of exact solutions; which one to use is a
multi-objective choice (joint motion from the current configuration,
manipulability, limit margin, ...). A memetic search finds the Pareto set:

1. Levenberg-Marquardt (:func:`moik.solver.lm.lm_start`, compiled) from
   ``q_current`` and from seeded random configurations: exact solutions on
   several branches (with the ``orientation`` criterion, some of them first
   driven towards the preferred rotation: where that pose is reachable its
   solutions are the criterion's optimum).
2. A registered multi-objective algorithm (MOEOSMA by default, any of the
   registry's) searches the joint space; each candidate it proposes is projected
   onto the target's solution set by the same LM (Marquardt's damped steps end at
   a nearby exact solution, so the redundant coordinates the candidate chose are
   kept) and evaluated there. Candidates that do not converge get a penalty that
   every exact point dominates; the algorithm sees the criteria of the
   projections (Baldwinian learning), the pose constraint stays out of its sight.
3. Local search on the solution set: from each criterion's best exact points
   (a few, apart in joint space: other branches' optima) and from the archive
   members best in a few weighted sums of the criteria, steps along the null space of
   the task Jacobian (directional derivatives by central differences, any
   criterion including the user's), each step projected back, several step
   lengths at once (:mod:`moik.solver.pareto_local`; the projection, archive and
   search are in :mod:`moik.solver.pareto_search`).

Every exact point (revolute joints shifted by 2 pi to the copy nearest
``q_current`` within the limits, when it is given) goes into an archive that keeps
the non-dominated ones. A
non-redundant arm (a 6-DOF arm at a pose) has isolated branches only: they are
enumerated by LM from many seeded starts (distinct modulo 2 pi) and the
non-dominated ones are returned. Either way the returned set is thinned to
``n_solutions`` spread over the front (the best of each criterion always kept),
each member's errors are recomputed by the reference FK, and it is deterministic
for a seed.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from moik._validate import integer, positive
from moik.algorithms import get_algorithm
from moik.algorithms.registry import is_multi_objective
from moik.exceptions import ParameterError, ShapeError
from moik.metrics.compromise import closest_to_utopia
from moik.problems.pareto_ik import ParetoIK
from moik.robots.catalog import as_robot
from moik.solver.collision import CollisionGuard, collision_guard, with_clearance
from moik.solver.memetic import memetic_search
from moik.solver.options import MAX_SOLUTIONS, at_most, seed_sequence
from moik.solver.pareto_search import BRANCH_STARTS, Projector, enumerate_branches, spread_subset
from moik.solver.session import pose_errors

DEFAULT_OBJECTIVES = ("joint_motion", "manipulability")


@dataclass(frozen=True)
class ParetoIKResult:
    """Outcome of :func:`solve_ik_pareto`.

    Attributes:
        X: ``(k, dof)`` exact solutions within the limits (revolute joints shifted by
            2 pi to the copy nearest ``q_current`` when it was given), sorted by the
            first criterion, best first.
        F: ``(k, m)`` criteria in their natural signs (``manipulability`` and
            ``limit_margin`` as themselves, larger better; ``joint_motion`` and
            ``orientation`` smaller better): mutually non-dominated.
        objectives: The criteria's names, the columns of ``F``.
        senses: ``"min"`` or ``"max"`` per criterion.
        position_errors, orientation_errors: ``(k,)`` errors of each member,
            recomputed by the reference FK (robot unit; geodesic angle, rad).
        redundant: Whether the arm is redundant for the target (memetic search)
            or not (branch enumeration).
        n_exact: Exact solutions evaluated (non-redundant arm: the distinct branches
            found, modulo 2 pi).
        n_eval: FK (+ Jacobian) evaluations.
        time: Wall time in seconds.
        min_distances: With a collision check, ``(k,)`` smallest signed distance of
            each member (all >= the clearance); ``None`` without one.
    """

    X: np.ndarray
    F: np.ndarray
    objectives: tuple[str, ...]
    senses: tuple[str, ...]
    position_errors: np.ndarray
    orientation_errors: np.ndarray
    redundant: bool
    n_exact: int
    n_eval: int
    time: float
    min_distances: np.ndarray | None = None

    @property
    def F_min(self) -> np.ndarray:
        """``F`` in minimisation form (maximised criteria negated), as :class:`ParetoIK` has it."""
        return self.F * np.array([1.0 if s == "min" else -1.0 for s in self.senses])

    def best(self, criterion: str) -> int:
        """Index of the member best in ``criterion`` (one of :attr:`objectives`).

        Raises:
            ParameterError: An unknown criterion name, or no solution.
        """
        if criterion not in self.objectives:
            raise ParameterError(f"criterion must be one of {list(self.objectives)}, got "
                                 f"{criterion!r}")
        if not len(self.X):
            raise ParameterError("no exact solution was found: no best member")
        return int(np.argmin(self.F_min[:, self.objectives.index(criterion)]))

    def compromise_index(self) -> int:
        """Index of the member closest to the utopia point (criteria scaled to [0, 1] over
        the set; the MO-m-PSO paper's Eq. 8 pick).

        Raises:
            ShapeError: No solution was found.
        """
        if not len(self.X):
            raise ShapeError("no exact solution was found: nothing to pick a compromise from")
        return closest_to_utopia(self.F_min)

    def compromise(self) -> tuple[np.ndarray, np.ndarray]:
        """The member of :meth:`compromise_index` as ``(q, f)`` copies (``f`` in natural signs).

        Raises:
            ShapeError: No solution was found.
        """
        i = self.compromise_index()
        return self.X[i].copy(), self.F[i].copy()


def solve_ik_pareto(robot, target, *, objectives=DEFAULT_OBJECTIVES, q_current=None,
                    n_solutions: int = 20, tol=1e-9, seed=0, method: str = "moeosma",
                    rotation=None, starts: int = 128, pop_size: int = 30,
                    generations: int = 20, local_iterations: int = 12,
                    local_step: float = 0.2, scene=None, self_collision: bool = False,
                    clearance: float = 0.0, collision=None) -> ParetoIKResult:
    """The exact IK solutions of ``target`` that are Pareto-optimal in secondary criteria.

    Args:
        robot: The arm (a Robot or a catalog name).
        target: 3-vector position, 4x4 pose, ``(position, rotation)`` or Target.
        objectives: Criteria (see :func:`moik.kinematics.criteria.build_criteria`):
            built-in names ``"joint_motion"`` (needs ``q_current``),
            ``"manipulability"``, ``"limit_margin"``, ``"orientation"`` (position
            targets, needs ``rotation``), :class:`~moik.kinematics.criteria.Criterion`
            objects, or callables ``f(Q) -> (n,)`` on a batch of joint vectors
            (minimised; wrap in a ``Criterion`` with ``sense="max"`` to maximise).
        q_current: The current configuration: the first start, and what
            ``joint_motion`` measures from.
        n_solutions: Most members returned (spread over the front, each criterion's
            best kept).
        tol: A number ``t``: position <= ``t * robot.reach``, orientation <= ``t``
            rad; or a pair (robot unit, rad). Every member meets it (reference FK).
        seed: Seed (int or SeedSequence): the same seed, the same result bit for bit.
        method: Registered multi-objective algorithm of the memetic search.
        rotation: The preferred end-effector rotation of ``"orientation"``.
        starts: Random Levenberg-Marquardt starts (after ``q_current``) that seed
            the search (a non-redundant arm's branches are enumerated from 256).
        pop_size, generations: Of the multi-objective search.
        local_iterations, local_step: Iterations and first step length (rad) of
            the null-space local search (0 iterations: none).
        scene, self_collision, clearance, collision: A collision check as in
            :func:`~moik.solver.solve_ik.solve_ik`: only members at least ``clearance``
            from contact are returned (the archive filtered at the end), and the
            criterion ``"clearance"`` (maximised) is the smallest signed distance.

    Returns:
        A :class:`ParetoIKResult` (empty ``X`` when no exact solution was found).

    Raises:
        ParameterError: A bad count, step, tolerance or criterion list
            (``joint_motion`` without ``q_current``, a criterion given twice,
            ``orientation`` with a pose target or without ``rotation``), a
            single-objective ``method`` or a ``pop_size`` it refuses.
        UnknownNameError: An unknown criterion or algorithm name.
        ShapeError, NonFiniteError: A criterion returning the wrong shape or a
            non-finite value; a malformed ``q_current`` or target.
    """
    t0 = time.perf_counter()
    robot = as_robot(robot)
    guard = collision_guard(robot, scene=scene, self_collision=self_collision,
                            clearance=clearance, collision=collision)
    objectives = with_clearance(objectives, guard)
    problem = ParetoIK(robot, target, objectives=objectives, q_current=q_current,
                       rotation=rotation, tol=tol)
    n_solutions = at_most("n_solutions", integer("n_solutions", n_solutions, minimum=1),
                          MAX_SOLUTIONS)
    starts = integer("starts", starts, minimum=0)
    pop_size = integer("pop_size", pop_size, minimum=2)
    generations = integer("generations", generations, minimum=0)
    local_iterations = integer("local_iterations", local_iterations, minimum=0)
    local_step = positive("local_step", local_step)
    if not is_multi_objective(method):
        raise ParameterError(f"method must be a multi-objective algorithm, got {method!r}")
    get_algorithm(method, pop_size=pop_size)  # the algorithm's own limits on pop_size
    seeds = seed_sequence(seed)
    rng = np.random.default_rng(seeds.spawn(1)[0])
    projector = Projector(problem, guard)
    first = np.empty((0, robot.dof)) if problem.q_current is None else problem.q_current[None]
    redundant = robot.dof > projector.task_rows
    if not redundant:
        enumerate_branches(projector, np.vstack([first, robot.random_q(BRANCH_STARTS, rng=rng)]))
    else:
        search: dict[str, Any] = {
            "starts": starts, "method": method, "pop_size": pop_size,
            "generations": generations, "local_iterations": local_iterations,
            "local_step": local_step, "seed": int(seeds.spawn(1)[0].generate_state(1)[0])}
        memetic_search(projector, first, rng, **search)
    return _result(problem, projector, n_solutions, redundant, t0, guard)


def _result(problem: ParetoIK, projector: Projector, n_solutions: int, redundant: bool,
            t0: float, guard: CollisionGuard | None = None) -> ParetoIKResult:
    """The archive (its collision-free members with a guard) thinned to ``n_solutions``,
    re-checked by the reference FK, sorted."""
    X_all, F_all = projector.X, projector.F
    if guard is not None and len(X_all):
        keep = guard.free(X_all)
        X_all, F_all = X_all[keep], F_all[keep]
    X = X_all[spread_subset(F_all, n_solutions)]
    pos, ori = pose_errors(problem.robot, problem.target, X, reference=True)
    exact = problem.tol.certifies(pos, ori)
    X, pos, ori = X[exact], pos[exact], ori[exact]
    F = problem.natural(X)
    order = np.argsort(problem.minimization_form(F)[:, 0], kind="stable")
    return ParetoIKResult(X=X[order], F=F[order], objectives=problem.names,
                          senses=problem.senses, position_errors=pos[order],
                          orientation_errors=ori[order], redundant=redundant,
                          n_exact=projector.n_exact, n_eval=projector.n_eval,
                          time=time.perf_counter() - t0,
                          min_distances=None if guard is None else guard.distances(X[order])
                          if len(X) else np.zeros(0))
