"""Collision-constrained IK problems: any IK problem plus inequality constraints ``G``.

:class:`CollisionIK` wraps a :class:`~moik.problems.PositionIK`,
:class:`~moik.problems.PoseIK` or :class:`~moik.problems.BiObjectiveIK` (same variables,
bounds and objectives, computed by the wrapped problem) and adds pymoo inequality
constraints ``G <= 0`` from the compiled distances of :mod:`moik.collision`:

* ``groups="min"``: one constraint, ``G = clearance - min_pairs d(q)`` (the aggregate);
* ``groups="links"``: one constraint per robot body in some checked pair,
  ``G_b = clearance - min over the pairs involving body b`` (:attr:`group_names`).

So any pymoo or moik algorithm that handles constraints (feasibility first) solves
collision-free IK; ``clearance`` is the required distance (robot unit).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from pymoo.core.problem import Problem

from moik._validate import choice, number
from moik.collision.model import CollisionChecker, keeps_clearance
from moik.exceptions import GeometryError, ParameterError
from moik.problems.ik import _IKProblem

GROUPS = ("min", "links")


class CollisionIK(Problem):
    """An IK problem with collision constraints (see the module doc).

    Args:
        problem: The IK problem (its robot must be the checker's).
        checker: The model, scene and self-collision switch, compiled.
        clearance: Required minimum distance (>= 0 keeps contact out; negative allows
            that much penetration).
        groups: ``"min"`` (one aggregate constraint) or ``"links"`` (one per body).
    """

    def __init__(self, problem: _IKProblem, *, checker: CollisionChecker,
                 clearance: float = 0.0, groups: str = "min") -> None:
        if not isinstance(problem, _IKProblem):
            raise ParameterError(f"problem must be a moik IK problem, got "
                                 f"{type(problem).__name__}")
        if not isinstance(checker, CollisionChecker):
            raise GeometryError(f"checker must be a CollisionChecker, got "
                                f"{type(checker).__name__}")
        if checker.robot is not problem.robot and (
                checker.robot.name != problem.robot.name or checker.robot.dof != problem.robot.dof):
            raise GeometryError(f"the collision model is for robot {checker.robot.name!r}, the "
                                f"problem for {problem.robot.name!r}")
        self.inner, self.checker = problem, checker
        self.clearance = number("clearance", clearance)
        self.groups = choice("collision groups", groups, GROUPS)
        bodies = sorted({b for pair in checker.pair_bodies for b in pair if b >= 0})
        self._group_of = np.array([[bodies.index(b) if b >= 0 else -1 for b in pair]
                                   for pair in checker.pair_bodies], dtype=np.int64
                                  ).reshape(-1, 2)
        links = checker.model.links
        self.group_names = ("min distance",) if self.groups == "min" else tuple(
            links[b] for b in bodies)
        self.robot, self.target = problem.robot, problem.target
        super().__init__(n_var=problem.n_var, n_obj=problem.n_obj,
                         n_ieq_constr=len(self.group_names), xl=problem.xl.copy(),
                         xu=problem.xu.copy(), vtype=float)

    def keeps(self, distances):
        """Whether distances keep :attr:`clearance`
        (:func:`~moik.collision.model.keeps_clearance`)."""
        return keeps_clearance(distances, self.clearance)

    def __getattr__(self, name: str) -> Any:
        # errors(), position_error(), q_start ... of the wrapped problem
        if name in ("inner", "__setstate__"):
            raise AttributeError(name)
        return getattr(self.inner, name)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = self.inner.evaluate(X, return_values_of=["F"])
        Q = self.robot.kernel_batch(np.atleast_2d(X))
        if self.groups == "min":
            out["G"] = (self.clearance - self.checker.min_distance_batch(Q))[:, None]
            return
        D = self.checker.distances(Q)
        G = np.full((Q.shape[0], len(self.group_names)), -np.inf)
        for k, (ga, gb) in enumerate(self._group_of):
            for g in (ga, gb):
                if g >= 0:
                    np.maximum(G[:, g], self.clearance - D[:, k], out=G[:, g])
        out["G"] = G

    def min_distance(self, X: np.ndarray) -> np.ndarray:
        """The smallest distance of each row, ``(n,)`` (recomputed, not from ``G``)."""
        return self.checker.min_distance(np.atleast_2d(X))
