"""Unreachable targets: a proof of being out of reach, and a polished error front.

Out of reach (a proof, no search needed): the end effector of
``F_0 M_1(q_1) F_1 ... M_n(q_n) F_n`` is ``t_0 + R_0 (t_1 + R_1 (...))`` plus the
prismatic strokes along unit axes, so by the triangle inequality
``|p(q)| <= sum_j |t_j| + sum max |q_prismatic|`` (``robot.reach``) for every ``q``;
a target farther than that from the base origin cannot be reached, and its
position error is at least the excess.

The (position error, orientation error) front of an unreachable pose is made of
weighted-sum scalarisations solved by the compiled Levenberg-Marquardt
(:func:`moik.solver.starts.front`), from ``weights`` running from 1 (position only:
the front's end with the smallest position error) to 0 (orientation only); when a
metaheuristic front exists too (the search fallback), its members seed the
scalarisations and both are merged. Only mutually non-dominated members are kept.
The front's objectives are those of :class:`~moik.problems.ik.BiObjectiveIK` with
the solve's orientation metric (errors recomputed by FK).
"""

from __future__ import annotations

import math

import numpy as np

from moik.algorithms.archive.fronts import nondominated_mask
from moik.problems.ik import BiObjectiveIK
from moik.problems.targets import Target
from moik.robots.chain import Robot
from moik.solver.starts import front as lm_front

FRONT_WEIGHTS = 21  # scalarisations from position-only (w = 1) to orientation-only (w = 0)
FRONT_STARTS = 4  # random starts per scalarisation (besides the previous weight's answer)


def reach_excess(robot: Robot, target: Target) -> float:
    """How far (robot unit) the target lies beyond ``robot.reach`` (<= 0: within).

    ``robot.reach`` is ``sum_j |t_j|`` over all constant transforms plus the
    prismatic strokes: the module docstring's bound, measured from the base origin.
    """
    p = target.position
    return math.hypot(float(p[0]), float(p[1]), float(p[2])) - robot.reach  # no overflow


def polished_front(robot: Robot, target: Target, orientation: str, starts: np.ndarray,
                   front_q: np.ndarray | None = None, budget: int = 2**62
                   ) -> tuple[np.ndarray, np.ndarray, int]:
    """The non-dominated (position, orientation) front of a pose, and its joint vectors.

    Args:
        robot, target: The problem (``target`` has a rotation).
        orientation: Orientation metric of the front's second objective.
        starts: Starts of every scalarisation ``(k, dof)``.
        front_q: Joint vectors of a front found otherwise (merged, and its two
            ends added to the starts).
        budget: No scalarisation start begins once this many FK evaluations are spent
            (the weights left keep the previous weight's answer).

    Returns:
        ``(F, Q, n_eval)``: ``F (m, 2)`` sorted by position error, ``Q (m, dof)``.
    """
    problem = BiObjectiveIK(robot, target, orientation=orientation)
    seeds = [np.asarray(starts, dtype=float)]
    if front_q is not None and len(front_q):
        F0 = problem.evaluate(front_q, return_values_of=["F"])
        seeds.append(front_q[[int(np.argmin(F0[:, 0])), int(np.argmin(F0[:, 1]))]])
    Q, n_eval = lm_front(robot, target, np.vstack(seeds), np.linspace(1.0, 0.0, FRONT_WEIGHTS),
                         budget=budget)
    if front_q is not None and len(front_q):
        Q = np.vstack([Q, front_q])
    Q = np.clip(Q, robot.lower, robot.upper)
    F = problem.evaluate(Q, return_values_of=["F"])
    keep = nondominated_mask(F)
    F, Q = F[keep], Q[keep]
    _, first = np.unique(F, axis=0, return_index=True)  # one member per objective vector
    order = first[np.argsort(F[first, 0], kind="stable")]
    return F[order], Q[order], n_eval + len(Q)
