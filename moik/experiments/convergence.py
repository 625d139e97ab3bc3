"""A trial's algorithm, built so that its best-so-far curve is recorded, and that curve.

moik's array-state algorithms record ``convergence`` (best f per generation)
themselves; pymoo's single-objective ones (``ga``, ``pymoo-de``) get a
:class:`BestF` callback that does the same.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.callback import Callback

from moik.algorithms.base import ArrayAlgorithm
from moik.algorithms.registry import get_algorithm, is_multi_objective
from moik.experiments.spec import TrialSpec


class BestF(Callback):
    """Best f per generation, for pymoo algorithms without ``convergence``."""

    def notify(self, algorithm) -> None:
        opt = algorithm.opt
        F = None if opt is None else opt.get("F")
        self.data.setdefault("best", []).append(float(np.min(F)) if F is not None and len(F)
                                                else np.inf)


def algorithm_factory(spec: TrialSpec, created: list) -> Callable[[], Algorithm]:
    """A factory of the trial's algorithm; every algorithm it builds is appended to ``created``.

    A pymoo single-objective algorithm gets a :class:`BestF` callback.
    """
    single_objective = not is_multi_objective(spec.algorithm)

    def factory() -> Algorithm:
        algorithm = get_algorithm(spec.algorithm, **spec.params)
        if single_objective and not isinstance(algorithm, ArrayAlgorithm):
            algorithm.callback = BestF()
        created.append(algorithm)
        return algorithm

    return factory


def convergence_curve(algorithm: Algorithm) -> np.ndarray:
    """The best-so-far f per generation of a finished algorithm (empty if not recorded)."""
    if hasattr(algorithm, "convergence"):
        return np.asarray(algorithm.convergence, dtype=float)
    cb = getattr(algorithm, "callback", None)
    return np.asarray(cb.data.get("best", []) if isinstance(cb, BestF) else [], dtype=float)
