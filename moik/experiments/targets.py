"""The problem and target parts of an experiment configuration: checks and builders.

Problem kinds map to :mod:`moik.problems` classes: ``"position"`` ->
:class:`~moik.problems.PositionIK`, ``"pose"`` -> :class:`~moik.problems.PoseIK`,
``"bi-objective"`` -> :class:`~moik.problems.BiObjectiveIK`. Joint values in
configs are degrees (``q_start_deg``, ``fk_q_deg``); lengths are in the robot's unit.

MO-m-PSO Section 4.4 ("alpha = 0, beta = 0, gamma is free") uses the named metric
``"zyx-euler-free-gamma"`` of :mod:`moik.kinematics.orientation`.

``locked_joints_deg`` (one entry per joint, ``None`` for a free joint) fixes
joints with :meth:`~moik.robots.Robot.with_locked_joints` (I-BES Table 9 solves
the Puma 560 position with joints 4-6 at 0); a fixed target point may name its
own ``robot`` (I-BES Table 8: one target per arm), else the experiment's is used.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from moik.exceptions import ConfigError, MoikError

PROBLEM_KINDS = ("position", "pose", "bi-objective")
TARGET_KINDS = ("random", "fixed", "circle")
_PROBLEM_KEYS = {"kind", "orientation", "weights", "displacement_weight", "q_start_deg",
                 "locked_joints_deg"}
_TARGET_KEYS = {
    "random": {"kind", "n", "seed", "with_orientation"},
    "fixed": {"kind", "points"},
    "circle": {"kind", "center", "radius", "n_points", "euler_deg", "convention"},
}
_POINT_KEYS = {"name", "position", "fk_q_deg", "euler_deg", "convention", "hv_ref_point",
               "robot"}


def _vec(where: str, value: Any, n: int) -> list[float]:
    from moik.experiments.config import check_float

    if not isinstance(value, (list, tuple)) or len(value) != n:
        raise ConfigError(f"{where} must be a list of {n} numbers, got {value!r}")
    return [check_float(f"{where}[{i}]", v) for i, v in enumerate(value)]


def check_problem(where: str, spec: Any, robot_name: str) -> dict:
    """Validate the ``problem`` dict; returns it with defaults filled in."""
    from moik.experiments.config import check_float, check_keys
    from moik.kinematics.orientation import available_metrics
    from moik.robots import get_robot

    p = check_keys(where, spec, _PROBLEM_KEYS, ("kind",))
    if p["kind"] not in PROBLEM_KINDS:
        raise ConfigError(f"{where}.kind must be one of {', '.join(PROBLEM_KINDS)}, "
                          f"got {p['kind']!r}")
    p.setdefault("orientation", "geodesic")
    if p["orientation"] not in available_metrics():
        raise ConfigError(f"{where}.orientation: unknown metric {p['orientation']!r}; expected "
                          f"one of: {', '.join(available_metrics())}")
    if "weights" in p:
        _vec(f"{where}.weights", p["weights"], 2)
    w = check_float(f"{where}.displacement_weight", p.get("displacement_weight", 0.0))
    robot = get_robot(robot_name)
    if "locked_joints_deg" in p:
        lj = p["locked_joints_deg"]
        if not isinstance(lj, list) or len(lj) != robot.dof:
            raise ConfigError(f"{where}.locked_joints_deg must be a list of {robot.dof} entries "
                              f"(a number or None per joint), got {lj!r}")
        for i, v in enumerate(lj):
            if v is not None:
                check_float(f"{where}.locked_joints_deg[{i}]", v)
        try:
            robot = experiment_robot(robot_name, p)
        except MoikError as exc:
            raise ConfigError(f"{where}.locked_joints_deg: {exc}") from None
    if w < 0:
        raise ConfigError(f"{where}.displacement_weight must be >= 0, got {w}")
    if w > 0 and "q_start_deg" not in p:
        raise ConfigError(f"{where}: displacement_weight > 0 needs q_start_deg")
    if "q_start_deg" in p:
        _vec(f"{where}.q_start_deg", p["q_start_deg"], robot.dof)
    return p


def check_targets(where: str, spec: Any, problem: Mapping) -> None:
    """Validate the ``targets`` dict (orientation required unless ``position`` problems)."""
    from moik.experiments.config import check_float, check_int, check_keys

    kind = spec.get("kind") if isinstance(spec, Mapping) else None
    if kind not in TARGET_KINDS:
        raise ConfigError(f"{where}.kind must be one of {', '.join(TARGET_KINDS)}, got {kind!r}")
    t = check_keys(where, spec, _TARGET_KEYS[kind], ("kind",))
    oriented = problem["kind"] != "position"
    if kind == "random":
        check_int(f"{where}.n", t.get("n"), 1)
        check_int(f"{where}.seed", t.get("seed"), 0)
        if oriented and not t.get("with_orientation", True):
            raise ConfigError(f"{where}: problem kind {problem['kind']!r} needs "
                              "with_orientation true")
    elif kind == "circle":
        _vec(f"{where}.center", t.get("center"), 3)
        check_float(f"{where}.radius", t.get("radius"), positive=True)
        check_int(f"{where}.n_points", t.get("n_points"), 2)
        if oriented or "euler_deg" in t:
            _vec(f"{where}.euler_deg", t.get("euler_deg"), 3)
    else:
        points = t.get("points")
        if not isinstance(points, list) or not points:
            raise ConfigError(f"{where}.points must be a non-empty list")
        for i, raw in enumerate(points):
            w = f"{where}.points[{i}]"
            pt = check_keys(w, raw, _POINT_KEYS, ("name",))
            _check_point_robot(w, pt)
            if ("position" in pt) == ("fk_q_deg" in pt):
                raise ConfigError(f"{w}: give exactly one of position and fk_q_deg")
            if "position" in pt:
                _vec(f"{w}.position", pt["position"], 3)
                if oriented and "euler_deg" not in pt:
                    raise ConfigError(f"{w}: problem kind {problem['kind']!r} needs euler_deg")
            if "euler_deg" in pt:
                _vec(f"{w}.euler_deg", pt["euler_deg"], 3)
            if "hv_ref_point" in pt:
                _vec(f"{w}.hv_ref_point", pt["hv_ref_point"], 2)


def _check_point_robot(where: str, pt: Mapping) -> None:
    from moik.robots import available_robots

    if "robot" in pt and pt["robot"] not in available_robots():
        raise ConfigError(f"{where}.robot: unknown robot {pt['robot']!r}; expected one of: "
                          f"{', '.join(available_robots())}")


def experiment_robot(name: str, problem: Mapping):
    """The catalog robot ``name`` with the problem's ``locked_joints_deg`` applied."""
    from moik.robots import get_robot

    robot = get_robot(name)
    locked = problem.get("locked_joints_deg")
    if locked:
        robot = robot.with_locked_joints({i: float(np.radians(v)) for i, v in enumerate(locked)
                                          if v is not None})
    return robot


