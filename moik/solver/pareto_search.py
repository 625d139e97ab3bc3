"""The search machinery of :func:`moik.solver.pareto.solve_ik_pareto`.

- :class:`Projector`: Levenberg-Marquardt from any joint vector onto the
  target's exact solutions (compiled, :func:`project_rows`), and the archive of
  the exact points found (non-dominated, distinct rows) in minimisation form.
- :func:`mo_search`: a registered multi-objective algorithm on the projected
  criteria (:class:`ProjectedCriteria`, unconstrained: a candidate whose
  projection fails gets a penalty every exact point dominates).
- :class:`ProjectionRepair`: the projection as a pymoo ``Repair``, for any pymoo
  algorithm on the constrained :class:`~moik.problems.pareto_ik.ParetoIK`.
- :func:`local_search`: steps along the null space of the task Jacobian, each
  projected back, for weighted sums of the (scaled) criteria.
- :func:`enumerate_branches`: the isolated solutions of a non-redundant arm.
- :func:`spread_subset`: ``n`` members spread over a front, each criterion's best kept.
"""

from __future__ import annotations

import numpy as np
from pymoo.core.problem import Problem
from pymoo.core.repair import Repair
from pymoo.core.sampling import Sampling

from moik._jit import jit, kernel_array
from moik.algorithms import get_algorithm
from moik.algorithms.archive.base import first_unique_mask, nondominated_mask
from moik.algorithms.registry import accepted_parameters
from moik.kinematics.jacobian import parts_and_jacobian
from moik.problems.pareto_ik import ParetoIK
from moik.solver.lm import STALL_RATIO, lm_start, multistart
from moik.solver.session import STOP_FRACTION, joint_distance, nearest_copies

LM_ITERATIONS = 30  # per projection (the first stage of solve_ik uses as many)
BRANCH_STARTS = 256  # random starts that enumerate a non-redundant arm's branches
MAX_BRANCHES = 16  # a general 6R arm has at most 16 solutions per pose
BRANCH_DISTINCT = 0.1  # joint-space distance (modulo 2 pi) between distinct branches
STEP_FACTORS = np.array([2.0, 1.0, 0.5, 0.25])  # trial step lengths, times the current one
FD_STEP = 1e-6  # central-difference step (rad) of the directional derivatives
MIN_STEP = 1e-5  # a local search stops below this step length (rad)
LIMIT_GAP = 1e-9  # a joint this near a limit (rad or robot unit) counts as at it
START_DISTINCT = 0.3  # joint-space distance between the starts of one local search weight


@jit
def project_rows(F, types, lo, hi, X, Rt, pt, has_rot, inv_len, stop_pos, stop_ori, max_iter,
                 stall_ratio, ok, cost):
    """LM from every row of ``X`` (in place): ``ok[i]`` whether it converged, ``cost[i]``
    its final ``0.5 |r|^2``. Returns the FK evaluations."""
    n_eval = 0
    for i in range(X.shape[0]):
        conv, c, ne = lm_start(F, types, lo, hi, X[i], Rt, pt, has_rot, inv_len, 1.0, stop_pos,
                               stop_ori, max_iter, stall_ratio)
        ok[i], cost[i] = conv, c
        n_eval += ne
    return n_eval


