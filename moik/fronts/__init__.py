"""Reference Pareto fronts of multi-objective IK problems (maths in
:mod:`moik.fronts.front`, :mod:`moik.fronts.motion`, :mod:`moik.fronts.scalarised`,
:mod:`moik.fronts.kernels`; the on-disk cache in :mod:`moik.fronts.cache`).

The names load at first use: the IK problems import this package for
``pareto_front()``, which a solve never calls (start-up time).
"""

from typing import TYPE_CHECKING

from moik._lazy import lazy_names

if TYPE_CHECKING:
    from moik.fronts.front import (
        METHOD_VERSION,
        ReferenceFront,
        bi_objective_front,
        dominating_points,
    )
    from moik.fronts.motion import motion_front

_LAZY: dict[str, tuple[str, str | None]] = {
    **{name: ("moik.fronts.front", name)
       for name in ("METHOD_VERSION", "ReferenceFront", "bi_objective_front",
                    "dominating_points")},
    "motion_front": ("moik.fronts.motion", "motion_front"),
}

__all__ = ["METHOD_VERSION", "ReferenceFront", "bi_objective_front", "dominating_points",
           "motion_front"]

__getattr__, __dir__ = lazy_names("moik.fronts", _LAZY, globals(), __all__)
