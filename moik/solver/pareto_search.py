"""The search machinery of :func:`moik.solver.pareto.solve_ik_pareto`.

- :class:`Projector`: Levenberg-Marquardt from any joint vector onto the
  target's exact solutions (compiled, :func:`~moik.solver.starts.run_starts`), and the archive of
  the exact points found (non-dominated, distinct rows) in minimisation form.
- :func:`mo_search`: a registered multi-objective algorithm on the projected
  criteria (:class:`ProjectedCriteria`, unconstrained: a candidate whose
  projection fails gets a penalty every exact point dominates).
- :class:`ProjectionRepair`: the projection as a pymoo ``Repair``, for any pymoo
  algorithm on the constrained :class:`~moik.problems.pareto_ik.ParetoIK`.
- :func:`enumerate_branches`: the isolated solutions of a non-redundant arm.
- :func:`spread_subset`: ``n`` members spread over a front, each criterion's best kept.
"""

from __future__ import annotations

import numpy as np
from pymoo.core.problem import Problem
from pymoo.core.repair import Repair
from pymoo.core.sampling import Sampling

from moik.algorithms import get_algorithm
from moik.algorithms.archive.fronts import first_unique_mask, nondominated_mask
from moik.algorithms.registry import accepted_parameters
from moik.kinematics.criteria import nearest_copies
from moik.problems.pareto_ik import ParetoIK
from moik.problems.targets import Target
from moik.solver.collision import CollisionGuard
from moik.solver.context import LM_ITERATIONS, ik_context
from moik.solver.starts import PATIENT, UNLIMITED, multistart, run_starts

BRANCH_STARTS = 256  # random starts that enumerate a non-redundant arm's branches
MAX_BRANCHES = 16  # a general 6R arm has at most 16 solutions per pose
BRANCH_DISTINCT = 0.1  # joint-space distance (modulo 2 pi) between distinct branches


