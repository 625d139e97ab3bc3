"""Targets of IK experiments: the ``targets`` key of a config (:mod:`moik.experiments.kinds.ik`).

``{"kind": "random", ...}`` (FK poses of random joint vectors, or FK positions with
rotations uniform on SO(3)), ``{"kind": "fixed", "points": [...]}`` (positions or
FK joint vectors in degrees, optional Euler angles, HV reference points and an own
robot per point) and ``{"kind": "circle", ...}``, each validated by building the
:class:`~moik.problems.Target` it names (:func:`build_targets`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.spatial.transform import Rotation

from moik.exceptions import ConfigError, MoikError
from moik.experiments.checks import check_keys, flag, integer, number, numbers
from moik.problems import Target
from moik.problems.targets import circle_path, random_reachable_targets
from moik.robots import Robot

TARGET_KINDS = ("random", "fixed", "circle")
RANDOM_ORIENTATIONS = ("reachable", "independent")
_TARGET_KEYS = {
    "random": {"kind", "n", "seed", "with_orientation", "orientation"},
    "fixed": {"kind", "points"},
    "circle": {"kind", "center", "radius", "n_points", "euler_deg", "convention"},
}
_POINT_KEYS = {"name", "position", "fk_q_deg", "euler_deg", "convention", "hv_ref_point",
               "robot"}




@dataclass(frozen=True)
class NamedTarget:
    """A target of an IK experiment: display name, pose, HV reference point, own robot.

    ``target`` is the validated :class:`~moik.problems.Target`; ``robot`` names the
    arm of this target when it is not the experiment's.
    """

    name: str
    target: Target
    hv_ref_point: list[float] | None = None
    robot: str | None = None

    @property
    def position(self) -> np.ndarray:
        """``(3,)`` position in the robot's unit."""
        return self.target.position

    @property
    def rotation(self) -> np.ndarray | None:
        """``(3, 3)`` rotation, or None for a position target."""
        return self.target.rotation

    def as_dict(self) -> dict:
        """JSON-ready form (floats round-trip exactly through ``json``)."""
        rot = self.target.rotation
        d = {"name": self.name, "position": self.target.position.tolist(),
             "rotation": None if rot is None else rot.tolist(), "hv_ref_point": self.hv_ref_point}
        return d if self.robot is None else {**d, "robot": self.robot}


def _rotation(spec: Mapping) -> np.ndarray:
    rotation = Target.from_euler([0.0, 0.0, 0.0], spec["euler_deg"],
                                 convention=spec.get("convention", "zyx-euler"),
                                 degrees=True).rotation
    assert rotation is not None  # from_euler always gives one
    return rotation


def build_targets(where: str, spec: Any, problem: Mapping, robot: Robot,
             robot_of: Callable[[Any, str], Robot]) -> list[NamedTarget]:
    """The targets of the config's ``targets`` (see :mod:`moik.experiments.kinds.ik`).

    Args:
        where: Config location for messages.
        spec: The ``targets`` value.
        problem: The validated ``problem`` dict (its kind decides whether targets
            need an orientation).
        robot: The experiment's arm (locked joints applied).
        robot_of: ``(name, key) -> Robot`` for a point naming its own arm.

    Raises:
        ConfigError: Naming the key and what was expected.
    """
    kind = spec.get("kind") if isinstance(spec, Mapping) else None
    if kind not in TARGET_KINDS:
        raise ConfigError(f"{where}.kind must be one of {', '.join(TARGET_KINDS)}, got {kind!r}")
    t = check_keys(where, spec, _TARGET_KEYS[kind], ("kind",))
    oriented = problem["kind"] != "position"
    try:
        if kind == "random":
            n = integer(f"{where}.n", t.get("n"), 1)
            seed = integer(f"{where}.seed", t.get("seed"), 0)
            with_orientation = flag(f"{where}.with_orientation", t.get("with_orientation", True))
            if oriented and not with_orientation:
                raise ConfigError(f"{where}: problem kind {problem['kind']!r} needs "
                                  "with_orientation true")
            reading = t.get("orientation", "reachable")
            if reading not in RANDOM_ORIENTATIONS:
                raise ConfigError(f"{where}.orientation must be one of "
                                  f"{', '.join(RANDOM_ORIENTATIONS)}, got {reading!r}")
            ts = random_reachable_targets(robot, n, seed=seed, with_orientation=with_orientation)
            if with_orientation and reading == "independent":
                drawn = Rotation.random(n, random_state=np.random.default_rng([seed, 1]))
                ts = [Target(x.position, R) for x, R in zip(ts, drawn.as_matrix(), strict=True)]
            return [NamedTarget(f"T{i + 1}", x) for i, x in enumerate(ts)]
        if kind == "circle":
            numbers(f"{where}.center", t.get("center"), 3)
            number(f"{where}.radius", t.get("radius"), positive=True)
            integer(f"{where}.n_points", t.get("n_points"), 2)
            rot = None
            if oriented or "euler_deg" in t:
                numbers(f"{where}.euler_deg", t.get("euler_deg"), 3)
                rot = _rotation(t)
            ts = circle_path(t["center"], t["radius"], t["n_points"], rotation=rot)
            return [NamedTarget(f"C{i + 1}", x) for i, x in enumerate(ts)]
        points = t.get("points")
        if not isinstance(points, list) or not points:
            raise ConfigError(f"{where}.points must be a non-empty list")
        return [_point(f"{where}.points[{i}]", raw, oriented, problem, robot, robot_of)
                for i, raw in enumerate(points)]
    except ConfigError:
        raise
    except MoikError as exc:
        raise ConfigError(f"{where}: {exc}") from None


def _point(where: str, raw: Any, oriented: bool, problem: Mapping, robot: Robot,
           robot_of: Callable[[Any, str], Robot]) -> NamedTarget:
    pt = check_keys(where, raw, _POINT_KEYS, ("name",))
    if not isinstance(pt["name"], str) or not pt["name"]:
        raise ConfigError(f"{where}.name must be a non-empty string, got {pt['name']!r}")
    arm = robot_of(pt["robot"], f"{where}.robot") if "robot" in pt else robot
    if ("position" in pt) == ("fk_q_deg" in pt):
        raise ConfigError(f"{where}: give exactly one of position and fk_q_deg")
    if "position" in pt:
        pos, rot = np.asarray(numbers(f"{where}.position", pt["position"], 3)), None
        if oriented and "euler_deg" not in pt:
            raise ConfigError(f"{where}: problem kind {problem['kind']!r} needs euler_deg")
    else:
        T = arm.fk(np.radians(numbers(f"{where}.fk_q_deg", pt["fk_q_deg"], arm.dof)))
        pos, rot = T[:3, 3], T[:3, :3]
    if "euler_deg" in pt:
        numbers(f"{where}.euler_deg", pt["euler_deg"], 3)
        rot = _rotation(pt)
    if "hv_ref_point" in pt:
        numbers(f"{where}.hv_ref_point", pt["hv_ref_point"], 2)
    return NamedTarget(pt["name"], Target(pos, rot), pt.get("hv_ref_point"), pt.get("robot"))
