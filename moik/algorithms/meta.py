"""moik's algorithms inside pymoo's ``MetaAlgorithm`` wrappers.

pymoo's constraint-handling wrappers wrap an algorithm object
(``AdaptiveEpsilonConstraintHandling(algorithm)``, pymoo/constraints/adaptive.py): the
wrapper shares the algorithm's ``__dict__`` and puts its own class first in the method
order. ``AdaptiveConstraintHandling._setup`` does not call the wrapped algorithm's
``_setup``, where moik's algorithms (and pymoo's MOEA/D and MOPSO-CD) read the problem:
bounds, sizes, reference directions, velocity limits. :func:`setup_through_wrapper` runs
pymoo's ``setup`` and then, where a wrapper skipped it, the algorithm's own ``_setup``
chain, which then reads the problem pymoo handed to ``setup``.

Each ``_setup`` of an algorithm that uses this sets ``_problem_read = True`` first.
"""

from __future__ import annotations

from collections.abc import Callable

from pymoo.core.algorithm import Algorithm
from pymoo.core.meta import Meta

__all__ = ["setup_through_wrapper"]


def setup_through_wrapper(algorithm: Algorithm, setup: Callable, problem, **kwargs) -> None:
    """``setup(problem, **kwargs)`` (pymoo's ``Algorithm.setup``, bound), then the
    algorithm's own ``_setup`` chain if a wrapper's ``_setup`` replaced it (module doc).

    Args:
        algorithm: The algorithm (possibly seen through a pymoo ``Meta`` wrapper).
        setup: pymoo's ``setup`` bound to it (``super().setup``).
        problem: The problem pymoo hands to ``setup``.
        **kwargs: The options of ``setup`` (termination, seed ...).
    """
    algorithm.__dict__["_problem_read"] = False
    setup(problem, **kwargs)
    if algorithm.__dict__.get("_problem_read"):
        return
    for klass in type(algorithm).__mro__:
        if not issubclass(klass, Meta) and "_setup" in vars(klass):
            vars(klass)["_setup"](algorithm, problem, **kwargs)
            return
