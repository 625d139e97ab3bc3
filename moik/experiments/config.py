"""Experiment configurations: declared data, validated on load.

An experiment is one TOML file in an experiments folder (data, never code; read
by :mod:`moik.experiments.config_files`, where ``extends = "base-name"`` makes a
variant of another experiment). The keys:

- ``name`` (lower-case, ``-`` separated; the file is ``name`` with ``_`` for
  ``-``), ``title``, ``source`` (paper, table and figures reproduced);
- ``problem`` and, for IK experiments, ``robot`` and ``targets``: their keys
  depend on the experiment kind, chosen once from ``problem.kind``
  (:mod:`moik.experiments.kinds`): ``"position"``, ``"pose"``,
  ``"bi-objective"`` are IK problems on a catalog robot or a URDF arm
  (:mod:`moik.experiments.kinds.ik`; ``robot = {urdf = "FILE", ...}``, paths read from
  the config file's folder: :mod:`moik.experiments.kinds.ik_robot`); ``"benchmark"``
  lists test functions and design problems, with no robot and no targets
  (:mod:`moik.experiments.kinds.functions`; ``requires`` lists its optional
  extras); ``"moo-benchmark"`` lists ZDT/DTLZ problems with analytic fronts
  (:mod:`moik.experiments.kinds.moo_functions`);
- ``algorithms``: list of ``{"name": registry name, "label": shown name,
  "params": {...}, "optional": bool}`` (an optional algorithm that is not
  registered is left out; a kind's baselines, such as ``random-search``, are
  accepted beside the registry's names); ``pop_size``,
  ``archive_size`` (multi-objective only), ``iterations``, ``runs`` (per target)
  and ``seed`` apply to all; ``iterations`` is the papers' Max_t (T): the update
  iterations after the initial population, so a run evaluates the initial
  population plus ``iterations`` x the algorithm's evaluations per iteration
  (pymoo's termination ``("n_gen", iterations + 1)``: pymoo counts the initial
  population as generation 1). The former key ``n_gen`` is refused;
- ``protocol`` (optional): ``{"threshold", "max_failures"}``, the EOSMA
  re-solve protocol (:func:`moik.experiments.protocol.solve_until_success`);
- ``analyses``: which tables the report prints (:data:`ANALYSES`);
  ``proposed``: label compared with the others; ``success_threshold``;
- ``paper``: the paper's numbers, with their citation, for the report;
- ``quick``: overrides (merged into the dict) for the seconds-long smoke size;
- ``requires`` (benchmark kind): optional extras it needs (:func:`check_requirements`).

Validation builds what a run uses (the robot, targets and pymoo problems of
the kind, and every algorithm through the registry). Unknown keys, wrong types
and values out of range raise :class:`ConfigError` naming the file and the key.
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from moik._paths import MAX_NAME
from moik.algorithms import available, get_algorithm
from moik.algorithms.registry import accepted_parameters, is_multi_objective
from moik.exceptions import ConfigError, MoikError
from moik.experiments.checks import check_keys, flag, integer, number
from moik.experiments.config_files import merge, name_of, read_config
from moik.experiments.kinds import KINDS, MULTI_OBJECTIVE_PROBLEMS, baselines, kind_of
from moik.experiments.kinds.functions import EXTRAS
from moik.experiments.kinds.ik_robot import resolve

ANALYSES = ("summary", "ranksum", "friedman-hv", "joint-motion", "compromise", "signed-rank",
            "per-target", "per-target-ranksum", "branches", "dh-fit", "solution-rank",
            "paper-consistency", "front-quality", "mean-ranks", "versus-random", "hv-shares",
            "reference-front", "collision")
"""Report tables an experiment can ask for (see :mod:`moik.experiments.analysis`)."""

_TOP_KEYS = {"name", "title", "source", "robot", "problem", "targets", "algorithms", "pop_size",
             "archive_size", "iterations", "runs", "seed", "protocol", "analyses", "proposed",
             "success_threshold", "paper", "quick", "requires"}
_REQUIRED = ("name", "title", "source", "problem", "algorithms", "pop_size", "iterations", "runs",
             "seed")
_NAME = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")


def _shown(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."




@dataclass(frozen=True)
class AlgorithmSpec:
    """One algorithm of an experiment: registry ``name``, shown ``label``, ``params``."""

    name: str
    label: str
    params: dict
    multi_objective: bool


def _algorithms(where: str, raw: Any, cfg: Mapping, kind: str, multi: bool
                ) -> tuple[tuple[AlgorithmSpec, ...], tuple[str, ...]]:
    if not isinstance(raw, list) or not raw:
        raise ConfigError(f"{where} must be a non-empty list of algorithms")
    own = baselines(kind)
    specs, labels, skipped = [], set(), []
    for i, entry in enumerate(raw):
        w = f"{where}[{i}]"
        entry = check_keys(w, entry, {"name", "label", "params", "optional"}, ("name",))
        name = entry["name"]
        if not isinstance(name, str):
            raise ConfigError(f"{w}.name must be an algorithm name (a string), got "
                              f"{type(name).__name__}")
        known = name in own or name in available()
        if flag(f"{w}.optional", entry.get("optional", False)) and not known:
            skipped.append(name)
            continue
        if not known:
            raise ConfigError(f"{w}.name: unknown algorithm {name!r}; expected one of: "
                              f"{', '.join([*available(), *own])}")
        label = entry.get("label", name)
        if not isinstance(label, str) or not _NAME.match(label) or label in labels \
                or len(label) > MAX_NAME:
            raise ConfigError(f"{w}.label must be a unique lower-case name of at most "
                              f"{MAX_NAME} characters, got {_shown(label)}")
        labels.add(label)
        accepted = own[name] if name in own else accepted_parameters(name)
        params = dict(check_keys(f"{w}.params", entry.get("params", {}), set(accepted)))
        params.setdefault("pop_size", cfg["pop_size"])
        if cfg.get("archive_size") is not None and "archive_size" in accepted:
            params.setdefault("archive_size", cfg["archive_size"])
        if name in own:
            integer(f"{w}.params.pop_size", params["pop_size"], 1)
        else:
            try:
                get_algorithm(name, **params)
            except MoikError as exc:
                raise ConfigError(f"{w}.params: {exc}") from None
        specs.append(AlgorithmSpec(name=name, label=label, params=params,
                                   multi_objective=multi if name in own
                                   else is_multi_objective(name)))
    if not specs:
        raise ConfigError(f"{where}: none of the algorithms is registered")
    return tuple(specs), tuple(skipped)


@dataclass(frozen=True)
class ExperimentConfig:
    """A validated experiment (build with :func:`load_config` or :meth:`from_dict`).

    Attributes:
        name: Experiment name (``moik experiment run NAME``).
        raw: The configuration dict as validated (without ``quick``).
        quick_overrides: The ``quick`` dict.
        algorithms: The algorithms, in report order.
        kind: The experiment kind (a key of :data:`moik.experiments.kinds.KINDS`).
        targets: The targets, built and validated (IK poses, or the benchmark
            problems that take their place), in trial order.
        skipped: Optional algorithms left out because they are not registered.
        is_quick: Whether this is the quick size.
        path: The file it came from, if any.
        folder: The folder the config's relative paths are read from (absolute: the
            file's folder, else the current folder when the config was validated).
    """

    name: str
    raw: dict
    quick_overrides: dict
    algorithms: tuple[AlgorithmSpec, ...]
    kind: str
    targets: tuple = field(repr=False, compare=False)
    skipped: tuple[str, ...] = ()
    is_quick: bool = False
    path: str | None = None
    folder: Path = field(default_factory=Path.cwd, compare=False)

    @classmethod
    def from_dict(cls, data: Mapping, *, path: str | None = None, is_quick: bool = False,
                  folder: str | Path | None = None) -> ExperimentConfig:
        """Validate ``data`` (a config file's keys) and build the config.

        Args:
            data: The keys.
            path: The file they came from.
            is_quick: Whether ``data`` is the quick size.
            folder: Where relative paths of ``data`` are read from (default: the folder
                of ``path``, else the current folder).

        Raises:
            ConfigError: Naming the key and what was expected.
        """
        where = path or "experiment"
        _refuse_renamed(where, data)
        cfg = check_keys(where, data, _TOP_KEYS, _REQUIRED)
        _refuse_renamed(f"{where}: quick", cfg.get("quick", {}))
        quick = check_keys(f"{where}: quick", cfg.pop("quick", {}), _TOP_KEYS - {"quick", "name"})
        name = cfg["name"]
        if not isinstance(name, str) or not _NAME.match(name) or len(name) > MAX_NAME:
            raise ConfigError(f"{where}: name must be lower-case words joined by '-' (at most "
                              f"{MAX_NAME} characters), got {_shown(name)}")
        for key in ("title", "source"):
            if not isinstance(cfg[key], str) or not cfg[key]:
                raise ConfigError(f"{where}: {key} must be a non-empty string")
        kind = kind_of(f"{where}: problem", cfg["problem"])
        integer(f"{where}: pop_size", cfg["pop_size"], 1)
        if cfg.get("archive_size") is not None:
            integer(f"{where}: archive_size", cfg["archive_size"], 1)
        integer(f"{where}: iterations", cfg["iterations"], 1)
        integer(f"{where}: runs", cfg["runs"], 1)
        integer(f"{where}: seed", cfg["seed"], 0)
        folder = Path(folder if folder is not None else Path(path).parent if path
                      else Path()).absolute()
        cfg["problem"], targets = KINDS[kind].check_config(where, cfg, folder)
        problem = cfg["problem"]
        want_mo = problem["kind"] in MULTI_OBJECTIVE_PROBLEMS
        algorithms, skipped = _algorithms(f"{where}: algorithms", cfg["algorithms"], cfg, kind,
                                          want_mo)
        for a in algorithms:
            if a.multi_objective != want_mo:
                which = "multi-objective" if a.multi_objective else "single-objective"
                raise ConfigError(f"{where}: algorithm {a.name!r} is {which} but the problem kind "
                                  f"is {problem['kind']!r}")
        _check_rest(where, cfg, algorithms, want_mo)
        return cls(name=name, raw=cfg, quick_overrides=quick, algorithms=algorithms, kind=kind,
                   targets=targets, skipped=skipped, is_quick=is_quick, path=path,
                   folder=folder)

    def quick(self) -> ExperimentConfig:
        """The quick (smoke-test) size: ``raw`` with the ``quick`` overrides merged."""
        if self.is_quick:
            return self
        return ExperimentConfig.from_dict(merge(self.raw, self.quick_overrides), path=self.path,
                                          is_quick=True, folder=self.folder)

    def __getitem__(self, key: str) -> Any:
        return self.raw.get(key)

    @property
    def robot(self) -> Any:
        """The robot the trials load: a catalog name, a URDF arm with absolute paths and its
        file's digest (:func:`~moik.experiments.kinds.ik_robot.resolve`), or None."""
        return resolve(self.raw.get("robot"), self.folder)

    @property
    def labels(self) -> list[str]:
        """Algorithm labels in report order."""
        return [a.label for a in self.algorithms]

    def fingerprint(self) -> str:
        """SHA-256 of ``raw`` and the algorithms present (identifies a run's configuration)."""
        text = json.dumps([self.raw, self.labels], sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()


def _refuse_renamed(where: str, data: Any) -> None:
    """Refuse the keys a former config format used, naming their replacement.

    Raises:
        ConfigError: For ``n_gen`` (now ``iterations``).
    """
    if isinstance(data, Mapping) and "n_gen" in data:
        raise ConfigError(f"{where}: the key 'n_gen' was renamed 'iterations' (the papers' "
                          f"Max_t: update iterations after the initial population; a run does "
                          f"pop_size + iterations x per-iteration evaluations), got "
                          f"n_gen={data['n_gen']!r}")


def _check_rest(where: str, cfg: dict, algorithms: tuple[AlgorithmSpec, ...],
                multi: bool) -> None:
    labels = [a.label for a in algorithms]
    if cfg.get("protocol") is not None:
        if multi:
            raise ConfigError(f"{where}: protocol applies to single-objective problems only")
        p = check_keys(f"{where}: protocol", cfg["protocol"], {"threshold", "max_failures"},
                       ("threshold", "max_failures"))
        number(f"{where}: protocol.threshold", p["threshold"], positive=True)
        integer(f"{where}: protocol.max_failures", p["max_failures"], 1)
    if "success_threshold" in cfg:
        number(f"{where}: success_threshold", cfg["success_threshold"], positive=True)
    analyses = cfg.get("analyses", ["summary"])
    if not isinstance(analyses, list) or any(a not in ANALYSES for a in analyses):
        raise ConfigError(f"{where}: analyses must be a list of: {', '.join(ANALYSES)}; "
                          f"got {analyses!r}")
    proposed = cfg.get("proposed")
    if proposed is not None and proposed not in labels:
        raise ConfigError(f"{where}: proposed {proposed!r} is not an algorithm label: "
                          f"{', '.join(labels)}")
    if {"ranksum", "signed-rank", "front-quality", "mean-ranks", "hv-shares"} & set(analyses) \
            and proposed is None:
        raise ConfigError(f"{where}: analyses ranksum/signed-rank/front-quality/mean-ranks/"
                          "hv-shares need 'proposed'")
    if "paper" in cfg and not isinstance(cfg["paper"], Mapping):
        raise ConfigError(f"{where}: paper must be a dict of the paper's numbers")


def load_config(path: str | Path, bases: Mapping[str, Path] | None = None) -> ExperimentConfig:
    """Load and validate the experiment defined by the TOML file ``path``.

    Args:
        path: The config file (:mod:`moik.experiments.config_files`).
        bases: Experiment name -> file, where an ``extends`` name is looked up first.

    Raises:
        ConfigError: If the file is missing, not TOML (a Python file is refused, never
            run), extends an unknown experiment, or its data is invalid.
    """
    p = Path(path)
    config = ExperimentConfig.from_dict(read_config(p, bases), path=str(p))
    if name_of(p) != config.name:
        raise ConfigError(f"{p}: name {config.name!r} must match the file name "
                          f"({name_of(p)!r})")
    return config


def check_requirements(config: ExperimentConfig) -> None:
    """Raise :class:`ConfigError` if an extra the experiment requires is not installed."""
    for extra in config["requires"] or []:
        module, what = EXTRAS[extra]
        if importlib.util.find_spec(module) is None:
            raise ConfigError(f"experiment {config.name!r} needs the optional extra {extra!r} "
                              f"({module}, for {what}): pip install -e '.[{extra}]' in the "
                              "moik repository")
