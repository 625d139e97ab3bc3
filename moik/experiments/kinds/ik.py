"""IK experiments: inverse kinematics of a catalog or URDF robot at a set of targets.

Config keys (see :mod:`moik.experiments.config` for the others):

- ``robot``: catalog name, or a URDF arm ``{urdf = "FILE", package_dirs = [...],
  base_link = "...", tip_link = "..."}`` (:mod:`moik.experiments.kinds.ik_robot`);
- ``problem``: ``{"kind": "position" | "pose" | "bi-objective", "orientation":
  metric, "weights": [w1, w2], "displacement_weight": w, "q_start_deg": [...],
  "locked_joints_deg": [...], "joint_limits_deg": [[lo, hi], ...]}``; the kinds map
  to :class:`~moik.problems.PositionIK`, :class:`~moik.problems.PoseIK` and
  :class:`~moik.problems.BiObjectiveIK`;
- ``targets``: ``{"kind": "random", "n", "seed", "with_orientation", "orientation"}``,
  ``{"kind": "fixed", "points": [{"name", "position" or "fk_q_deg",
  "euler_deg", "convention", "hv_ref_point", "robot"}]}`` or ``{"kind": "circle",
  "center", "radius", "n_points", "euler_deg", "convention"}``.

Joint values in configs are degrees (``q_start_deg``, ``fk_q_deg``); lengths are
in the robot's unit. MO-m-PSO Section 4.4 ("alpha = 0, beta = 0, gamma is free")
uses the named metric ``"zyx-euler-free-gamma"`` of :mod:`moik.kinematics.orientation`.
``locked_joints_deg`` (one entry per joint, ``"free"`` (or ``None``) for a free joint) fixes
joints with :meth:`~moik.robots.Robot.with_locked_joints` (I-BES Table 9 solves
the Puma 560 position with joints 4-6 at 0); a fixed target point may name its
own ``robot`` (a catalog name; I-BES Table 8: one target per arm), else the experiment's
is used.
``joint_limits_deg`` (one ``[lower, upper]`` pair per joint) replaces the
arm's limits before any joint is locked (MO-m-PSO Section 4.4 run with and without
Table 1's servo ranges). Random targets take FK poses of random joint vectors
(``"orientation": "reachable"``, the default) or FK positions with rotations drawn
uniformly on SO(3), independent of the position (``"independent"``, from the
generator seeded ``[seed, 1]``; MO-m-PSO Section 4.3 reads "each point is
associated with a random orientation").

The targets are parsed and built in :mod:`moik.experiments.kinds.ik_targets`.
Validation builds what a run uses: the robots, every target (a
:class:`~moik.problems.Target`, validated once and carried to the trials as it
is) and the pymoo problem at every target; a :class:`~moik.exceptions.MoikError`
raised there becomes a :class:`~moik.exceptions.ConfigError` naming the key.

A trial records ``best_f``/``position_error``/``orientation_error``/``best_x``
(and ``attempts``/``solved`` under the protocol, ``joint_distance_deg`` with a
start configuration) for single-objective problems; the compromise's errors,
``n_front`` and ``hv`` for bi-objective ones. Its arrays are ``convergence`` or
``front_F``/``front_X``, and ``best_x``.
"""

from __future__ import annotations

import json
import time
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
from pymoo.optimize import minimize

from moik.algorithms import get_algorithm
from moik.exceptions import ConfigError, MoikError
from moik.experiments.checks import check_keys, number, numbers
from moik.experiments.convergence import algorithm_factory, convergence_curve
from moik.experiments.kinds.ik_collision import COLLISION_KEYS, feasibility, with_collision
from moik.experiments.kinds.ik_robot import arm, check_robot, experiment_robot, locked, resolve
from moik.experiments.kinds.ik_targets import NamedTarget, build_targets
from moik.experiments.protocol import solve_until_success
from moik.experiments.spec import TrialSpec
from moik.kinematics.orientation import orientation_metric
from moik.metrics import closest_to_utopia, hypervolume
from moik.problems import BiObjectiveIK, PoseIK, PositionIK
from moik.robots import Robot

PROBLEM_KINDS = ("position", "pose", "bi-objective")
MULTI_OBJECTIVE = ("bi-objective",)
"""The problem kinds of this module whose algorithms are multi-objective."""
_PROBLEM_KEYS = {"kind", "orientation", "weights", "displacement_weight", "q_start_deg",
                 "locked_joints_deg", "joint_limits_deg", *COLLISION_KEYS}


