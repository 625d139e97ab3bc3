"""The memetic search of :func:`~moik.solver.pareto.solve_ik_pareto` on a redundant arm
(:func:`memetic_search`, the steps 1-3 of that module), and its kernels compiled in a
second process while the first stage runs (:func:`precompile`).

With an empty kernel cache, the first :func:`~moik.solver.pareto.solve_ik_pareto` of a
redundant arm compiles two independent families of kernels one after the other: the
Levenberg-Marquardt start loop of its projection (:mod:`moik.solver.starts`, about
half of the time) and the memetic search's (the multi-objective algorithm, the
criteria, the archive's fronts). numba compiles one kernel at a time in a process, so
where a second CPU is free :func:`precompile` runs the same search in a child process with
an identity projection instead of LM (the same problem and search parameters, hence
the same kernels and argument types, and no LM kernel): it writes the memetic kernels
to the cache while this process compiles the LM ones, and :meth:`Precompile.wait`
waits for it before this process's search, which then loads them
(``benchmarks/startup.py`` times the cold first ``--pareto`` solve).

It starts only where it can help: a memetic kernel is not cached yet, more than one
CPU is available to this process, and ``MOIK_BACKGROUND_COMPILE`` is not ``0``. The
child changes nothing but time: it draws nothing from the caller's seeds, calls no
criterion of the user's (a stand-in instead: the kernels are the same), and whatever
it did not write (it failed, or took longer than :data:`WAIT_LIMIT`) this process
compiles itself.
"""

from __future__ import annotations

import atexit
import os
import pickle
import subprocess
import sys
from collections.abc import Callable
from functools import partial
from pathlib import Path

import numpy as np

from moik import _jit
from moik.algorithms.archive.fronts import front_mask_2d
from moik.algorithms.moo.moeosma_kernels import generation_draws
from moik.kinematics.criteria import Criterion
from moik.problems.pareto_ik import ParetoIK
from moik.solver.pareto_local import local_search, local_search_starts
from moik.solver.pareto_search import Projector, mo_search

ORIENTATION_STARTS = 16  # LM ends of the random starts moved towards the preferred rotation
WAIT_LIMIT = 120.0  # seconds the search waits for the child at most
ENV_SWITCH = "MOIK_BACKGROUND_COMPILE"


class Precompile:
    """A running child process compiling the memetic kernels (from :func:`precompile`)."""

    def __init__(self, process: subprocess.Popen):
        self.process = process
        atexit.register(self._stop)

    def wait(self) -> None:
        """Wait for the child (at most :data:`WAIT_LIMIT` s; then it is stopped)."""
        try:
            self.process.wait(timeout=WAIT_LIMIT)
        except subprocess.TimeoutExpired:
            self._stop()

    def _stop(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()


def memetic_search(projector: Projector, first: np.ndarray, rng: np.random.Generator, *,
                   starts: int, method: str, pop_size: int, generations: int,
                   local_iterations: int, local_step: float, seed: int,
                   ready: Callable[[], None] | None = None) -> None:
    """Steps 1-3 of a redundant arm's search (module docstring): LM from ``first`` and
    ``starts`` random configurations (from ``rng``), the multi-objective ``method`` (seeded
    by ``seed``), the local search; every exact point enters ``projector``'s archive.
    ``ready`` is called between the LM starts and the first criteria (a background
    compilation of the search's kernels is waited for there)."""
    problem, robot = projector.problem, projector.robot
    P, ok, _ = projector.project(first, patient=True)
    Q, ok_q, _ = projector.project(robot.random_q(starts, rng=rng))
    exact = np.vstack([P[ok], Q[ok_q]])
    if problem.rotation is not None and "orientation" in problem.names:
        R, ok_r, _ = projector.project_via_pose(Q[:ORIENTATION_STARTS], problem.rotation)
        exact = np.vstack([exact, R[ok_r]])
    if ready is not None:
        ready()
    projector.objectives(exact)
    if generations:
        mo_search(projector, method, exact, pop_size=pop_size, generations=generations,
                  seed=seed)
    if local_iterations and len(projector.X):
        begin, weights = local_search_starts(projector)
        local_search(projector, begin, weights, iterations=local_iterations, step=local_step)


def _cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on every platform
        return os.cpu_count() or 1


def precompile(problem: ParetoIK, objectives, first: np.ndarray, search: dict
               ) -> Precompile | None:
    """Start compiling the memetic search's kernels in a child process, or return None
    where that cannot help (see the module docstring).

    Args:
        problem: The :class:`~moik.problems.pareto_ik.ParetoIK` problem of the search.
        objectives: Its criteria as given (names, :class:`Criterion` objects, callables);
            the child evaluates the built-in ones and a stand-in (a joint value) for
            every other: a user's function is never called there.
        first, search: The arguments :func:`memetic_search` will be given.
    """
    probes = [generation_draws] + ([front_mask_2d] if problem.n_obj <= 2 else [])
    if (os.environ.get(ENV_SWITCH) == "0" or _cpus() < 2
            or all(_jit.is_cached(kernel) for kernel in probes)):
        return None
    names = list(objectives) if isinstance(objectives, (list, tuple)) else [objectives]
    if len(names) != problem.n_obj:
        return None
    arguments = {"robot": problem.robot, "target": problem.target,
                 "q_current": problem.q_current, "rotation": problem.rotation,
                 "tol": (problem.tol_position, problem.tol_orientation),
                 "objectives": [item if isinstance(item, str) else
                                Criterion(problem.names[k], partial(joint_value, k),
                                          problem.senses[k])
                                for k, item in enumerate(names)]}
    try:
        payload = pickle.dumps((arguments, first, search))
    except Exception:  # noqa: BLE001 - a robot pickle cannot take: compile here
        return None
    root = str(Path(__file__).resolve().parents[2])  # where this moik is imported from
    env = {**os.environ, ENV_SWITCH: "0",
           "PYTHONPATH": os.pathsep.join(p for p in (root, os.environ.get("PYTHONPATH")) if p)}
    try:
        process = subprocess.Popen([sys.executable, "-m", __name__], stdin=subprocess.PIPE,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                   env=env)
        assert process.stdin is not None
        process.stdin.write(payload)
        process.stdin.close()
    except (OSError, ValueError):  # no interpreter to start, no pipe: compile here
        return None
    return Precompile(process)


def joint_value(k: int, Q: np.ndarray) -> np.ndarray:
    """The stand-in of a user's ``k``-th criterion in the child: joint ``k mod dof``."""
    return Q[:, k % Q.shape[1]].copy()


class IdentityProjector(Projector):
    """A :class:`~moik.solver.pareto_search.Projector` whose projection keeps every point
    (no LM): the child's search calls every kernel of the memetic search but LM's."""

    def _ends(self, ctx, X, flags: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        P = np.asarray(X, dtype=np.float64).reshape(-1, self.robot.dof)
        P = np.clip(P, self.robot.lower, self.robot.upper)
        return P, np.ones(len(P), dtype=bool), np.zeros(len(P))


def _child() -> None:
    """The child: the memetic search on the pickled problem (from stdin), unprojected."""
    problem, first, search = pickle.loads(sys.stdin.buffer.read())
    memetic_search(IdentityProjector(ParetoIK(**problem)), first, np.random.default_rng(0),
                   **{**search, "seed": 0})


if __name__ == "__main__":
    _child()
