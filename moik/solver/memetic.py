"""The memetic search of :func:`~moik.solver.pareto.solve_ik_pareto` on a redundant arm
(:func:`memetic_search`, the steps 1-3 of that module), and its algorithm's kernels
compiled in a second process while the first stage runs (:func:`precompile`).

With an empty kernel cache, the first :func:`~moik.solver.pareto.solve_ik_pareto` of a
redundant arm compiles two independent families of kernels one after the other: the
kinematic ones (the Levenberg-Marquardt start loop of its projection,
:mod:`moik.solver.starts`, about half of the time, then the criteria and the local
search's Jacobians, which share its FK kernels) and those of the multi-objective
algorithm and the archive's fronts (:mod:`moik.algorithms`). Where a second CPU is free
:func:`precompile` runs the same algorithm in a child process (:mod:`moik._background`:
the same ``method``, population, generations and numbers of joints and criteria, hence
the same kernels and argument types) on stand-ins: an identity projection instead of LM
and plain-numpy stand-ins of the criteria (:func:`stand_in`), so it compiles no
kinematic kernel, and no local search. It writes the algorithm's kernels to the cache
while this process compiles LM's, says so, and then evaluates the local search's joint
distances and Jacobians (which this process needs last) and the built-in criteria on a
few configurations: their kernels (which share the FK kernels this process has cached
by then) are often cached too when this process gets to them. This process
waits for the child's word after its first criteria and before its archive and search,
which then load the algorithm's kernels (``benchmarks/startup.py`` times the cold first
``--pareto`` solve).

The child changes nothing but time: it draws nothing from the caller's seeds, never
calls a criterion of the user's (a stand-in instead), and whatever it did not write
this process compiles itself.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

import numpy as np

from moik import _background
from moik.algorithms.archive.fronts import front_mask_2d
from moik.algorithms.moo.moeosma_kernels import generation_draws
from moik.kinematics.criteria import Criterion, joint_distance
from moik.kinematics.jacobian import parts_and_jacobian
from moik.problems.pareto_ik import ParetoIK
from moik.solver.pareto_local import local_search, local_search_starts
from moik.solver.pareto_search import Projector, mo_search

ORIENTATION_STARTS = 16  # LM ends of the random starts moved towards the preferred rotation


def memetic_search(projector: Projector, first: np.ndarray, rng: np.random.Generator, *,
                   starts: int, method: str, pop_size: int, generations: int,
                   local_iterations: int, local_step: float, seed: int,
                   ready: Callable[[], None] | None = None) -> None:
    """Steps 1-3 of a redundant arm's search (module docstring): LM from ``first`` and
    ``starts`` random configurations (from ``rng``), the multi-objective ``method`` (seeded
    by ``seed``), the local search; every exact point enters ``projector``'s archive.
    ``ready`` is called after the first criteria, before the archive and the search (a
    background compilation of the algorithm's kernels is waited for there)."""
    problem, robot = projector.problem, projector.robot
    P, ok, _ = projector.project(first, patient=True)
    Q, ok_q, _ = projector.project(robot.random_q(starts, rng=rng))
    exact = np.vstack([P[ok], Q[ok_q]])
    if problem.rotation is not None and "orientation" in problem.names:
        R, ok_r, _ = projector.project_via_pose(Q[:ORIENTATION_STARTS], problem.rotation)
        exact = np.vstack([exact, R[ok_r]])
    F = projector.criteria(exact)  # the criteria's kernels compile beside the child
    if ready is not None:
        ready()
    projector.objectives(exact, F)
    if generations:
        mo_search(projector, method, exact, pop_size=pop_size, generations=generations,
                  seed=seed)
    if local_iterations and len(projector.X):
        begin, weights = local_search_starts(projector)
        local_search(projector, begin, weights, iterations=local_iterations, step=local_step)


def precompile(problem: ParetoIK, objectives, first: np.ndarray, search: dict
               ) -> _background.Background | None:
    """Start compiling the search's kernels in a child process, or return None where that
    cannot help (see the module docstring and :mod:`moik._background`).

    Args:
        problem: The :class:`~moik.problems.pareto_ik.ParetoIK` problem of the search.
        objectives: Its criteria as given (names, :class:`Criterion` objects, callables):
            the child's search runs on stand-ins (:func:`stand_in`) of every one; then
            it evaluates the built-in ones by name (their kernels) and never calls a
            function of the user's.
        first, search: The arguments :func:`memetic_search` will be given.
    """
    names = list(objectives) if isinstance(objectives, list | tuple) else [objectives]
    if len(names) != problem.n_obj:
        return None
    m = problem.n_obj
    arguments = {"robot": problem.robot, "target": problem.target,
                 "tol": (problem.tol_position, problem.tol_orientation),
                 "rotation": problem.rotation}
    stand_ins = [Criterion(problem.names[k], partial(stand_in, k, m, sense), sense)
                 for k, sense in enumerate(problem.senses)]
    kinematic = [item if isinstance(item, str) else stand_ins[k] for k, item in enumerate(names)]
    probes = [generation_draws] + ([front_mask_2d] if m <= 2 else [])
    return _background.start(__name__, ({**arguments, "objectives": stand_ins}, first,
                                        {**search, "local_iterations": 0},
                                        {**arguments, "objectives": kinematic,
                                         "q_current": problem.q_current}), probes)


def stand_in(k: int, m: int, sense: str, Q: np.ndarray) -> np.ndarray:
    """The child's ``k``-th of ``m`` criteria (natural sign for ``sense``): joint values, no
    kinematics. In minimisation form the first ``m - 1`` are joints ``0 .. m - 2`` and
    the last is ``1 - `` their mean plus a tenth of the next joint, so the criteria
    conflict (most points are non-dominated, some dominated; the archive fills and is
    thinned, as on a real front); a single criterion is joint 0."""
    dof = Q.shape[1]
    if k < m - 1 or m == 1:
        f = Q[:, k % dof].copy()
    else:
        f = 1.0 - Q[:, [j % dof for j in range(m - 1)]].mean(axis=1) + 0.1 * Q[:, (m - 1) % dof]
    return f if sense == "min" else -f


class IdentityProjector(Projector):
    """A :class:`~moik.solver.pareto_search.Projector` whose projection keeps every point
    (no LM): with stand-in criteria the child's search calls the algorithm's and the
    archive's kernels and no kinematic one."""

    def _ends(self, target, X, flags: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        P = np.asarray(X, dtype=np.float64).reshape(-1, self.robot.dof)
        P = np.clip(P, self.robot.lower, self.robot.upper)
        return P, np.ones(len(P), dtype=bool), np.zeros(len(P))


def _child() -> None:
    """The child: the memetic search unprojected, on stand-in criteria, without the local
    search; then (its parent told, :func:`moik._background.ready`) the local search's
    joint distances and Jacobians and the built-in criteria on a few configurations."""
    search_problem, first, search, kinematic = _background.child_arguments()
    memetic_search(IdentityProjector(ParetoIK(**search_problem)), first,
                   np.random.default_rng(0), **{**search, "seed": 0})
    _background.ready()
    problem = ParetoIK(**kinematic)
    Q = problem.robot.random_q(4, rng=np.random.default_rng(0))
    # first what the parent needs last (the local search's starts and Jacobians): it is
    # compiling its first criteria when the child gets here, or soon after
    joint_distance(problem.robot, Q[0], Q)
    parts_and_jacobian(problem.robot, Q)
    problem.natural(Q)


if __name__ == "__main__":
    _child()
