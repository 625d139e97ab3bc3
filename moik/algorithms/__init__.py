"""Optimization algorithms: array-state single- and multi-objective metaheuristics, a registry.

Every class registered in :mod:`moik.algorithms.registry` (the one list of
algorithms, with each one's kind and source) is importable from here, with the
registry functions and the two array-state bases.
"""

from moik.algorithms import registry
from moik.algorithms.base import ArrayAlgorithm
from moik.algorithms.moo.base import MOArrayAlgorithm
from moik.algorithms.registry import *  # noqa: F403  (the registry's __all__: its classes)

__all__ = ["ArrayAlgorithm", "MOArrayAlgorithm", *registry.__all__]
