"""Reference fronts cached on disk, keyed by a fingerprint of everything they depend on.

A front (:func:`moik.fronts.front.bi_objective_front`) costs seconds; :func:`cached_front`
computes it once per (robot kinematics and limits, target, metric, method settings and
seed, :data:`~moik.fronts.front.METHOD_VERSION`) and keeps it in
``$XDG_CACHE_HOME/moik/fronts`` (``~/.cache/moik/fronts`` when unset) as one ``.npz``
file named by the fingerprint. The fronts of the registered problems
(:mod:`moik.problems.registry`) ship in ``moik/fronts/data`` under the same names and
are read from there first (``python -m studies.ik_fronts --write`` regenerates them).
A change of any of those inputs gives another fingerprint (the old file is simply not
read). An unwritable or unreadable cache is not an error: the front is then computed
and returned without being stored; a damaged file is recomputed.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import os
from pathlib import Path
from typing import Any

import numpy as np

from moik import _paths
from moik.exceptions import MoikError
from moik.fronts.front import METHOD_VERSION, ReferenceFront, bi_objective_front
from moik.fronts.motion import motion_front
from moik.robots.chain import Robot

FRONT_SEED = 20240  # the random starts' seed of every cached front
KEY_DECIMALS = 9  # of the numbers in a front's key (fingerprint)
SHIPPED = Path(__file__).with_name("data")  # fronts shipped with moik, by fingerprint
DEFAULT_SETTINGS = {"levels": 40, "starts": 16, "checks": 1, "tol": 1e-9, "seed": FRONT_SEED}


def cache_dir() -> Path:
    """Where fronts are kept: ``$XDG_CACHE_HOME/moik/fronts`` or ``~/.cache/moik/fronts``."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "moik" / "fronts"


MOTION_SETTINGS: dict[str, Any] = {"levels": 12, "motion_levels": 12, "starts": 8,
                                   "tol": 1e-9, "seed": FRONT_SEED}
"""The settings of a three-objective front (:func:`moik.fronts.motion.motion_front`)."""


def fingerprint(robot: Robot, position, rotation, metric: str, settings: dict,
                q_start=None) -> str:
    """A hex digest of what the front depends on (not of the robot's name or source);
    ``q_start``: the three-objective front's start configuration (None: bi-objective).

    Every number enters rounded to :data:`KEY_DECIMALS` decimals (and ``-0.0`` as ``0.0``):
    a target computed by numpy (a norm, an FK) differs in its last bits between kinds
    of machine (numpy's sums dispatch on SIMD), and must find the same shipped front."""
    chain = robot.kinematic_chain
    h = hashlib.sha256()
    arrays = [chain.origins, chain.joint_types, robot.lower, robot.upper, position, rotation]
    for a in arrays if q_start is None else [*arrays, q_start]:
        arr = np.ascontiguousarray(np.round(np.asarray(a, dtype=float), KEY_DECIMALS) + 0.0)
        h.update(str(arr.shape).encode())
        h.update(arr.tobytes())
    h.update(json.dumps({"metric": metric, "version": METHOD_VERSION, **settings},
                        sort_keys=True).encode())
    return h.hexdigest()[:32]


def _meta(front: ReferenceFront) -> dict:
    return {"reachable": front.reachable, "metric": front.metric, "starts": front.starts,
            "levels": front.levels, "checks": front.checks, "tol": front.tol,
            "guarantee": front.guarantee, "version": front.version, "extra": front.extra}


def _load(path: Path, key: str) -> ReferenceFront | None:
    """The front stored at ``path`` under ``key``, or None (missing, for another key, or
    damaged: a damaged file of the user's cache is removed, so the recomputed front
    replaces it; a shipped file is never removed)."""
    try:
        with np.load(path, allow_pickle=False) as data:
            meta = json.loads(str(data["meta"]))
            if not isinstance(meta, dict) or meta.pop("fingerprint", None) != key:
                return None
            front = ReferenceFront(F=data["F"], Q=data["Q"], kkt=data["kkt"], **meta)
    except Exception:  # noqa: BLE001 - any damage (BadZipFile, EOFError, a CRC, bad meta)
        if path.parent != SHIPPED:
            with contextlib.suppress(OSError, MoikError):
                _paths.remove(path.parent, path)
        return None
    return front