class Projector:
    """Projection onto one target's exact solutions, and the archive of those found.

    Args:
        problem: The :class:`~moik.problems.pareto_ik.ParetoIK` problem (target,
            tolerances, criteria, ``q_current``).
        guard: The collision test (:class:`~moik.solver.collision.CollisionGuard`) of the
            constraint form: an exact point below its clearance is infeasible, never
            archived (so it cannot dominate a feasible one), and scored like a point LM
            did not converge to, worse the deeper it is.

    Attributes:
        X, F: The archive: exact (and with a guard collision-free), mutually
            non-dominated points and their criteria in minimisation form.
        n_eval: FK (+ Jacobian) evaluations so far.
        n_exact: Exact points evaluated so far.
    """

    def __init__(self, problem: ParetoIK, guard: CollisionGuard | None = None):
        self.problem, self.robot, self.guard = problem, problem.robot, guard
        self._has_rot = problem.target.rotation is not None
        self._stops = problem.tol.stop
        self.n_eval = self.n_exact = 0
        self.X = np.empty((0, self.robot.dof))
        self.F = np.empty((0, problem.n_obj))
        self.worst = np.zeros(problem.n_obj)  # of every exact point seen
        self._seen: list[tuple[np.ndarray, np.ndarray]] = []  # every exact point, in batches

    def seen(self) -> tuple[np.ndarray, np.ndarray]:
        """Every exact point evaluated so far (dominated ones too) and its criteria."""
        if not self._seen:
            return self.X, self.F
        self._seen = [(np.concatenate([b[0] for b in self._seen]),
                       np.concatenate([b[1] for b in self._seen]))]
        return self._seen[0]

    @property
    def task_rows(self) -> int:
        """Rows of the task: 6 for a pose, 3 for a position."""
        return 6 if self._has_rot else 3

    def project(self, X, patient: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(P, ok, cost)``: the LM ends from the rows of ``X`` (within the limits, shifted
        to the 2 pi copies nearest ``q_current``), which converged, their residual costs.
        ``patient``: no start is abandoned for slow progress."""
        P, ok, cost = self._ends(self.problem.target, X, PATIENT if patient else 0)
        return self.copies(P), ok, cost

    def project_via_pose(self, X, rotation: np.ndarray
                         ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`project` after LM towards the pose (target position, ``rotation``): the
        starts of the ``orientation`` criterion (0 where that pose is reachable)."""
        return self.project(self._ends(Target(self.problem.target.position, rotation), X, 0)[0])

    def _ends(self, target: Target, X, flags: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """LM towards ``target`` from every row of ``X`` (a projection, :func:`run_starts`
        with ``found=None``): the ends, which converged, their costs. The context is built
        per call: a Projector is deep-copied (pymoo), and a context cannot be."""
        ctx = ik_context(self.robot, target, stop=self._stops, max_iter=LM_ITERATIONS)
        P = np.array(X, dtype=np.float64, order="C", copy=True).reshape(-1, self.robot.dof)
        ends = np.empty((len(P), 3))
        self.n_eval += int(run_starts(ctx, P, (flags, UNLIMITED), None, None, ends)[1])
        return P, ends[:, 0] != 0.0, ends[:, 1]

    def copies(self, P: np.ndarray) -> np.ndarray:
        """``P`` with revolute joints shifted by 2 pi to the copies nearest ``q_current``
        within the limits (``P`` itself without ``q_current``)."""
        if self.problem.q_current is None or not len(P):
            return P
        return np.ascontiguousarray(nearest_copies(self.robot, P, self.problem.q_current))

    def criteria(self, P: np.ndarray) -> np.ndarray:
        """Criteria of the rows of ``P`` in minimisation form (nothing enters the archive)."""
        return self.problem.minimization_form(self.problem.natural(P))

    def objectives(self, P: np.ndarray, F: np.ndarray | None = None) -> np.ndarray:
        """Criteria of exact points in minimisation form (``F``: :meth:`criteria` of ``P``
        when already computed); the points enter the archive (with a guard: the
        collision-free ones; the others get a penalty score)."""
        F = self.criteria(P) if F is None else F
        if len(P):
            self.worst = np.maximum(self.worst, F.max(axis=0))
            self.n_exact += len(P)
        if len(P) and self.guard is not None:  # the constraint form: infeasible rows
            d = self.guard.distances(P)
            depth = self.guard.clearance - d
            bad = ~self.guard.keeps(d)
            F[bad] = self.worst + (1.0 + np.abs(self.worst)) * (1.0 + depth[bad, None])
            P, F_free = P[~bad], F[~bad]
        else:
            F_free = F
        if len(P):
            self._seen.append((P, F_free))
            X, Fa = np.concatenate([self.X, P]), np.concatenate([self.F, F_free])
            keep = nondominated_mask(Fa)
            X, Fa = X[keep], Fa[keep]
            keep = first_unique_mask(Fa)
            self.X, self.F = X[keep], Fa[keep]
        return F

    def evaluate(self, X: np.ndarray) -> np.ndarray:
        """Criteria of the projections of ``X`` (minimisation form); where LM did not
        converge, ``worst + (1 + |worst|) (1 + cost)``: dominated by every exact point."""
        P, ok, cost = self.project(X)
        F = np.empty((len(P), self.problem.n_obj))
        F[ok] = self.objectives(P[ok])
        F[~ok] = self.worst + (1.0 + np.abs(self.worst)) * (1.0 + cost[~ok, None])
        return F


class ProjectedCriteria(Problem):
    """What the multi-objective algorithm sees: the criteria at each candidate's projection.

    Unconstrained, bounds the joint limits. A single criterion is given twice (the
    multi-objective algorithms need two objectives; the dominance is the same).
    """

    def __init__(self, projector: Projector):
        self.projector = projector
        robot = projector.robot
        super().__init__(n_var=robot.dof, n_obj=max(projector.problem.n_obj, 2),
                         xl=robot.lower.copy(), xu=robot.upper.copy(), vtype=float)

    def _evaluate(self, X, out, *args, **kwargs):
        F = self.projector.evaluate(X)
        out["F"] = F if F.shape[1] > 1 else np.hstack([F, F])


class ProjectionRepair(Repair):
    """A pymoo repair that moves each candidate onto the target's exact solutions (LM,
    as :class:`Projector`); candidates that do not converge are left as they are.

    With it any pymoo algorithm on :class:`~moik.problems.pareto_ik.ParetoIK` becomes a
    Lamarckian memetic search: ``NSGA2(repair=ProjectionRepair(problem))``.
    """

    def __init__(self, problem: ParetoIK):
        super().__init__()
        self.projector = Projector(problem)

    def _do(self, problem, X, **kwargs):
        P, ok, _ = self.projector.project(X)
        return np.where(ok[:, None], P, X)


class SeededSampling(Sampling):
    """pymoo's initial sampling: the rows of ``X0`` first, the rest uniform within the bounds
    (drawn from the algorithm's random state)."""

    def __init__(self, X0: np.ndarray):
        super().__init__()
        self.X0 = X0

    def _do(self, problem, n_samples, *args, random_state=None, **kwargs):
        X0 = self.X0[:n_samples]
        xl, xu = problem.bounds()
        rest = random_state.uniform(xl, xu, size=(n_samples - len(X0), problem.n_var))
        return np.vstack([X0, rest])


def mo_search(projector: Projector, method: str, X0: np.ndarray, *, pop_size: int,
              generations: int, seed: int) -> None:
    """Run ``method`` for ``generations`` on :class:`ProjectedCriteria`, its initial
    population seeded with the rows of ``X0`` (moik's ``X0``, pymoo's ``sampling``)."""
    params: dict = {"pop_size": pop_size}
    accepted = accepted_parameters(method)
    X0 = X0[:pop_size]
    if "X0" in accepted:
        if len(X0):
            params["X0"] = X0
    elif "sampling" in accepted:
        params["sampling"] = SeededSampling(X0)
    algorithm = get_algorithm(method, **params)
    algorithm.setup(ProjectedCriteria(projector), termination=("n_gen", generations), seed=seed)
    while algorithm.has_next():
        algorithm.next()


def enumerate_branches(projector: Projector, starts: np.ndarray) -> None:
    """The distinct solutions (modulo 2 pi) reached by LM from ``starts`` enter the archive."""
    problem = projector.problem
    res = multistart(projector.robot, problem.target, starts,
                     stop_position=problem.tol.stop[0], stop_orientation=problem.tol.stop[1],
                     want=MAX_BRANCHES, distinct=BRANCH_DISTINCT, max_iter=LM_ITERATIONS)
    projector.n_eval += res.n_eval
    projector.objectives(projector.copies(res.solutions))


def spread_subset(F: np.ndarray, n: int) -> np.ndarray:
    """Indices of at most ``n`` rows of ``F`` spread over it: each column's minimum first,
    then repeatedly the row farthest (columns scaled to [0, 1]) from those taken."""
    if len(F) <= n:
        return np.arange(len(F))
    span = np.ptp(F, axis=0)
    Z = (F - F.min(axis=0)) / np.where(span > 0, span, 1.0)
    chosen = list(dict.fromkeys(int(i) for i in np.argmin(F, axis=0)))[:n]
    dist = np.min(np.linalg.norm(Z[:, None, :] - Z[chosen][None], axis=2), axis=1)
    while len(chosen) < n:
        i = int(np.argmax(dist))
        chosen.append(i)
        dist = np.minimum(dist, np.linalg.norm(Z - Z[i], axis=1))
    return np.array(chosen)
