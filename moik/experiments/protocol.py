"""The EOSMA paper's solving protocol: re-run until solved, at most 10 failures.

Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3, section
"Results obtained for scenario 1": a run counts as solved when its best error is
below a threshold; otherwise the algorithm solves again, until the maximum
number of failures (10 for every algorithm) is reached. The paper prints the
threshold as "10e-6"; read as 10^-6 (``threshold=1e-6``), the value the other
numbers of the paper are compared with.

Reading of "maximum number of failures": at most ``max_failures`` runs in all;
the protocol stops at the first solved run. Every run gets a fresh seed spawned
from one ``numpy.random.SeedSequence``, so the whole protocol is reproducible
from a single seed.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.problem import Problem
from pymoo.core.result import Result
from pymoo.optimize import minimize

from moik._validate import integer
from moik.exceptions import ParameterError


@dataclass
class ProtocolResult:
    """Outcome of :func:`solve_until_success`.

    Attributes:
        best: pymoo ``Result`` of the run with the lowest best f.
        solved: Whether a run reached ``f < threshold``.
        attempts: Number of runs made (1 to ``max_failures``).
        total_time: Wall-clock seconds of all runs together.
        best_f: Best objective value over all runs (inf if none was feasible).
        run_f: Best f of each run, in order.
        seeds: The integer seed of each run, in order.
    """

    best: Result
    solved: bool
    attempts: int
    total_time: float
    best_f: float
    run_f: list[float] = field(default_factory=list)
    seeds: list[int] = field(default_factory=list)


def _best_f_of(res: Result) -> float:
    if res.F is None:
        return float("inf")
    return float(np.min(res.F))


def solve_until_success(problem: Problem, algorithm_factory: Callable[[], Algorithm],
                        termination, *, seed: int | np.random.SeedSequence | None,
                        threshold: float = 1e-6, max_failures: int = 10) -> ProtocolResult:
    """Solve ``problem`` the paper's way: re-run with fresh seeds until ``f < threshold``.

    Args:
        problem: A single-objective pymoo problem (e.g. ``PositionIK``).
        algorithm_factory: Returns a fresh algorithm for each run (e.g.
            ``lambda: EOSMA.scenario(1)``).
        termination: pymoo termination of each run (e.g. ``("n_gen", 500)``).
        seed: Root seed; run k uses the k-th child of ``SeedSequence(seed)``.
        threshold: A run is solved when its best f is below this (paper: 1e-6).
        max_failures: Most runs in all (paper: 10).

    Returns:
        The best run, whether it solved, the number of runs and the total time.

    Raises:
        ParameterError: For a non-positive threshold or max_failures, or a
            factory that does not return a pymoo ``Algorithm``.
    """
    if not (np.isfinite(threshold) and threshold > 0):
        raise ParameterError(f"threshold must be a finite number > 0, got {threshold!r}")
    max_failures = integer("max_failures", max_failures, minimum=1)
    root = seed if isinstance(seed, np.random.SeedSequence) else np.random.SeedSequence(seed)
    children = root.spawn(max_failures)
    best, best_f, run_f, seeds = None, float("inf"), [], []
    start = time.perf_counter()
    for child in children:
        algorithm = algorithm_factory()
        if not isinstance(algorithm, Algorithm):
            raise ParameterError("algorithm_factory must return a pymoo Algorithm, got "
                                 f"{type(algorithm).__name__}")
        run_seed = int(child.generate_state(1, dtype=np.uint32)[0])
        res = minimize(problem, algorithm, termination, seed=run_seed, copy_algorithm=False)
        f = _best_f_of(res)
        run_f.append(f)
        seeds.append(run_seed)
        if best is None or f < best_f:
            best, best_f = res, f
        if f < threshold:
            break
    total = time.perf_counter() - start
    return ProtocolResult(best=best, solved=best_f < threshold, attempts=len(run_f),
                          total_time=total, best_f=best_f, run_f=run_f, seeds=seeds)
