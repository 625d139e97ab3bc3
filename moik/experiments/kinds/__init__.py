"""The experiment kinds: IK problems on robot arms, and benchmark functions.

A kind is a module with ``PROBLEM_KINDS`` (the ``problem.kind`` values it
takes), ``check_config(where, cfg)`` (validates its part of a config by
building it; returns the problem dict and the targets) and
``run_trial(spec, record, arrays)``. The kind of an experiment is chosen once,
from its ``problem.kind``, when the config is validated
(:func:`kind_of`); its name travels in every :class:`~moik.experiments.spec.TrialSpec`.

- ``"ik"`` (:mod:`moik.experiments.kinds.ik`): ``position``, ``pose``, ``bi-objective``;
- ``"functions"`` (:mod:`moik.experiments.kinds.functions`): ``benchmark``.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import ModuleType
from typing import Any

from moik.exceptions import ConfigError
from moik.experiments.kinds import functions, ik

KINDS: dict[str, ModuleType] = {"ik": ik, "functions": functions}
"""Kind name -> its module."""

_BY_PROBLEM_KIND = {pk: name for name, module in KINDS.items() for pk in module.PROBLEM_KINDS}


def kind_of(where: str, problem: Any) -> str:
    """The kind name of an experiment whose ``problem`` dict is ``problem``.

    Raises:
        ConfigError: If ``problem`` is not a dict or its ``kind`` is unknown.
    """
    if not isinstance(problem, Mapping):
        raise ConfigError(f"{where} must be a dict, got {type(problem).__name__}")
    kind = problem.get("kind")
    if not isinstance(kind, str) or kind not in _BY_PROBLEM_KIND:
        raise ConfigError(f"{where}.kind must be one of {', '.join(_BY_PROBLEM_KIND)}, "
                          f"got {kind!r}")
    return _BY_PROBLEM_KIND[kind]


__all__ = ["KINDS", "functions", "ik", "kind_of"]
