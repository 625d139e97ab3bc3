"""``solve_path``: a sequence of targets solved with continuity.

Each target is first refined from the previous solution (a warm start keeps
the arm on the same branch); only if that fails, or the step would exceed
``max_step``, is the target solved globally with :func:`moik.solve.solve_ik`,
preferring the solution nearest the previous configuration. The largest joint
step along the path is reported, so a branch jump cannot pass unnoticed.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from moik.exceptions import ParameterError
from moik.kinematics.polish import polish, pose_errors
from moik.problems.targets import as_target, check_unit_range
from moik.robots.chain import Robot
from moik.solve import _tolerances, solve_ik


@dataclass(frozen=True)
class PathResult:
    """Outcome of :func:`solve_path`.

    Attributes:
        Q: Joint vectors ``(n, dof)``, all within the limits.
        position_errors: ``(n,)`` recomputed by FK (robot unit).
        orientation_errors: ``(n,)`` geodesic, rad (0 for position targets).
        success: ``(n,)`` both errors within tolerance.
        statuses: Per target ``"solved"``, ``"unreachable"`` or ``"not-converged"``.
        warm_started: ``(n,)`` whether the warm start alone solved the target.
        joint_steps: ``(n - 1,)`` largest absolute joint change between neighbours.
        max_joint_step: ``joint_steps.max()`` (0 for a single target).
        n_eval: FK evaluations in total.
        time: Wall time in seconds.
    """

    Q: np.ndarray
    position_errors: np.ndarray
    orientation_errors: np.ndarray
    success: np.ndarray
    statuses: tuple[str, ...]
    warm_started: np.ndarray
    joint_steps: np.ndarray
    max_joint_step: float
    n_eval: int
    time: float


def solve_path(robot: Robot, targets, *, q_start=None, max_step: float | None = None,
               seed=0, tol=1e-9, **solve_options) -> PathResult:
    """Solve a sequence of targets keeping the arm on one branch.

    Args:
        robot: The arm.
        targets: Sequence of targets (anything :func:`moik.problems.as_target` takes).
        q_start: Configuration before the first target (warm start and
            nearest-solution preference for it).
        max_step: Largest acceptable change of any joint between neighbouring
            targets; a warm-started solution beyond it is re-solved globally.
        seed: Base seed; target ``i`` uses ``SeedSequence(seed).spawn`` child ``i``.
        tol: As in :func:`moik.solve.solve_ik`.
        **solve_options: Passed to :func:`moik.solve.solve_ik` (not ``seed``,
            ``q_current``, ``n_solutions``).
    """
    t0 = time.perf_counter()
    targets = [as_target(t) for t in targets]
    if not targets:
        raise ParameterError("targets must hold at least one target")
    for target in targets:
        check_unit_range(target, robot)
    for key in ("seed", "q_current", "n_solutions"):
        if key in solve_options:
            raise ParameterError(f"solve_path sets {key!r} itself; do not pass it")
    if max_step is not None and not max_step > 0:
        raise ParameterError(f"max_step must be > 0, got {max_step!r}")
    tol_pos, tol_ori = _tolerances(tol, robot)
    prev = None if q_start is None else robot.check_q(q_start, "q_start")
    seeds = np.random.SeedSequence(seed).spawn(len(targets))
    Q, statuses, warm, n_eval = [], [], [], 0
    for i, target in enumerate(targets):
        q, status, used_warm = None, None, False
        if prev is not None:
            out = polish(robot, target, prev, length=robot.reach,
                         stop_position=1e-3 * tol_pos, stop_orientation=1e-3 * tol_ori)
            n_eval += out.n_eval
            pos, ori = (float(v[0]) for v in pose_errors(robot, target, out.q))
            step = float(np.max(np.abs(out.q - prev)))
            if pos <= tol_pos and ori <= tol_ori and (max_step is None or step <= max_step):
                q, status, used_warm = out.q, "solved", True
        if q is None:
            res = solve_ik(robot, target, q_current=prev, seed=seeds[i], tol=tol,
                           **solve_options)
            n_eval += res.n_eval
            q, status = res.q, res.status
        Q.append(q)
        statuses.append(status)
        warm.append(used_warm)
        prev = q
    Q = np.array(Q)
    pos_err, ori_err = pose_errors_all(robot, targets, Q)
    steps = np.max(np.abs(np.diff(Q, axis=0)), axis=1) if len(Q) > 1 else np.zeros(0)
    return PathResult(Q=Q, position_errors=pos_err, orientation_errors=ori_err,
                      success=(pos_err <= tol_pos) & (ori_err <= tol_ori),
                      statuses=tuple(statuses), warm_started=np.array(warm),
                      joint_steps=steps, max_joint_step=float(steps.max()) if steps.size else 0.0,
                      n_eval=n_eval, time=time.perf_counter() - t0)


def pose_errors_all(robot: Robot, targets, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Errors of ``Q[i]`` w.r.t. ``targets[i]``, recomputed by FK."""
    errs = [pose_errors(robot, t, q) for t, q in zip(targets, Q, strict=True)]
    return (np.array([e[0][0] for e in errs]), np.array([e[1][0] for e in errs]))
