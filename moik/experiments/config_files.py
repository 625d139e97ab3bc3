"""Reading an experiment config file: TOML data, never code, with ``extends`` for variants.

A config file is TOML (parsed by the standard library's :mod:`tomllib`; ``tomli`` on
Python 3.10: :mod:`moik._toml`) holding the keys :mod:`moik.experiments.config` describes at its top
level. TOML has no null: where a config needs one (a free joint in
``problem.locked_joints_deg``) it says ``"free"``.

``extends = "base-name"`` makes the file a variant: the base experiment's data
(found by name among the known config files, else beside the file; the base may
extend another) deep-merged with the file's own keys (:func:`merge`: tables merge
key by key, everything else replaces), so a variant states only what differs.
A Python file, or a file that is not valid TOML, is refused with a
:class:`~moik.exceptions.ConfigError`: a config is never run.
"""

from __future__ import annotations

import copy
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from moik._paths import file_name
from moik._validate import reading as _reading
from moik.exceptions import ConfigError

SUFFIX = ".toml"
"""The file suffix of a config file."""


def merge(base: Mapping, overrides: Mapping) -> dict:
    """Deep merge: dicts merge key by key, everything else is replaced."""
    out = copy.deepcopy(dict(base))
    for key, value in overrides.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), Mapping):
            out[key] = merge(out[key], value)
        else:
            out[key] = copy.deepcopy(value)
    return out


def name_of(path: Path) -> str:
    """The experiment name a file must define (``eosma_table5.toml`` -> ``eosma-table5``)."""
    return path.stem.replace("_", "-")


def _parse(path: Path) -> dict[str, Any]:
    if not path.exists():
        raise ConfigError(f"experiment file {str(path)!r} does not exist")
    if not path.is_file():
        raise ConfigError(f"experiment file {str(path)!r} is not a regular file")
    if path.suffix.lower() != SUFFIX:
        what = "Python code, which moik does not run" if path.suffix == ".py" else \
            f"a {path.suffix or 'suffix-less'} file"
        raise ConfigError(f"{path}: experiment configs are TOML data files ({SUFFIX}); this is "
                          f"{what}: write the EXPERIMENT keys as TOML (see the configs in "
                          "moik's experiments/ folder)")
    return _reading.read_toml(path, "experiment file", ConfigError)


def read_config(path: str | Path, bases: Mapping[str, Path] | None = None,
                _seen: tuple[str, ...] = ()) -> dict[str, Any]:
    """The data of the config file ``path``, its ``extends`` chain merged in.

    Args:
        path: The ``.toml`` file.
        bases: Experiment name -> config file, where an ``extends`` name is looked up
            first (the registry's files); then the files beside ``path``.

    Raises:
        ConfigError: A missing, non-TOML or invalid file, an unknown or cyclic base.
    """
    p = Path(path)
    data = _parse(p)
    base_name = data.pop("extends", None)
    if base_name is None:
        return data
    if not isinstance(base_name, str) or not base_name:
        raise ConfigError(f"{p}: extends must be the name of another experiment, got "
                          f"{base_name!r}")
    file_name(base_name, f"{p}: extends", error=ConfigError)
    if base_name in (*_seen, name_of(p)):
        raise ConfigError(f"{p}: extends {base_name!r} makes a cycle "
                          f"({' -> '.join((*_seen, name_of(p), base_name))})")
    sibling = p.with_name(base_name.replace("-", "_") + SUFFIX)
    base_path = (bases or {}).get(base_name) or (sibling if sibling.is_file() else None)
    if base_path is None:
        known = sorted({*(bases or {}), *(name_of(f) for f in p.parent.glob(f"*{SUFFIX}"))})
        raise ConfigError(f"{p}: extends {base_name!r}, which is not a known experiment "
                          f"(known: {', '.join(known)})")
    base = read_config(base_path, bases, (*_seen, name_of(p)))
    merged = merge(base, data)
    if isinstance(base.get("paper"), dict) and "paper" not in data:
        # the paper's numbers come with the base's budget: a variant that changes it is
        # marked in its report (moik.experiments.tables.Results)
        merged["paper"].setdefault("budget", budget_of(base))
    return merged


def budget_of(config: Mapping) -> dict[str, int]:
    """What sets an experiment's budget (a paper's numbers compare with a run at the
    same): ``iterations``, ``pop_size`` and the problem's ``evaluations``, those the
    config's data sets."""
    values = {"iterations": config.get("iterations"), "pop_size": config.get("pop_size"),
              "evaluations": (config.get("problem") or {}).get("evaluations")}
    return {k: v for k, v in values.items() if v is not None}


def budget_text(budget: Mapping) -> str:
    """``1000 iterations, population 100`` (or ``10000 evaluations``) in words."""
    if budget.get("evaluations"):
        return f"{budget['evaluations']} evaluations"
    parts = ([f"{budget['iterations']} iterations"] if "iterations" in budget else []) + (
        [f"population {budget['pop_size']}"] if "pop_size" in budget else [])
    return ", ".join(parts) or "its budget"