def build_problem(robot: Robot, problem: Mapping, target: NamedTarget):
    """The pymoo problem of ``problem`` (the config dict) at ``target``."""
    common = {"displacement_weight": float(problem.get("displacement_weight", 0.0))}
    if "q_start_deg" in problem:
        common["q_start"] = np.radians(problem["q_start_deg"])
    kind = problem["kind"]
    if kind == "position":
        ik = PositionIK(robot, target.target, **common)
    elif kind == "pose":
        ik = PoseIK(robot, target.target, weights=tuple(problem.get("weights", (0.5, 0.5))),
                    orientation=problem["orientation"], **common)
    else:
        ik = BiObjectiveIK(robot, target.target, orientation=problem["orientation"], **common)
    return with_collision(ik, problem)


def check_config(where: str, cfg: dict, folder: Path) -> tuple[dict, tuple[NamedTarget, ...]]:
    """Validate an IK experiment's robot, problem and targets by building them.

    ``cfg["robot"]`` is replaced by its checked form (a URDF robot gains its ``sha256``:
    :func:`~moik.experiments.kinds.ik_robot.check_robot`; its paths are read from
    ``folder``).

    Returns:
        The problem dict (``orientation`` defaulted to ``"geodesic"``) and the targets.

    Raises:
        ConfigError: Naming the key and what was expected.
    """
    if "robot" not in cfg or "targets" not in cfg or "requires" in cfg:
        raise ConfigError(f"{where}: an IK experiment needs 'robot' and 'targets' (and takes "
                          "no 'requires')")
    problem = _check_problem(f"{where}: problem", cfg["problem"])
    if isinstance(problem.get("locked_joints_deg"), list):  # TOML has no null: "free"
        problem["locked_joints_deg"] = [None if v == "free" else v
                                        for v in problem["locked_joints_deg"]]
    cfg["robot"] = check_robot(f"{where}: robot", cfg["robot"], folder)
    robots: dict[str, Robot] = {}  # the robot value -> the arm with the locked joints, built once

    def robot_of(value: Any, key: str) -> Robot:
        if isinstance(value, Mapping) and value is not cfg["robot"]:
            raise ConfigError(f"{key} must be a catalog robot's name (a URDF arm is the "
                              f"experiment's robot), got a table")
        name = json.dumps(value, sort_keys=True)
        if name not in robots:
            try:
                loaded = arm(resolve(value, folder))
            except MoikError as exc:
                raise ConfigError(f"{key}: {exc}") from None
            _check_locked_joints(f"{where}: problem", problem, loaded.dof)
            try:
                robots[name] = locked(loaded, problem)
            except MoikError as exc:
                key = "locked_joints_deg" if "locked_joints_deg" in problem else "joint_limits_deg"
                raise ConfigError(f"{where}: problem.{key}: {exc}") from None
        return robots[name]

    robot = robot_of(cfg["robot"], f"{where}: robot")
    if "q_start_deg" in problem:
        numbers(f"{where}: problem.q_start_deg", problem["q_start_deg"], robot.dof)
    targets = build_targets(f"{where}: targets", cfg["targets"], problem, robot, robot_of)
    for t in targets:
        try:
            build_problem(robot_of(t.robot or cfg["robot"], f"{where}: robot"), problem, t)
        except MoikError as exc:
            raise ConfigError(f"{where}: problem (at target {t.name!r}): {exc}") from None
    return problem, tuple(targets)


def _check_problem(where: str, spec: Any) -> dict:
    p = check_keys(where, spec, _PROBLEM_KEYS, ("kind",))
    if p["kind"] not in PROBLEM_KINDS:
        raise ConfigError(f"{where}.kind must be one of {', '.join(PROBLEM_KINDS)}, "
                          f"got {p['kind']!r}")
    p.setdefault("orientation", "geodesic")
    try:
        orientation_metric(p["orientation"])
    except MoikError as exc:
        raise ConfigError(f"{where}.orientation: {exc}") from None
    if "weights" in p:
        numbers(f"{where}.weights", p["weights"], 2)
    number(f"{where}.displacement_weight", p.get("displacement_weight", 0.0))
    return p


