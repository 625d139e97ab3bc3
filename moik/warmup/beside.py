"""Background families: kernels a child process compiles beside a cold first use
(:mod:`moik.warmup.background`), each named by a string (:data:`moik.warmup.BESIDE`; the
collision-aware solve's are in :mod:`moik.warmup.beside_collision`).

``"solve-leaves"``: a cold first :func:`~moik.solver.solve_ik.solve_ik` compiles the start
loop (:func:`~moik.solver.starts.run_starts`) as one tree, one kernel at a time, each
kernel's callees before it: first the FK and residual kernels, then the other leaves.
:func:`beside_solve` has a child compile those other leaves at the same time, each
called on a context and workspace of the numba types of the solve's: the damped step, the
re-check, the bookkeeping of found solutions and of the best candidate, the batch FK of
the final check and the compiled seeding of the random starts
(:func:`~moik.solver.start_streams.seed_state`). The ``moik`` command starts it before a
plain ``solve`` (a collision check makes the context another numba type).

``"front-leaves"``: a target proven out of reach (:func:`~moik.solver.front.reach_excess`)
runs no start loop: its cold first solve compiles the weighted-sum front
(:func:`~moik.solver.starts.lm_front`), then the batch FK of its polish and the joint
check of the answer. :func:`beside_solve` given such a target has the child compile only
the damped step, that batch FK and that check: on two CPUs a child compiling kernels the
parent never needs takes CPU time from it.

``"pareto-search"``: a cold first Pareto solve of a redundant arm
(:func:`~moik.solver.pareto.solve_ik_pareto`) compiles two independent families one
after the other: the kinematic kernels (the Levenberg-Marquardt start loop of its
projection, then the criteria and the local search's Jacobians, which share its FK
kernels) and those of its multi-objective algorithm and archive (:mod:`moik.algorithms`).
:func:`beside_pareto` has a child run the same algorithm (method, population,
generations, numbers of joints and criteria: the same kernels and argument types) on
stand-in criteria of plain numpy (:func:`stand_in`: no kinematic kernel), and the
archive's front masks; then the local search's joint distances and Jacobians and the
built-in criteria, which the parent needs last (and first, being small, the joint check
of the members). ``benchmarks/startup.py`` times the cold
first ``--pareto`` solve with and without it.

The child draws nothing from the caller's seeds and never calls a user's criterion
(only built-in ones, by name); whatever it has not cached when the parent needs it,
the parent compiles itself.
"""

from __future__ import annotations

import importlib
import inspect
from typing import Any

import numpy as np
from pymoo.core.problem import Problem

from moik.algorithms import get_algorithm
from moik.algorithms.archive.fronts import nondominated_mask
from moik.algorithms.registry import accepted_parameters
from moik.kinematics.criteria import CRITERIA, joint_distance
from moik.kinematics.jacobian import parts_and_jacobian
from moik.problems.pareto_ik import ParetoIK
from moik.problems.targets import Target, as_target
from moik.robots import Robot
from moik.solver.context import ik_context, lm_workspace
from moik.solver.front import reach_excess
from moik.solver.lm import LAMBDA0, damped_step
from moik.solver.options import STARTS_KEY
from moik.solver.pareto import solve_ik_pareto
from moik.solver.start_streams import seed_state
from moik.solver.starts import improve_best, keep_found, recheck
from moik.warmup import background

ARCHIVE_PROBE = "moik.algorithms.archive.fronts:front_mask_2d"  # two criteria (or one)
LEAF_PROBES = ("moik.solver.starts:run_starts", "moik.solver.lm:damped_step")
"""The start loop and a leaf the ``"solve-leaves"`` child writes: both cached, no child."""
FRONT_PROBES = ("moik.solver.starts:lm_front", "moik.solver.lm:damped_step")
"""The front's loop and a leaf the ``"front-leaves"`` child writes."""
METHOD_PROBES = {"moeosma": "moik.algorithms.moo.moeosma_kernels:generation_draws"}
"""A kernel of each algorithm whose compiled kernels the child writes (``module:name``):
a family all of whose probes are cached starts no child."""


def kernel(path: str) -> Any:
    """The kernel named ``"module:name"``."""
    module, name = path.split(":")
    return getattr(importlib.import_module(module), name)


def stand_in(k: int, m: int, Q: np.ndarray) -> np.ndarray:
    """The child's ``k``-th of ``m`` criteria (minimised): joint values, no kinematics. The
    first ``m - 1`` are joints ``0 .. m - 2`` and the last is ``1 -`` their mean plus a
    tenth of the next joint, so the criteria conflict (most points are non-dominated, some
    dominated: the archive fills and is thinned, as on a real front); a single criterion
    is joint 0."""
    dof = Q.shape[1]
    if k < m - 1 or m == 1:
        return Q[:, k % dof].copy()
    return 1.0 - Q[:, [j % dof for j in range(m - 1)]].mean(axis=1) + 0.1 * Q[:, (m - 1) % dof]


class StandInCriteria(Problem):
    """The search's problem as the algorithm sees it (``dof`` variables within the joint
    limits, ``max(m, 2)`` objectives: a single criterion is given twice) with
    :func:`stand_in` criteria."""

    def __init__(self, robot: Robot, m: int):
        self.m = m
        super().__init__(n_var=robot.dof, n_obj=max(m, 2), xl=robot.lower.copy(),
                         xu=robot.upper.copy(), vtype=float)

    def _evaluate(self, X, out, *args, **kwargs):
        F = np.column_stack([stand_in(k, self.m, X) for k in range(self.m)])
        out["F"] = F if F.shape[1] > 1 else np.hstack([F, F])


