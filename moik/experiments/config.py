"""Experiment configurations: declared data, validated on load.

An experiment is one Python file in an experiments folder that defines a dict
``EXPERIMENT`` (plain literals only: the file is data). The keys:

- ``name`` (lower-case, ``-`` separated; the file is ``name`` with ``_`` for
  ``-``), ``title``, ``source`` (paper, table and figures reproduced);
- ``robot``: catalog name;
- ``problem``: ``{"kind": "position" | "pose" | "bi-objective", "orientation":
  metric, "weights": [w1, w2], "displacement_weight": w, "q_start_deg": [...],
  "locked_joints_deg": [...]}`` (see :mod:`moik.experiments.targets`), or
  ``{"kind": "benchmark", "names": [...]}`` with no robot and no targets (see
  :mod:`moik.experiments.benchmark`; ``requires`` lists its optional extras);
- ``targets``: ``{"kind": "random", "n", "seed", "with_orientation"}``,
  ``{"kind": "fixed", "points": [{"name", "position" or "fk_q_deg",
  "euler_deg", "convention", "hv_ref_point"}]}`` or ``{"kind": "circle",
  "center", "radius", "n_points", "euler_deg", "convention"}``;
- ``algorithms``: list of ``{"name": registry name, "label": shown name,
  "params": {...}, "optional": bool}`` (an optional algorithm that is not
  registered is left out: baselines that later issues add); ``pop_size``,
  ``archive_size`` (multi-objective only), ``n_gen``, ``runs`` (per target)
  and ``seed`` apply to all;
- ``protocol`` (optional): ``{"threshold", "max_failures"}``, the EOSMA
  re-solve protocol (:func:`moik.experiments.protocol.solve_until_success`);
- ``analyses``: which tables the report prints (:data:`ANALYSES`);
  ``proposed``: label compared with the others; ``success_threshold``;
- ``paper``: the paper's numbers, with their citation, for the report;
- ``quick``: overrides (merged into the dict) for the seconds-long smoke size.

Unknown keys, wrong types and values out of range raise :class:`ConfigError`
naming the file and the key.
"""

from __future__ import annotations

import copy
import hashlib
import json
import re
import runpy
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from moik.exceptions import ConfigError, MoikError
from moik.experiments.targets import check_problem, check_targets

ANALYSES = ("summary", "ranksum", "friedman-hv", "joint-motion", "compromise", "signed-rank",
            "per-target", "per-target-ranksum", "branches")
"""Report tables an experiment can ask for (see :mod:`moik.experiments.analysis`)."""

_TOP_KEYS = {"name", "title", "source", "robot", "problem", "targets", "algorithms", "pop_size",
             "archive_size", "n_gen", "runs", "seed", "protocol", "analyses", "proposed",
             "success_threshold", "paper", "quick", "requires"}
_REQUIRED = ("name", "title", "source", "problem", "algorithms", "pop_size", "n_gen", "runs",
             "seed")
_NAME = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")


def check_int(where: str, value: Any, lo: int) -> int:
    """``value`` as an int >= ``lo`` (bools rejected), else :class:`ConfigError`."""
    if isinstance(value, bool) or not isinstance(value, int) or value < lo:
        raise ConfigError(f"{where} must be an integer >= {lo}, got {value!r}")
    return value


def check_float(where: str, value: Any, *, positive: bool = False) -> float:
    """``value`` as a finite float (> 0 if ``positive``), else :class:`ConfigError`."""
    ok = isinstance(value, (int, float)) and not isinstance(value, bool)
    if not ok or value != value or value in (float("inf"), float("-inf")) or (
            positive and value <= 0):
        kind = "a finite number > 0" if positive else "a finite number"
        raise ConfigError(f"{where} must be {kind}, got {value!r}")
    return float(value)


def check_keys(where: str, spec: Any, allowed: set[str], required: tuple[str, ...] = ()) -> dict:
    """``spec`` as a dict with only ``allowed`` keys and all ``required`` ones."""
    if not isinstance(spec, Mapping):
        raise ConfigError(f"{where} must be a dict, got {type(spec).__name__}")
    unknown = sorted(set(spec) - allowed)
    if unknown:
        raise ConfigError(f"{where}: unknown key(s) {', '.join(unknown)}; "
                          f"expected some of: {', '.join(sorted(allowed))}")
    missing = [k for k in required if k not in spec]
    if missing:
        raise ConfigError(f"{where}: missing key(s) {', '.join(missing)}")
    return dict(spec)


