"""The robot of an IK experiment: a catalog name, or a URDF arm the config names.

``robot = "panda"`` names a catalog arm (:func:`moik.robots.get_robot`). A table names a
URDF file, as ``moik solve ARM.urdf --base B --tip T --package-dir DIR`` does::

    robot = { urdf = "arms/my_arm.urdf", package_dirs = ["arms"], tip_link = "tool0" }

- ``urdf`` (required): the file; a relative path is read from the config file's folder (a
  config given as data, :meth:`~moik.experiments.config.ExperimentConfig.from_dict`
  without a path: from the current folder);
- ``package_dirs``: where its ``package://`` meshes are found (a collision check reads
  them), a list of folders holding package folders or a table ``{package = folder}``
  (:func:`moik.collision.meshes.resolve_mesh`); relative to the config's folder likewise;
- ``base_link``, ``tip_link``: the chain, as :func:`moik.robots.load_urdf` takes them;
- ``srdf``: the robot's MoveIt SRDF, whose disabled pairs a self-collision check leaves out
  (:mod:`moik.collision.srdf`), relative to the config's folder likewise; its SHA-256 is
  set as ``srdf_sha256`` and checked as the URDF's is;
- ``sha256``: the SHA-256 of the file's bytes. Validation adds it to the config as run
  (so the results' ``meta.json`` records which file, and the configuration fingerprint
  changes with its content: ``--resume`` refuses a changed arm as it refuses a changed
  config); a config that states it pins the file, and another file is refused.

A config is a file from elsewhere: the URDF is read as every file moik reads is
(:func:`moik._reading.read_bytes`: a regular file, at most
:data:`~moik.robots.urdf.MAX_URDF_BYTES`), and a file that is missing, unreadable, not a
URDF or not the file the config (or a run) was checked against is a
:class:`~moik.exceptions.ConfigError` naming the key and the path.

The trials and the stored results carry the entry *resolved* (:func:`resolve`: absolute
paths, the digest), so a trial in another process and a report made later load the same
file, and refuse it if it changed (:func:`arm`).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from moik._validate import reading as _reading
from moik.exceptions import ConfigError, MoikError, ResultsError
from moik.robots import Robot, get_robot
from moik.robots.urdf import MAX_URDF_BYTES, load_urdf

URDF_KEYS = ("urdf", "package_dirs", "base_link", "tip_link", "sha256", "srdf", "srdf_sha256")
"""The keys of a URDF robot entry."""
_ARMS: dict[str, Robot] = {}
_CACHE_SIZE = 8


def _digest(path: Path, what: str = "URDF file") -> str:
    data = _reading.read_bytes(path, what, ConfigError, limit=MAX_URDF_BYTES)
    return hashlib.sha256(data).hexdigest()


def _text(where: str, value: Any) -> str:
    if not isinstance(value, str) or not value.strip():
        raise ConfigError(f"{where} must be a non-empty string, got {value!r}")
    return value


def _folders(where: str, value: Any) -> list[str] | dict[str, str]:
    """``package_dirs`` as written: a list of folders, or ``{package: folder}``."""
    if isinstance(value, Mapping):
        return {_text(f"{where} key", k): _text(f"{where}.{k}", v) for k, v in value.items()}
    if isinstance(value, list):
        return [_text(f"{where}[{i}]", v) for i, v in enumerate(value)]
    raise ConfigError(f"{where} must be a list of folders or a table {{package = folder}}, "
                      f"got {value!r}")


def _absolute(path: str, folder: Path) -> str:
    return str(folder / path) if not Path(path).is_absolute() else path


def check_robot(where: str, value: Any, folder: Path) -> str | dict:
    """``value`` (the config's ``robot``) checked: a catalog name as it is, a URDF entry with
    its keys checked, its files found and its ``sha256`` set (see the module doc).

    Args:
        where: The config and key, for messages.
        value: A string or a table.
        folder: The folder relative paths are read from (absolute).

    Raises:
        ConfigError: An unknown key (the allowed ones are named), a wrong type, a missing
            or unreadable file or folder, a ``sha256`` the file does not have.
    """
    if not isinstance(value, Mapping):
        return value
    unknown = sorted(set(value) - set(URDF_KEYS))
    if unknown:
        raise ConfigError(f"{where}: unknown key(s) {', '.join(map(repr, unknown))} of a URDF "
                          f"robot; expected: {', '.join(URDF_KEYS)} (urdf required)")
    if "urdf" not in value:
        raise ConfigError(f"{where}: a URDF robot needs 'urdf' (the file; allowed keys: "
                          f"{', '.join(URDF_KEYS)}); a catalog robot is a name (robot = "
                          "\"panda\")")
    entry: dict[str, Any] = {"urdf": _text(f"{where}.urdf", value["urdf"])}
    if "package_dirs" in value:
        entry["package_dirs"] = _folders(f"{where}.package_dirs", value["package_dirs"])
        named = entry["package_dirs"]
        for key, rel in (named.items() if isinstance(named, dict) else enumerate(named)):
            if not Path(_absolute(rel, folder)).is_dir():
                raise ConfigError(f"{where}.package_dirs[{key!r}]: {rel!r} is not a folder "
                                  f"(looked for {_absolute(rel, folder)!r})")
    for key in ("base_link", "tip_link"):
        if key in value:
            entry[key] = _text(f"{where}.{key}", value[key])
    if "srdf" in value:
        entry["srdf"] = _text(f"{where}.srdf", value["srdf"])
        srdf = Path(_absolute(entry["srdf"], folder))
        try:
            entry["srdf_sha256"] = _digest(srdf, "SRDF file")
        except ConfigError as exc:
            raise ConfigError(f"{where}.srdf: {exc}") from None
        if "srdf_sha256" in value and value["srdf_sha256"] != entry["srdf_sha256"]:
            raise ConfigError(f"{where}.srdf_sha256: the file {str(srdf)!r} has SHA-256 "
                              f"{entry['srdf_sha256']}, not {value['srdf_sha256']!r}")
    elif "srdf_sha256" in value:
        raise ConfigError(f"{where}.srdf_sha256 goes with srdf (the file it pins)")
    path = Path(_absolute(entry["urdf"], folder))
    try:
        digest = _digest(path)
    except ConfigError as exc:
        raise ConfigError(f"{where}.urdf: {exc} (a relative path is read from the config's "
                          f"folder, {str(folder)!r})") from None
    if "sha256" in value and value["sha256"] != digest:
        raise ConfigError(f"{where}.sha256: the file {str(path)!r} has SHA-256 {digest}, not "
                          f"{value['sha256']!r} as the config pins it (the URDF changed: remove "
                          "sha256 to accept the new file)")
    entry["sha256"] = digest
    return entry


def resolve(value: Any, folder: Path) -> Any:
    """A checked ``robot`` value (:func:`check_robot`) as the trials and the results carry it:
    a catalog name as it is; a URDF entry with absolute paths."""
    if not isinstance(value, Mapping):
        return value
    out = dict(value)
    out["urdf"] = _absolute(value["urdf"], folder)
    if "srdf" in value:
        out["srdf"] = _absolute(value["srdf"], folder)
    dirs = value.get("package_dirs")
    if isinstance(dirs, Mapping):
        out["package_dirs"] = {k: _absolute(v, folder) for k, v in dirs.items()}
    elif dirs is not None:
        out["package_dirs"] = [_absolute(v, folder) for v in dirs]
    return out


def arm(value: Any) -> Robot:
    """The robot of a resolved ``robot`` value (:func:`resolve`): the catalog arm, or the
    URDF's chain after checking the file still has the digest the config was checked with
    (loaded once per process and file).

    Raises:
        ConfigError: The URDF is missing, changed, or not a loadable chain.
        UnknownNameError: An unknown catalog name.
    """
    if not isinstance(value, Mapping):
        return get_robot(value)
    key = json.dumps(value, sort_keys=True)
    path = Path(value["urdf"])
    digest = _digest(path)
    if digest != value.get("sha256"):
        raise ConfigError(f"robot: the URDF {str(path)!r} changed since the experiment was "
                          f"checked (SHA-256 {str(value.get('sha256'))[:12]}..., now "
                          f"{digest[:12]}...): restore it, or run the experiment again")
    if "srdf" in value and _digest(Path(value["srdf"]), "SRDF file") != value.get("srdf_sha256"):
        raise ConfigError(f"robot: the SRDF {value['srdf']!r} changed since the experiment was "
                          "checked: restore it, or run the experiment again")
    if key not in _ARMS:
        try:
            robot = load_urdf(path, base_link=value.get("base_link"),
                              tip_link=value.get("tip_link"),
                              package_dirs=value.get("package_dirs"), srdf=value.get("srdf"))
        except MoikError as exc:
            raise ConfigError(f"robot: {exc}") from None
        if len(_ARMS) >= _CACHE_SIZE:
            _ARMS.pop(next(iter(_ARMS)))
        _ARMS[key] = robot
    return _ARMS[key]


def experiment_robot(value: Any, problem: Mapping) -> Robot:
    """The robot of a resolved ``robot`` value (:func:`arm`) with the problem's
    ``joint_limits_deg`` and ``locked_joints_deg`` applied."""
    return locked(arm(value), problem)


def locked(robot: Robot, problem: Mapping) -> Robot:
    """``robot`` with the problem's ``joint_limits_deg``, then its ``locked_joints_deg``."""
    limits = problem.get("joint_limits_deg")
    if limits:
        lower, upper = np.radians(np.asarray(limits, dtype=float)).T
        robot = dataclasses.replace(robot, name=f"{robot.name}[limits]", lower=lower, upper=upper,
                                    source=f"{robot.source}; limits {limits} deg")
    lock = problem.get("locked_joints_deg")
    if lock:
        robot = robot.with_locked_joints({i: float(np.radians(v)) for i, v in enumerate(lock)
                                          if v is not None})
    return robot


def stored_robot(meta: Mapping) -> Any:
    """The resolved ``robot`` value of a results folder's ``meta.json``: the config's catalog
    name, or the URDF arm the run recorded (``meta["robot"]``: absolute paths), which must be
    the config's (same file name, chain and digest).

    Raises:
        ResultsError: A URDF arm in the config that ``meta.json`` does not record, or
            records otherwise.
    """
    value = meta["config"].get("robot")
    if not isinstance(value, Mapping):
        return value
    stored = meta.get("robot")
    same = isinstance(stored, Mapping) and all(
        stored.get(k) == value.get(k) for k in ("sha256", "base_link", "tip_link")) and \
        Path(str(stored.get("urdf"))).name == Path(str(value.get("urdf"))).name
    if not same:
        raise ResultsError(f"meta.json: the config's robot is the URDF {value.get('urdf')!r} "
                           f"(SHA-256 {str(value.get('sha256'))[:12]}...) but meta.json's "
                           f"'robot' does not record that file: {stored!r}")
    return stored


def config_folder(meta: Mapping) -> Path | None:
    """The folder a results folder's config read its relative paths from: what the recorded
    URDF path (``meta["robot"]``) holds before the path the config names; None for a catalog
    robot or a path recorded otherwise."""
    value, stored = meta["config"].get("robot"), meta.get("robot")
    if not isinstance(value, Mapping) or not isinstance(stored, Mapping):
        return None
    rel, full = Path(str(value.get("urdf"))), Path(str(stored.get("urdf")))
    n = len(rel.parts)
    if rel.is_absolute() or full.parts[-n:] != rel.parts or len(full.parts) <= n:
        return None
    return Path(*full.parts[:-n])


def describe(value: Any) -> str:
    """The config's ``robot`` value in words, for a report: the URDF as the config names it
    (no path of this machine, unless the config wrote one) and its digest."""
    if not isinstance(value, Mapping):
        return f"`{value}`"
    chain = " to ".join(f"`{value[k]}`" for k in ("base_link", "tip_link") if k in value)
    return (f"URDF `{value.get('urdf')}` (SHA-256 "
            f"{str(value.get('sha256'))[:12]}{', chain ' + chain if chain else ''})")
