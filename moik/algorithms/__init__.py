"""Optimization algorithms: array-state single- and multi-objective metaheuristics, a registry.

Every class registered in :mod:`moik.algorithms.registry` (the one list of
algorithms, with each one's kind and source) is importable from here, with the
registry functions and the two array-state bases. They load at first use
(PEP 562): importing every algorithm and pymoo's own is a large part of a process's
start-up, which code that needs one module of this package (an archive, a kernel) or
the solver's first stage need not pay (docs/performance.md, "Compilation and start-up").
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from moik.algorithms import registry as registry
    from moik.algorithms.base import ArrayAlgorithm as ArrayAlgorithm
    from moik.algorithms.moo.base import MOArrayAlgorithm as MOArrayAlgorithm
    from moik.algorithms.registry import *  # noqa: F403

_BASES = {"ArrayAlgorithm": "moik.algorithms.base", "MOArrayAlgorithm": "moik.algorithms.moo.base"}


def _registry() -> Any:
    return importlib.import_module("moik.algorithms.registry")


def __getattr__(name: str) -> Any:
    """``registry``, the bases, ``__all__`` and the registry's names, loaded at first use."""
    if name in _BASES:
        value = getattr(importlib.import_module(_BASES[name]), name)
    elif name == "registry":
        value = _registry()
    elif name == "__all__":
        value = ["ArrayAlgorithm", "MOArrayAlgorithm", *_registry().__all__]
    elif name in _registry().__all__:
        value = getattr(_registry(), name)
    else:
        raise AttributeError(f"module 'moik.algorithms' has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__getattr__("__all__")})