def merge(base: Mapping, overrides: Mapping) -> dict:
    """Deep merge: dicts merge key by key, everything else is replaced."""
    out = copy.deepcopy(dict(base))
    for key, value in overrides.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), Mapping):
            out[key] = merge(out[key], value)
        else:
            out[key] = copy.deepcopy(value)
    return out


@dataclass(frozen=True)
class AlgorithmSpec:
    """One algorithm of an experiment: registry ``name``, shown ``label``, ``params``."""

    name: str
    label: str
    params: dict
    multi_objective: bool


def _algorithms(where: str, raw: Any, cfg: Mapping
                ) -> tuple[tuple[AlgorithmSpec, ...], tuple[str, ...]]:
    from moik.algorithms import available, get_algorithm
    from moik.algorithms.registry import accepted_parameters

    if not isinstance(raw, list) or not raw:
        raise ConfigError(f"{where} must be a non-empty list of algorithms")
    if any(isinstance(e, Mapping) and e.get("optional", False) not in (True, False) for e in raw):
        raise ConfigError(f"{where}: optional must be true or false")
    specs, labels, skipped = [], set(), []
    for i, entry in enumerate(raw):
        w = f"{where}[{i}]"
        entry = check_keys(w, entry, {"name", "label", "params", "optional"}, ("name",))
        name = entry["name"]
        if entry.get("optional", False) and name not in available():
            skipped.append(name)
            continue
        if name not in available():
            raise ConfigError(f"{w}.name: unknown algorithm {name!r}; expected one of: "
                              f"{', '.join(available())}")
        label = entry.get("label", name)
        if not isinstance(label, str) or not _NAME.match(label) or label in labels:
            raise ConfigError(f"{w}.label must be a unique lower-case name, got {label!r}")
        labels.add(label)
        params = dict(check_keys(f"{w}.params", entry.get("params", {}),
                                 set(accepted_parameters(name))))
        params.setdefault("pop_size", cfg["pop_size"])
        if cfg.get("archive_size") is not None and "archive_size" in accepted_parameters(name):
            params.setdefault("archive_size", cfg["archive_size"])
        try:
            algorithm = get_algorithm(name, **params)
        except MoikError as exc:
            raise ConfigError(f"{w}.params: {exc}") from None
        multi = ".moo." in type(algorithm).__module__
        specs.append(AlgorithmSpec(name=name, label=label, params=params, multi_objective=multi))
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
        skipped: Optional algorithms left out because they are not registered.
        is_quick: Whether this is the quick size.
        path: The file it came from, if any.
    """

    name: str
    raw: dict
    quick_overrides: dict
    algorithms: tuple[AlgorithmSpec, ...]
    skipped: tuple[str, ...] = ()
    is_quick: bool = False
    path: str | None = None

    @classmethod
    def from_dict(cls, data: Mapping, *, path: str | None = None,
                  is_quick: bool = False) -> ExperimentConfig:
        """Validate ``data`` (the ``EXPERIMENT`` dict) and build the config.

        Raises:
            ConfigError: Naming the key and what was expected.
        """
        where = path or "experiment"
        cfg = check_keys(where, data, _TOP_KEYS, _REQUIRED)
        quick = check_keys(f"{where}: quick", cfg.pop("quick", {}), _TOP_KEYS - {"quick", "name"})
        name = cfg["name"]
        if not isinstance(name, str) or not _NAME.match(name):
            raise ConfigError(f"{where}: name must be lower-case words joined by '-', got {name!r}")
        for key in ("title", "source"):
            if not isinstance(cfg[key], str) or not cfg[key]:
                raise ConfigError(f"{where}: {key} must be a non-empty string")
        from moik.experiments.benchmark import check_benchmark_experiment, is_benchmark
        from moik.robots import available_robots

        if is_benchmark(cfg["problem"]):
            cfg["problem"] = check_benchmark_experiment(where, cfg)
        elif "robot" not in cfg or "targets" not in cfg or "requires" in cfg:
            raise ConfigError(f"{where}: an IK experiment needs 'robot' and 'targets' (and takes "
                              "no 'requires')")
        elif cfg["robot"] not in available_robots():
            raise ConfigError(f"{where}: robot: unknown robot {cfg['robot']!r}; expected one of: "
                              f"{', '.join(available_robots())}")
        check_int(f"{where}: pop_size", cfg["pop_size"], 1)
        if cfg.get("archive_size") is not None:
            check_int(f"{where}: archive_size", cfg["archive_size"], 1)
        check_int(f"{where}: n_gen", cfg["n_gen"], 1)
        check_int(f"{where}: runs", cfg["runs"], 1)
        check_int(f"{where}: seed", cfg["seed"], 0)
        if not is_benchmark(cfg["problem"]):
            cfg["problem"] = check_problem(f"{where}: problem", cfg["problem"], cfg["robot"])
            check_targets(f"{where}: targets", cfg["targets"], cfg["problem"])
        problem = cfg["problem"]
        algorithms, skipped = _algorithms(f"{where}: algorithms", cfg["algorithms"], cfg)
        want_mo = problem["kind"] == "bi-objective"
        for a in algorithms:
            if a.multi_objective != want_mo:
                kind = "multi-objective" if a.multi_objective else "single-objective"
                raise ConfigError(f"{where}: algorithm {a.name!r} is {kind} but the problem kind "
                                  f"is {problem['kind']!r}")
        _check_rest(where, cfg, algorithms, want_mo)
        return cls(name=name, raw=cfg, quick_overrides=quick, algorithms=algorithms,
                   skipped=skipped, is_quick=is_quick, path=path)

    def quick(self) -> ExperimentConfig:
        """The quick (smoke-test) size: ``raw`` with the ``quick`` overrides merged."""
        if self.is_quick:
            return self
        return ExperimentConfig.from_dict(merge(self.raw, self.quick_overrides), path=self.path,
                                          is_quick=True)

    def __getitem__(self, key: str) -> Any:
        return self.raw.get(key)

    @property
    def labels(self) -> list[str]:
        """Algorithm labels in report order."""
        return [a.label for a in self.algorithms]

    def fingerprint(self) -> str:
        """SHA-256 of ``raw`` and the algorithms present (identifies a run's configuration)."""
        text = json.dumps([self.raw, self.labels], sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()


def _check_rest(where: str, cfg: dict, algorithms: tuple[AlgorithmSpec, ...],
                multi: bool) -> None:
    labels = [a.label for a in algorithms]
    if cfg.get("protocol") is not None:
        if multi:
            raise ConfigError(f"{where}: protocol applies to single-objective problems only")
        p = check_keys(f"{where}: protocol", cfg["protocol"], {"threshold", "max_failures"},
                       ("threshold", "max_failures"))
        check_float(f"{where}: protocol.threshold", p["threshold"], positive=True)
        check_int(f"{where}: protocol.max_failures", p["max_failures"], 1)
    if "success_threshold" in cfg:
        check_float(f"{where}: success_threshold", cfg["success_threshold"], positive=True)
    analyses = cfg.get("analyses", ["summary"])
    if not isinstance(analyses, list) or any(a not in ANALYSES for a in analyses):
        raise ConfigError(f"{where}: analyses must be a list of: {', '.join(ANALYSES)}; "
                          f"got {analyses!r}")
    proposed = cfg.get("proposed")
    if proposed is not None and proposed not in labels:
        raise ConfigError(f"{where}: proposed {proposed!r} is not an algorithm label: "
                          f"{', '.join(labels)}")
    if {"ranksum", "signed-rank"} & set(analyses) and proposed is None:
        raise ConfigError(f"{where}: analyses ranksum/signed-rank need 'proposed'")
    if "paper" in cfg and not isinstance(cfg["paper"], Mapping):
        raise ConfigError(f"{where}: paper must be a dict of the paper's numbers")


def load_config(path: str | Path) -> ExperimentConfig:
    """Load and validate the experiment defined by the file ``path``.

    Raises:
        ConfigError: If the file is missing, does not define a dict ``EXPERIMENT``,
            fails to execute, or the dict is invalid.
    """
    p = Path(path)
    if not p.is_file():
        raise ConfigError(f"experiment file {str(p)!r} does not exist")
    try:
        namespace = runpy.run_path(str(p))
    except Exception as exc:  # any failure of a config file is a config error
        raise ConfigError(f"{p}: cannot be executed: {type(exc).__name__}: {exc}") from None
    data = namespace.get("EXPERIMENT")
    if not isinstance(data, Mapping):
        raise ConfigError(f"{p}: must define a dict named EXPERIMENT")
    config = ExperimentConfig.from_dict(data, path=str(p))
    if p.stem.replace("_", "-") != config.name:
        raise ConfigError(f"{p}: name {config.name!r} must match the file name "
                          f"({p.stem.replace('_', '-')!r})")
    return config
