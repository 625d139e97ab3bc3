"""Where experiments are found: one config file per table or figure.

The folders searched, in order: the ``experiments/`` folder next to the moik
package (the repository's), then every folder in the environment variable
``MOIK_EXPERIMENTS_PATH`` (``os.pathsep``-separated). Each ``*.py`` file not
starting with ``_`` is one experiment named after the file (``eosma_table5.py``
-> ``eosma-table5``). Adding an experiment = dropping a file there; a later
folder's file replaces an earlier one of the same name. ``NAME`` may also be
the path of a config file.
"""

from __future__ import annotations

import os
from pathlib import Path

from moik.exceptions import UnknownNameError
from moik.experiments.config import ExperimentConfig, load_config

ENV_VAR = "MOIK_EXPERIMENTS_PATH"


def experiment_dirs() -> list[Path]:
    """The folders searched for experiment files, existing ones only."""
    dirs = [Path(__file__).resolve().parents[2] / "experiments"]
    dirs += [Path(p) for p in os.environ.get(ENV_VAR, "").split(os.pathsep) if p]
    return [d for d in dirs if d.is_dir()]


def experiment_files() -> dict[str, Path]:
    """Experiment name -> config file."""
    found: dict[str, Path] = {}
    for folder in experiment_dirs():
        for path in sorted(folder.glob("*.py")):
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
        return load_config(files[name])
    if name.endswith(".py") or os.sep in name:
        return load_config(name)
    raise UnknownNameError("experiment", name, files)