def beside_pareto(robot: Robot, target, **options: Any) -> background.Background | None:
    """Start the ``"pareto-search"`` child for ``solve_ik_pareto(robot, target, **options)``
    (module docstring), or return None where it cannot help: the arm is not redundant for
    the target (no search), its probes are cached, a switch or a single CPU
    (:mod:`moik.warmup.background`). ``options`` are checked by the solve, not here:
    options it would refuse start no child."""
    try:
        bound = inspect.signature(solve_ik_pareto).bind(robot, target, **options)
        goal = as_target(target)
    except Exception:  # noqa: BLE001 - the solve says what is wrong with them
        return None
    bound.apply_defaults()
    given = bound.arguments
    rows = 3 if goal.rotation is None else 6
    names = given["objectives"]
    names = [names] if isinstance(names, str) else list(names)
    if not isinstance(robot, Robot) or robot.dof <= rows or not names:
        return None
    probes = [kernel(path) for path in (
        ([ARCHIVE_PROBE] if len(names) <= 2 else [])
        + ([METHOD_PROBES[given["method"]]] if given["method"] in METHOD_PROBES else []))]
    arguments = {"robot": robot, "target": goal, "m": len(names),
                 "criteria": [n for n in names if isinstance(n, str) and n in CRITERIA],
                 "q_current": given["q_current"], "rotation": given["rotation"],
                 "method": given["method"], "pop_size": given["pop_size"],
                 "generations": given["generations"]}
    return background.start("pareto-search", arguments, probes)


def pareto_search(robot: Robot, target, m: int, criteria: list[str], q_current, rotation,
                  method: str, pop_size: int, generations: int) -> None:
    """The ``"pareto-search"`` child: the joint check, ``method`` on
    :class:`StandInCriteria`, the archive's masks, then the local search's distances and
    Jacobians and the built-in ``criteria``."""
    X0 = robot.random_q(pop_size, rng=np.random.default_rng(0))
    robot.check_q(X0)  # the members' joint check (a small kernel, needed last: ready early)
    params: dict[str, Any] = {"pop_size": pop_size}
    if "X0" in accepted_parameters(method):
        params["X0"] = X0
    algorithm = get_algorithm(method, **params)
    algorithm.setup(StandInCriteria(robot, m), termination=("n_gen", generations), seed=0)
    while algorithm.has_next():
        algorithm.next()
    nondominated_mask(np.column_stack([stand_in(k, m, X0) for k in range(m)]))  # the archive
    Q = robot.random_q(4, rng=np.random.default_rng(0))
    joint_distance(robot, Q[0], Q)
    parts_and_jacobian(robot, Q)
    if criteria:
        ParetoIK(robot, target, objectives=criteria, q_current=q_current,
                 rotation=rotation).natural(Q)


def beside_solve(robot: Robot, target=None) -> background.Background | None:
    """Start the child for a first plain solve of ``robot`` (module docstring):
    ``"front-leaves"`` for a ``target`` proven out of reach, else ``"solve-leaves"``; or
    return None where it cannot help (the leaves are cached, a switch or a single CPU:
    :mod:`moik.warmup.background`). A target the solve would refuse starts no child."""
    if not isinstance(robot, Robot):
        return None
    try:
        beyond = target is not None and reach_excess(robot, as_target(target)) > 0
    except Exception:  # noqa: BLE001 - the solve says what is wrong with it
        return None
    family, probes = ("front-leaves", FRONT_PROBES) if beyond else ("solve-leaves", LEAF_PROBES)
    return background.start(family, {"robot": robot}, [kernel(path) for path in probes])


def _stand_in_start(robot: Robot) -> tuple[Any, Any, np.ndarray]:
    """A context and workspace of the numba types a plain solve's have (any target: the
    types do not depend on it), and a joint vector to call the leaves at."""
    ctx = ik_context(robot, Target(np.zeros(3), np.eye(3)), stop=(0.0, 0.0), tol=(0.0, 0.0),
                     distinct=0.1)
    q = np.ascontiguousarray((robot.lower + robot.upper) / 2.0, dtype=np.float64)
    return ctx, lm_workspace(robot.dof), q


def solve_leaves(robot: Robot) -> None:
    """The ``"solve-leaves"`` child: each leaf called once, in the order a solve needs them."""
    ctx, ws, q = _stand_in_start(robot)
    damped_step(ctx, ws, LAMBDA0, q)
    recheck(ctx, ws, q)
    keep_found(ctx, ws, np.full((1, robot.dof + 2), np.nan), 0, q)
    improve_best(ctx, ws, np.full(robot.dof + 1, np.inf), q)
    robot.fk_parts(q[None])
    seed_state(0, STARTS_KEY)


def front_leaves(robot: Robot) -> None:
    """The ``"front-leaves"`` child: the damped step on a context of the front's numba
    types, the batch FK of its polish and the answer's joint check."""
    ctx, ws, q = _stand_in_start(robot)
    damped_step(ctx, ws, LAMBDA0, q)
    robot.fk_parts(q[None])
    robot.check_q(q)