class Projector:
    """Projection onto one target's exact solutions, and the archive of those found.

    Args:
        problem: The :class:`~moik.problems.pareto_ik.ParetoIK` problem (target,
            tolerances, criteria, ``q_current``).

    Attributes:
        X, F: The archive: exact, mutually non-dominated points and their criteria
            in minimisation form.
        n_eval: FK (+ Jacobian) evaluations so far.
    """

    def __init__(self, problem: ParetoIK):
        self.problem, self.robot = problem, problem.robot
        target = problem.target
        self._has_rot = target.rotation is not None
        self._Rt = kernel_array(target.rotation if self._has_rot else np.eye(3))
        self._pt = kernel_array(target.position)
        self._stops = (STOP_FRACTION * problem.tol_position,
                       STOP_FRACTION * problem.tol_orientation)
        self.n_eval = 0
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
        robot, chain = self.robot, self.robot.kinematic_chain
        P = np.array(X, dtype=np.float64, order="C", copy=True).reshape(-1, robot.dof)
        ok, cost = np.zeros(len(P), dtype=np.bool_), np.empty(len(P))
        self.n_eval += int(project_rows(
            chain.origins, chain.joint_types, robot.lower, robot.upper, P, self._Rt, self._pt,
            self._has_rot, 1.0 / robot.reach, self._stops[0], self._stops[1], LM_ITERATIONS,
            1.0 if patient else STALL_RATIO, ok, cost))
        return self._copies(P), ok, cost

    def project_via_pose(self, X, rotation: np.ndarray
                         ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`project` after LM towards the pose (target position, ``rotation``): the
        starts of the ``orientation`` criterion (0 where that pose is reachable)."""
        robot, chain = self.robot, self.robot.kinematic_chain
        P = np.array(X, dtype=np.float64, order="C", copy=True).reshape(-1, robot.dof)
        ok, cost = np.zeros(len(P), dtype=np.bool_), np.empty(len(P))
        self.n_eval += int(project_rows(
            chain.origins, chain.joint_types, robot.lower, robot.upper, P,
            kernel_array(rotation), self._pt, True, 1.0 / robot.reach, self._stops[0],
            self._stops[1], LM_ITERATIONS, STALL_RATIO, ok, cost))
        return self.project(P)

    def _copies(self, P: np.ndarray) -> np.ndarray:
        if self.problem.q_current is None or not len(P):
            return P
        return np.ascontiguousarray(nearest_copies(self.robot, P, self.problem.q_current))

    def objectives(self, P: np.ndarray) -> np.ndarray:
        """Criteria of exact points in minimisation form; the points enter the archive."""
        F = self.problem.minimization_form(self.problem.natural(P))
        if len(P):
            self.worst = np.maximum(self.worst, F.max(axis=0))
            self._seen.append((P, F))
            X, Fa = np.concatenate([self.X, P]), np.concatenate([self.F, F])
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


def nullspace(projector: Projector, P: np.ndarray) -> np.ndarray:
    """Orthonormal null-space bases ``(n, dof - rows, dof)`` of the task Jacobians at ``P``
    (position rows scaled by ``1 / reach``)."""
    robot, rows = projector.robot, projector.task_rows
    _, _, J = parts_and_jacobian(robot, P)
    Jt = J[:, :rows].copy()
    Jt[:, :3] /= robot.reach
    return np.linalg.svd(Jt)[2][:, rows:, :]


def descent_directions(robot, P: np.ndarray, N: np.ndarray, g: np.ndarray) -> np.ndarray:
    """Steepest descent ``(n, dof)`` within the null spaces ``N (n, r, dof)`` given the
    directional derivatives ``g (n, r)`` along their basis, with the joints at a limit
    that it would push out held fixed (the descent within the remaining subspace)."""
    d = -np.einsum("ar,ard->ad", g, N)
    at_lo, at_hi = P - robot.lower <= LIMIT_GAP, robot.upper - P <= LIMIT_GAP
    for i in np.flatnonzero(np.any((at_lo & (d < 0)) | (at_hi & (d > 0)), axis=1)):
        held = (at_lo[i] & (d[i] < 0)) | (at_hi[i] & (d[i] > 0))
        _, sv, Vt = np.linalg.svd(N[i][:, held].T)  # coefficients a with (N^T a)_held = 0
        B = Vt[int(np.sum(sv > 1e-12)):].T
        d[i] = -N[i].T @ (B @ (B.T @ g[i]))
    return d


def scaled_scores(F: np.ndarray, W: np.ndarray, span: np.ndarray) -> np.ndarray:
    """Weighted sums ``sum_k W_ik F_ik / span_k`` per row."""
    return np.einsum("...m,...m->...", F / span, W)


def local_search(projector: Projector, starts: np.ndarray, weights: np.ndarray, *,
                 iterations: int, step: float) -> None:
    """Descend each weighted sum from its start along the solution set, all at once.

    Each iteration takes the gradient of ``w . F / span`` within the null space
    (central differences along its basis), tries steps of several lengths along
    it, projects them back (every exact trial enters the archive) and moves to the
    best trial if it improves the weighted sum; the step length grows after a
    long accepted step and shrinks by 4 after a failure.
    """
    problem, dof = projector.problem, projector.robot.dof
    span = np.ptp(projector.F, axis=0)
    span = np.where(span > 0, span, 1.0)
    P, W = starts.copy(), weights
    S = scaled_scores(problem.minimization_form(problem.natural(P)), W, span)
    h = np.full(len(P), float(step))
    for _ in range(iterations):
        act = np.flatnonzero(h > MIN_STEP)
        if not len(act):
            return
        N = nullspace(projector, P[act])
        D = P[act, None, None, :] + FD_STEP * np.array([1.0, -1.0])[:, None] * N[:, :, None, :]
        Fd = problem.minimization_form(problem.natural(D.reshape(-1, dof)))
        Sd = scaled_scores(Fd.reshape(*D.shape[:3], -1), W[act, None, None], span)
        d = descent_directions(projector.robot, P[act], N,
                               (Sd[..., 0] - Sd[..., 1]) / (2.0 * FD_STEP))
        norm = np.linalg.norm(d, axis=1)
        norm = np.where(norm > 0, norm, 1.0)
        lengths = h[act, None] * STEP_FACTORS
        trials = P[act, None, :] + lengths[..., None] * (d / norm[:, None])[:, None, :]
        Pt, ok, _ = projector.project(trials.reshape(-1, dof))
        St = np.full(len(Pt), np.inf)
        St[ok] = scaled_scores(projector.objectives(Pt[ok]), np.repeat(W[act], len(
            STEP_FACTORS), axis=0)[ok], span)
        St = St.reshape(len(act), -1)
        b = np.argmin(St, axis=1)
        better = St[np.arange(len(act)), b] < S[act]
        Pt = Pt.reshape(len(act), len(STEP_FACTORS), dof)
        won = act[better]
        P[won], S[won] = Pt[better, b[better]], St[better, b[better]]
        h[won] = lengths[better, b[better]] * 1.5
        h[act[~better]] *= 0.25


def local_search_starts(projector: Projector, per_extreme: int = 4
                        ) -> tuple[np.ndarray, np.ndarray]:
    """``(starts, weights)``: for each criterion, the ``per_extreme`` best exact points
    seen that are ``START_DISTINCT`` apart in joint space (local optima on other
    branches or regions), with that criterion's unit weight; and the archive member
    best in a few even weighted sums (three for two criteria, one for more)."""
    m = projector.F.shape[1]
    mixes = [np.array([t, 1.0 - t]) for t in (0.25, 0.5, 0.75)] if m == 2 else (
        [np.full(m, 1.0 / m)] if m > 2 else [])
    X, F = projector.seen()
    span = np.ptp(projector.F, axis=0)
    span = np.where(span > 0, span, 1.0)
    starts, weights = [], []
    for k in range(m):
        picked = _distinct_best(projector.robot, X, F[:, k], per_extreme)
        starts += picked
        weights += [np.eye(m)[k]] * len(picked)
    for w in mixes:
        starts += _distinct_best(projector.robot, projector.X, projector.F / span @ w, 1)
        weights.append(w)
    return np.array(starts), np.array(weights)


def _distinct_best(robot, X: np.ndarray, score: np.ndarray, count: int) -> list[np.ndarray]:
    """The ``count`` rows of ``X`` lowest in ``score``, each ``START_DISTINCT`` from the others."""
    order = np.argsort(score, kind="stable")
    free = np.ones(len(order), dtype=bool)  # far enough from every row picked so far
    picked: list[np.ndarray] = []
    while len(picked) < count and free.any():
        q = X[order[int(np.argmax(free))]]
        picked.append(q)
        free &= joint_distance(robot, q, X[order]) > START_DISTINCT
    return picked


def enumerate_branches(projector: Projector, starts: np.ndarray) -> None:
    """The distinct solutions (modulo 2 pi) reached by LM from ``starts`` enter the archive."""
    problem = projector.problem
    res = multistart(projector.robot, problem.target, starts,
                     stop_position=STOP_FRACTION * problem.tol_position,
                     stop_orientation=STOP_FRACTION * problem.tol_orientation,
                     want=MAX_BRANCHES, distinct=BRANCH_DISTINCT, max_iter=LM_ITERATIONS)
    projector.n_eval += res.n_eval
    projector.objectives(projector._copies(res.solutions))


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