@dataclass(frozen=True)
class NamedTarget:
    """A target of an experiment with its display name and optional HV reference point.

    ``robot`` names the arm of this target when it is not the experiment's.
    """

    name: str
    position: list[float]
    rotation: list[list[float]] | None
    hv_ref_point: list[float] | None = None
    robot: str | None = None

    def as_dict(self) -> dict:
        """JSON-ready form (floats round-trip exactly through ``json``)."""
        d = {"name": self.name, "position": self.position, "rotation": self.rotation,
             "hv_ref_point": self.hv_ref_point}
        return d if self.robot is None else {**d, "robot": self.robot}


def _rotation(spec: Mapping, default_convention: str = "zyx-euler") -> np.ndarray:
    from moik.problems.targets import Target

    t = Target.from_euler([0.0, 0.0, 0.0], spec["euler_deg"],
                          convention=spec.get("convention", default_convention), degrees=True)
    return t.rotation


def build_targets(config) -> list:
    """The targets of ``config`` (random ones drawn from their own seed).

    For a benchmark experiment, its problems
    (:func:`moik.experiments.benchmark.build_benchmark_targets`).
    """
    from moik.experiments.benchmark import build_benchmark_targets, is_benchmark
    from moik.problems.targets import circle_path, random_reachable_targets

    if is_benchmark(config["problem"]):
        return build_benchmark_targets(config)

    robot = experiment_robot(config["robot"], config["problem"])
    spec = config["targets"]
    try:
        if spec["kind"] == "random":
            ts = random_reachable_targets(robot, spec["n"], seed=spec["seed"],
                                          with_orientation=spec.get("with_orientation", True))
            return [NamedTarget(f"T{i + 1}", t.position.tolist(),
                                None if t.rotation is None else t.rotation.tolist())
                    for i, t in enumerate(ts)]
        if spec["kind"] == "circle":
            rot = _rotation(spec) if "euler_deg" in spec else None
            ts = circle_path(spec["center"], spec["radius"], spec["n_points"], rotation=rot)
            return [NamedTarget(f"C{i + 1}", t.position.tolist(),
                                None if rot is None else rot.tolist()) for i, t in enumerate(ts)]
        out = []
        for pt in spec["points"]:
            if "fk_q_deg" in pt:
                arm = experiment_robot(pt["robot"], config["problem"]) if "robot" in pt else robot
                T = arm.fk(np.radians(pt["fk_q_deg"]))
                pos, rot = T[:3, 3], T[:3, :3]
            else:
                pos, rot = np.asarray(pt["position"], dtype=float), None
            if "euler_deg" in pt:
                rot = _rotation(pt)
            out.append(NamedTarget(pt["name"], [float(v) for v in pos],
                                   None if rot is None else rot.tolist(), pt.get("hv_ref_point"),
                                   pt.get("robot")))
        return out
    except MoikError as exc:
        raise ConfigError(f"{config.path or config.name}: targets: {exc}") from None


def build_problem(robot, problem: Mapping, target: NamedTarget):
    """The pymoo problem of one trial."""
    from moik.problems import BiObjectiveIK, PoseIK, PositionIK, Target

    tgt = Target(target.position, None if target.rotation is None else np.array(target.rotation))
    common = {"displacement_weight": float(problem.get("displacement_weight", 0.0))}
    if "q_start_deg" in problem:
        common["q_start"] = np.radians(problem["q_start_deg"])
    kind = problem["kind"]
    if kind == "position":
        return PositionIK(robot, tgt, **common)
    if kind == "pose":
        return PoseIK(robot, tgt, weights=tuple(problem.get("weights", (0.5, 0.5))),
                      orientation=problem["orientation"], **common)
    return BiObjectiveIK(robot, tgt, orientation=problem["orientation"], **common)
