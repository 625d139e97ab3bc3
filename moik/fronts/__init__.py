"""Reference Pareto fronts of multi-objective IK problems (maths in
:mod:`moik.fronts.front`, :mod:`moik.fronts.scalarised`, :mod:`moik.fronts.kernels`;
the on-disk cache in :mod:`moik.fronts.cache`)."""

from moik.fronts.front import (
    METHOD_VERSION,
    ReferenceFront,
    bi_objective_front,
    dominating_points,
)

__all__ = ["METHOD_VERSION", "ReferenceFront", "bi_objective_front", "dominating_points"]
