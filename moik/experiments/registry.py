"""Where experiments are found: one config file per table or figure.

The folders searched, in order:

1. the papers' configs shipped with moik: when moik runs from a source checkout
   (a ``pyproject.toml`` beside the ``moik`` package), that checkout's
   ``experiments/`` folder, so that the code and its configs come from one tree
   (an editable install made from another checkout maps the package to that
   checkout's folder); otherwise the package ``moik.paper_configs``, which is the
   repository's top-level ``experiments/`` folder mapped into the package
   (``pyproject.toml``), found with :mod:`importlib.resources`;
2. every folder in the environment variable ``MOIK_EXPERIMENTS_PATH``
   (:data:`ENV_VAR`, ``os.pathsep``-separated): a user's own configs.

Each ``*.toml`` file not starting with ``_`` is one experiment named after the
file (``eosma_table5.toml`` -> ``eosma-table5``); it is data, never run
(:mod:`moik.experiments.config_files`). Adding an experiment = dropping
a file in such a folder; a later folder's file replaces an earlier one of the
same name. :func:`get_experiment` also takes the path of a config file
(``moik experiment run --config FILE``).
"""

from __future__ import annotations

import os
from importlib import resources
from pathlib import Path

from moik.exceptions import UnknownNameError
from moik.experiments.config import ExperimentConfig, load_config

ENV_VAR = "MOIK_EXPERIMENTS_PATH"
"""Environment variable: extra folders of experiment configs, ``os.pathsep``-separated."""

PACKAGE = "moik.paper_configs"
"""The package that holds the papers' configs (the repository's ``experiments/``)."""

_CHECKOUT = Path(__file__).resolve().parents[2] / "experiments"


def packaged_dir() -> Path | None:
    """The folder of the papers' configs, or None if moik has none.

    A source checkout's own ``experiments/`` (beside the ``moik`` package it runs
    from); else the installed package :data:`PACKAGE` if importable.
    """
    if (_CHECKOUT / "__init__.py").is_file() and (_CHECKOUT.parent / "pyproject.toml").is_file():
        return _CHECKOUT
    try:
        root = resources.files(PACKAGE)
    except ModuleNotFoundError:
        root = None
    if isinstance(root, Path) and root.is_dir():
        return root
    return None


def experiment_dirs() -> list[Path]:
    """The folders searched for experiment files, existing ones only."""
    packaged = packaged_dir()
    dirs = [] if packaged is None else [packaged]
    dirs += [Path(p) for p in os.environ.get(ENV_VAR, "").split(os.pathsep) if p]
    return [d for d in dirs if d.is_dir()]


def experiment_files() -> dict[str, Path]:
    """Experiment name -> config file."""
    found: dict[str, Path] = {}
    for folder in experiment_dirs():
        for path in sorted(folder.glob("*.toml")):
            if not path.name.startswith("_"):
                found[path.stem.replace("_", "-")] = path
    return dict(sorted(found.items()))


def available_experiments() -> list[str]:
    """Names accepted by :func:`get_experiment`, sorted."""
    return list(experiment_files())


def get_experiment(name: str) -> ExperimentConfig:
    """Load the experiment ``name`` (or the config file at path ``name``).

    Raises:
        UnknownNameError: Listing the available experiments.
        ConfigError: If the file is invalid.
    """
    files = experiment_files()
    if name in files:
        return load_config(files[name], files)
    if name.endswith((".toml", ".py")) or os.sep in name:
        return load_config(name, files)
    raise UnknownNameError("experiment", name, files)