def store(path: Path, key: str, front: ReferenceFront) -> bool:
    """Write ``front`` to ``path`` (atomically, never through a link) under fingerprint
    ``key``; False when the folder is not writable. The temporary is removed whatever
    interrupts the write."""
    buffer = io.BytesIO()
    np.savez(buffer, F=front.F, Q=front.Q, kkt=front.kkt,
             meta=np.array(json.dumps({"fingerprint": key, **_meta(front)})))
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        _paths.atomic_write_bytes(path, buffer.getvalue())
        return True
    except (OSError, MoikError):
        return False


def cached_front(robot: Robot, position, rotation, *, metric: str, levels: int = 40,
                 starts: int = 16, checks: int = 1, tol: float = 1e-9,
                 seed: int = FRONT_SEED, use_cache: bool = True) -> ReferenceFront:
    """:func:`~moik.fronts.front.bi_objective_front` with the random starts drawn from
    ``numpy.random.default_rng(seed)``, read from the disk cache when there.

    Args:
        robot, position, rotation, metric: The problem (see ``bi_objective_front``).
        levels, starts, checks, tol: The method's settings.
        seed: The random starts' seed (part of the fingerprint).
        use_cache: False computes without reading or writing the cache.
    """
    settings = {"levels": levels, "starts": starts, "checks": checks, "tol": tol, "seed": seed}
    key = fingerprint(robot, position, rotation, metric, settings)
    path = cache_dir() / f"{key}.npz"
    for where in (SHIPPED / f"{key}.npz", path) if use_cache else ():
        front = _load(where, key) if where.is_file() else None
        if front is not None:
            return front
    front = bi_objective_front(robot, position, rotation, metric=metric, levels=levels,
                               starts=starts, checks=checks, tol=tol,
                               rng=np.random.default_rng(seed))
    if use_cache:
        store(path, key, front)
    return front


def cached_motion_front(robot: Robot, position, rotation, q_start, *, metric: str,
                        use_cache: bool = True) -> ReferenceFront:
    """:func:`~moik.fronts.motion.motion_front` with :data:`MOTION_SETTINGS`, read from
    the shipped data or the disk cache when there (as :func:`cached_front`)."""
    q_start = np.asarray(q_start, dtype=float)
    key = fingerprint(robot, position, rotation, metric, MOTION_SETTINGS, q_start)
    path = cache_dir() / f"{key}.npz"
    for where in (SHIPPED / f"{key}.npz", path) if use_cache else ():
        front = _load(where, key) if where.is_file() else None
        if front is not None:
            return front
    settings = {k: v for k, v in MOTION_SETTINGS.items() if k != "seed"}
    front = motion_front(robot, position, rotation, q_start, metric=metric, **settings,
                         rng=np.random.default_rng(FRONT_SEED))
    if use_cache:
        store(path, key, front)
    return front


def ship(robot: Robot, position, rotation, *, metric: str, q_start=None,
         directory: Path = SHIPPED) -> tuple[ReferenceFront, Path]:
    """Compute the front with :func:`cached_front`'s default settings (or, with
    ``q_start``, :func:`cached_motion_front`'s; cache not read) and store it in
    ``directory`` (the shipped data by default) under its fingerprint."""
    if q_start is None:
        key = fingerprint(robot, position, rotation, metric, DEFAULT_SETTINGS)
        front = cached_front(robot, position, rotation, metric=metric, use_cache=False)
    else:
        key = fingerprint(robot, position, rotation, metric, MOTION_SETTINGS, q_start)
        front = cached_motion_front(robot, position, rotation, q_start, metric=metric,
                                    use_cache=False)
    path = Path(directory) / f"{key}.npz"
    if not store(path, key, front):
        raise OSError(f"cannot write {path}")
    return front, path
