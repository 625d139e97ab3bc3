"""The start loop of one collision-aware solve, its collision test called between compiled runs.

:func:`~moik.solver.starts.run_starts` on a context with a collision set tests each exact
end in the same compiled call. That start loop links the whole distance-kernel tree (GJK
on the hulls, the pairs' bounds): numba compiles and optimises that tree once more inside
the loop, seconds of a cold first collision-aware solve that nothing else needs.
:func:`run_tested_starts` gives the same answers with the loop of a plain solve (a
context without a check: the kernel a plain solve compiles) and the compiled distance
test (:func:`~moik.collision.kernels.distance_below`, which a background child compiles
meanwhile: :mod:`moik.warmup.beside_collision`) called from Python between its runs: each
run stops at its first new solution (its ``found`` table one row longer than the known ones), whose
distance then decides whether it stays. Used by :func:`~moik.solver.solve_ik.solve_ik`
(one target: a Python call per new solution costs microseconds); the batch keeps the
compiled test inside its loop (:func:`~moik.solver.starts.run_batch`).

Where the compiled loop with the test inside is at hand (compiled in this process or cached:
after a collision-aware batch, ``moik compile``, a warm run), :func:`run_collision_starts`
calls it: a start whose end collides costs no return to Python there, which counts where
most ends collide (measured on ur5 with a table, a box and a ball, 60 targets of which
most collide: a median solve about 1.3x as long from Python). Both give the same answers.

Same bookkeeping as the compiled loop, to the bit (tests/solver/test_tested_starts.py): the
same ends, evaluations, solutions, best candidate and distances of the ends that passed
the pose test (those that do not keep the clearance are not solutions).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from moik import _jit
from moik.collision.kernels import distance_below, distance_scratch
from moik.solver.context import lm_workspace
from moik.solver.starts import improve_best, recheck, run_starts, solution_cost


def run_tested_starts(ctx, cs, clearance: float, starts: np.ndarray, policy: tuple[int, int],
                      found: np.ndarray, best: np.ndarray, ends: np.ndarray
                      ) -> tuple[int, int, int]:
    """:func:`~moik.solver.starts.run_starts` with :data:`~moik.solver.starts.CHECK` on a
    context of the collision set ``cs`` and ``clearance``, run as the module docstring says.

    Args:
        ctx: The solve's context *without* a collision set (a plain solve's type).
        cs: The compiled collision set (:attr:`~moik.collision.CollisionChecker.compiled`),
            with at least one pair.
        clearance: Smallest signed distance of a solution (robot unit).
        starts, policy, found, best, ends: As :func:`~moik.solver.starts.run_starts` takes
            them (``policy`` with :data:`~moik.solver.starts.CHECK`).

    Returns:
        ``(n_found, n_eval, n_used)``, as :func:`~moik.solver.starts.run_starts`.
    """
    flags, budget = policy  # CHECK is set: every end that may be a solution is re-checked
    n, dof = starts.shape
    want = found.shape[0]
    ws, scratch = lm_workspace(dof), distance_scratch(cs)
    tol_cost = solution_cost(ctx)
    n_known = 0
    while n_known < want and not np.isnan(found[n_known, 0]):
        n_known += 1
    n_found, n_eval, used, low, low_cost = n_known, 0, 0, -1, np.inf
    ignored = np.full(dof + 1, -np.inf)  # the runs' own best: never replaced
    while used < n and n_found < want and n_eval < budget:
        n_run, n_eval_run, n_used = run_starts(ctx, starts[used:], (flags, budget - n_eval),
                                               found[:n_found + 1], ignored, ends[used:])
        n_eval += int(n_eval_run)
        if n_used == 0:
            break
        for s in range(used, used + n_used):
            q, cost = starts[s], ends[s, 1]
            if cost < low_cost:
                low, low_cost = s, cost
            if not ((ends[s, 0] != 0.0 or cost <= tol_cost) and recheck(ctx, ws, q)):
                continue
            _jit.await_elsewhere(distance_below)  # a cold first use: a child compiles it
            ends[s, 2] = distance_below(cs, q, scratch, clearance)[0]
        used += n_used
        if n_run > n_found:  # its last start's end is new: a solution if it keeps clearance
            if ends[used - 1, 2] >= clearance:
                n_found = n_run
                improve_best(ctx, ws, best, starts[used - 1])  # ws.err: its re-check
            else:
                found[n_found] = np.nan
    if low >= 0 and n_found == n_known:
        recheck(ctx, ws, starts[low])
        improve_best(ctx, ws, best, starts[low])
    return n_found, n_eval, used


_LOOP_SIGNATURES: dict[type, tuple] = {}  # the loop's argument types, per collision set type
_ON_DISK: dict[type, bool] = {}  # whether the kernel cache held that loop (read once)


def run_collision_starts(ctx, collision_ctx: Callable[[], Any], cs, clearance: float,
                         starts: np.ndarray, policy: tuple[int, int], found: np.ndarray,
                         best: np.ndarray, ends: np.ndarray) -> tuple[int, int, int]:
    """One solve's collision-aware start loop: :func:`~moik.solver.starts.run_starts` on
    ``collision_ctx()`` (the context with ``cs`` and ``clearance``, built when needed) where
    that compiled loop is at hand (module docstring), else :func:`run_tested_starts` on
    ``ctx`` (the context without a check): the same answers either way."""
    if not hasattr(run_starts, "typeof_pyval"):  # NUMBA_DISABLE_JIT: every kernel is Python
        return run_starts(collision_ctx(), starts, policy, found, best, ends)
    kind = type(cs)
    signature = _LOOP_SIGNATURES.get(kind)
    if signature is None:
        args = (collision_ctx(), starts, policy, found, best, ends)
        signature = _LOOP_SIGNATURES[kind] = tuple(run_starts.typeof_pyval(a) for a in args)
    if loop_at_hand(kind, signature):
        return run_starts(collision_ctx(), starts, policy, found, best, ends)
    return run_tested_starts(ctx, cs, clearance, starts, policy, found, best, ends)


def loop_at_hand(kind: type, signature: tuple) -> bool:
    """Whether :func:`~moik.solver.starts.run_starts` for ``signature`` (a context with a
    collision set of class ``kind``) is compiled in this process, or was in the kernel
    cache when this process first asked (read once per process: a per-call read of the
    cache's index would cost a tenth of a millisecond)."""
    if kind not in _ON_DISK:
        _ON_DISK[kind] = _jit.is_cached_for(run_starts, signature)
    return _ON_DISK[kind] or signature in run_starts.overloads
