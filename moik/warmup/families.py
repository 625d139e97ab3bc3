"""The kernel families of ``moik compile``, each named by a string and compiled by one
small workload of public calls (:data:`FAMILIES`, :func:`compile_family`).

A workload calls what a first use of that kind calls (a solve on a DH arm and on a URDF
chain, a Pareto solve, ...), so numba compiles and caches the same kernels for the same
argument types; ``moik compile`` (:mod:`moik.cli.kernels`) runs each in its own process.
"""

from __future__ import annotations

import contextlib
import io
import time
from collections.abc import Callable

import numpy as np
from pymoo.optimize import minimize

from moik import _jit
from moik.algorithms import available, get_algorithm
from moik.algorithms.registry import is_multi_objective
from moik.collision import Box, HalfSpace, Scene
from moik.exceptions import UnknownNameError
from moik.problems import BiObjectiveIK, PoseIK, random_reachable_targets
from moik.robots import Robot, get_robot
from moik.robots.transforms import translation
from moik.solver import solve_ik
from moik.solver.batch import solve_ik_batch
from moik.solver.pareto import solve_ik_pareto
from moik.solver.path import solve_path

ARMS = ("eosma7", "ur5")  # a DH arm and a URDF chain: two kinds of kinematic chain


def _solve(arm: Robot, targets) -> None:
    solve_ik(arm, targets[0].pose, n_solutions=2)
    arm.fk(targets[0].q_source)


def _solve_position(arm: Robot, targets) -> None:
    solve_ik(arm, targets[0].position)


def _unreachable(arm: Robot, targets) -> None:
    far = targets[0].position * (3.0 * arm.reach / np.linalg.norm(targets[0].position))
    pose = targets[0].pose.copy()
    pose[:3, 3] = far
    solve_ik(arm, far, max_evals=2000)
    solve_ik(arm, pose, max_evals=2000)


def _pareto(arm: Robot, targets) -> None:
    solve_ik_pareto(arm, targets[0].pose, objectives=("joint_motion", "manipulability"),
                    q_current=targets[1].q_source, n_solutions=5)
    solve_ik_pareto(arm, targets[0].position, objectives=("limit_margin", "orientation"),
                    rotation=targets[1].rotation, n_solutions=5)


def _batch_path(arm: Robot, targets) -> None:
    solve_ik_batch(arm, np.array([t.pose for t in targets]))
    solve_path(arm, [t.pose for t in targets])


def _collision(arm: Robot, targets) -> None:  # the start loop with a distance test
    # self pairs only: a set of bounds and hulls (CompoundSet); with a box, the exact
    # primitive kernels too (CollisionSet): the two types a first collision-aware use takes
    far = Box(size=(0.1, 0.1, 0.1), pose=translation(0.0, 0.0, -2.0 * arm.reach))
    for scene in (None, Scene({"table": HalfSpace.plane([0, 0, 1], -1.5 * arm.reach),
                               "box": far})):
        solve_ik(arm, targets[0].pose, self_collision=True, scene=scene)
        solve_ik_batch(arm, np.array([t.pose for t in targets]), self_collision=True,
                       scene=scene)


def _on_arms(workload: Callable[[Robot, list], None]) -> Callable[[], None]:
    def run() -> None:
        for name in ARMS:
            arm = get_robot(name)
            workload(arm, random_reachable_targets(arm, 3, seed=1))
    return run


def _algorithms(multi: bool) -> Callable[[], None]:
    def run() -> None:
        arm = get_robot("eosma7-m")
        target = random_reachable_targets(arm, 1, seed=1)[0]
        problem = BiObjectiveIK(arm, target) if multi else PoseIK(arm, target)
        for name in available():
            if is_multi_objective(name) == multi:
                minimize(problem, get_algorithm(name, pop_size=10), ("n_gen", 3), seed=1)
    return run


FAMILIES: dict[str, Callable[[], None]] = {
    "solve": _on_arms(_solve),
    "solve-position": _on_arms(_solve_position),
    "unreachable": _on_arms(_unreachable),
    "pareto": _on_arms(_pareto),
    "batch-path": _on_arms(_batch_path),
    "collision": _on_arms(_collision),
    "algorithms-single": _algorithms(False),
    "algorithms-multi": _algorithms(True),
}
"""Each family's workload, by name (``moik compile`` runs each in a process of its own)."""


def compile_family(name: str) -> tuple[str, float, int]:
    """Run the workload of family ``name``: ``(name, seconds, kernels compiled)`` (the
    kernels this process compiled so far, not loaded from the cache).

    Raises:
        UnknownNameError: ``name`` is not in :data:`FAMILIES`.
    """
    if name not in FAMILIES:
        raise UnknownNameError("kernel family", name, FAMILIES)
    t0 = time.perf_counter()
    with contextlib.redirect_stderr(io.StringIO()):  # the per-process notice: ours instead
        FAMILIES[name]()
    return name, time.perf_counter() - t0, _jit.compile_count()