def _check_locked_joints(where: str, p: Mapping, dof: int) -> None:
    """``locked_joints_deg``: one entry per joint of the arm, a number or None."""
    if "locked_joints_deg" in p:
        lj = p["locked_joints_deg"]
        if not isinstance(lj, list) or len(lj) != dof:
            raise ConfigError(f"{where}.locked_joints_deg must be a list of {dof} entries "
                              f"(a number, or \"free\" for a free joint), got {lj!r}")
        for i, v in enumerate(lj):
            if v is not None:
                number(f"{where}.locked_joints_deg[{i}]", v)
    if "joint_limits_deg" in p:
        lim = p["joint_limits_deg"]
        if not isinstance(lim, list) or len(lim) != dof:
            raise ConfigError(f"{where}.joint_limits_deg must be a list of {dof} [lower, upper] "
                              f"pairs, got {lim!r}")
        for i, pair in enumerate(lim):
            numbers(f"{where}.joint_limits_deg[{i}]", pair, 2)


def run_trial(spec: TrialSpec, record: dict, arrays: dict) -> None:
    """Run one IK trial; fills ``record`` and ``arrays`` (see the module docstring)."""
    # an IK trial names its robot and carries a NamedTarget (moik.experiments.trials)
    assert spec.robot is not None and isinstance(spec.target, NamedTarget)
    robot = experiment_robot(spec.robot, spec.problem)
    problem = build_problem(robot, spec.problem, spec.target)
    if problem.n_obj == 1:
        _single_objective(spec, problem, record, arrays)
    else:
        _multi_objective(spec, problem, record, arrays)


def _single_objective(spec: TrialSpec, problem, record: dict, arrays: dict) -> None:
    created: list = []
    factory = algorithm_factory(spec, created)
    termination = ("n_gen", spec.iterations + 1)  # the initial population is generation 1
    t0 = time.perf_counter()
    if spec.protocol is not None:
        out = solve_until_success(problem, factory, termination, seed=spec.seed_sequence,
                                  threshold=spec.protocol["threshold"],
                                  max_failures=spec.protocol["max_failures"])
        res, elapsed = out.best, out.total_time
        record.update(attempts=out.attempts, solved=bool(out.solved), run_f=out.run_f,
                      run_seeds=out.seeds)
    else:
        res = minimize(problem, factory(), termination, seed=spec.seed, copy_algorithm=False)
        elapsed = time.perf_counter() - t0
    x = np.asarray(res.X, dtype=float).reshape(-1) if res.X is not None else None
    record.update(time=elapsed, n_eval=int(sum(a.evaluator.n_eval for a in created)),
                  best_f=float(np.min(res.F)) if res.F is not None else float("inf"))
    if x is not None:
        record["best_x"] = x.tolist()
        if hasattr(problem, "errors"):
            pos, ori = problem.errors(x[None])
            record.update(position_error=float(pos[0]), orientation_error=float(ori[0]))
        else:
            record["position_error"] = float(problem.position_error(x[None])[0])
        if problem.q_start is not None:
            record["joint_distance_deg"] = float(np.linalg.norm(np.degrees(x - problem.q_start)))
        arrays["best_x"] = x
    arrays["convergence"] = convergence_curve(res.algorithm)
    if spec.record_history and hasattr(res.algorithm, "best_x_history"):
        arrays["best_x_history"] = res.algorithm.best_x_history


def _multi_objective(spec: TrialSpec, problem, record: dict, arrays: dict) -> None:
    algorithm = get_algorithm(spec.algorithm, **spec.params)
    t0 = time.perf_counter()
    res = minimize(problem, algorithm, ("n_gen", spec.iterations + 1), seed=spec.seed,
                   copy_algorithm=False)
    elapsed = time.perf_counter() - t0
    F = np.atleast_2d(np.asarray(res.F, dtype=float))
    X = np.atleast_2d(np.asarray(res.X, dtype=float))
    i = closest_to_utopia(F)
    record.update(time=elapsed, n_eval=int(algorithm.evaluator.n_eval), n_front=int(len(F)),
                  position_error=float(F[i, 0]), orientation_error=float(F[i, 1]),
                  min_position_error=float(F[:, 0].min()),
                  min_orientation_error=float(F[:, 1].min()), best_x=X[i].tolist())
    target = spec.target
    assert isinstance(target, NamedTarget)  # an IK trial's target (run_trial)
    feasible = feasibility(problem, X, record)
    if target.hv_ref_point is not None:
        record["hv"] = hypervolume(F[feasible], target.hv_ref_point) if feasible.any() else 0.0
    arrays.update(front_F=F, front_X=X, best_x=X[i])
