"""The experiment kinds: IK problems on robot arms, and benchmark functions.

A kind is a module with ``PROBLEM_KINDS`` (the ``problem.kind`` values it
takes), ``check_config(where, cfg, folder)`` (validates its part of a config by
building it, relative paths read from ``folder``; returns the problem dict and the
targets, and may put a key's checked form back into ``cfg``) and
``run_trial(spec, record, arrays)``; optionally ``MULTI_OBJECTIVE`` (those of
its problem kinds that take multi-objective algorithms) and ``BASELINES``
(algorithm names it runs itself, beside the registry's, each with the keywords
it takes). The kind of an experiment is chosen once,
from its ``problem.kind``, when the config is validated
(:func:`kind_of`); its name travels in every :class:`~moik.experiments.spec.TrialSpec`.

- ``"ik"`` (:mod:`moik.experiments.kinds.ik`): ``position``, ``pose``, ``bi-objective``
  (the robot: :mod:`moik.experiments.kinds.ik_robot`);
- ``"functions"`` (:mod:`moik.experiments.kinds.functions`): ``benchmark``;
- ``"moo-functions"`` (:mod:`moik.experiments.kinds.moo_functions`): ``moo-benchmark``
  (ZDT/DTLZ problems with analytic fronts, and the ``random-search`` baseline).
"""

from __future__ import annotations

from collections.abc import Mapping
from types import ModuleType
from typing import Any

from moik.exceptions import ConfigError
from moik.experiments.kinds import functions, ik, moo_functions

KINDS: dict[str, ModuleType] = {"ik": ik, "functions": functions,
                                 "moo-functions": moo_functions}
"""Kind name -> its module."""

_BY_PROBLEM_KIND = {pk: name for name, module in KINDS.items() for pk in module.PROBLEM_KINDS}

MULTI_OBJECTIVE_PROBLEMS = frozenset(pk for module in KINDS.values()
                                     for pk in getattr(module, "MULTI_OBJECTIVE", ()))
"""The ``problem.kind`` values whose algorithms are multi-objective."""


def baselines(kind: str) -> dict[str, tuple[str, ...]]:
    """The baselines the kind ``kind`` runs itself: name -> the keywords each takes."""
    return dict(getattr(KINDS[kind], "BASELINES", {}))


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


__all__ = ["KINDS", "MULTI_OBJECTIVE_PROBLEMS", "baselines", "functions", "ik", "kind_of",
           "moo_functions"]
