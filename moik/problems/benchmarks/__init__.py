"""Benchmark problems of the I-BES and MChOA papers: classical F1-F23, CEC2017, engineering design.

* ``F1`` ... ``F23``: the classical functions of the MChOA paper's Table 2
  (:mod:`moik.problems.benchmarks.classical`, :mod:`moik.problems.benchmarks.fixed`).
* ``cec2017_F<i>``: official CEC2017 functions used by the I-BES paper
  (Section 5.2), through the optional dependency minionpy, a port of the
  official C code (:mod:`moik.problems.benchmarks.cec2017`).
* ``spring``, ``pressure_vessel``: the constrained design problems of the
  I-BES paper, Section 5.3 (:mod:`moik.problems.benchmarks.engineering`).
* ``F24``: the MChOA paper's IRB-2600 pose IK objective (Eq. 6), with the
  weights and target moik chooses (:mod:`moik.problems.benchmarks.irb2600_ik`).

Every problem exposes its known optimum as ``f_opt`` (and ``pareto_front()``).
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable

from pymoo.core.problem import Problem

from moik.exceptions import ParameterError, UnknownNameError
from moik.problems.benchmarks import classical, fixed
from moik.problems.benchmarks.cec2017 import CEC2017, IBES_FUNCTIONS
from moik.problems.benchmarks.engineering import PressureVessel, SpringDesign
from moik.problems.benchmarks.irb2600_ik import IRB2600PoseIK

_CLASSICAL: dict[str, Callable[..., Problem]] = {
    f"F{i}": getattr(classical if i <= 13 else fixed, f"F{i}") for i in range(1, 24)
}
_CEC: dict[str, Callable[..., Problem]] = {
    f"cec2017_F{i}": functools.partial(CEC2017, i) for i in IBES_FUNCTIONS
}
_REGISTRY: dict[str, Callable[..., Problem]] = {
    **_CLASSICAL,
    "F24": IRB2600PoseIK,
    **_CEC,
    "spring": SpringDesign,
    "pressure_vessel": PressureVessel,
}


def available_benchmarks() -> list[str]:
    """Return the registered benchmark names (F1-F24, cec2017_F*, engineering)."""
    return list(_REGISTRY)


def get_benchmark(name: str, **kwargs: object) -> Problem:
    """Build a registered benchmark problem by name.

    Args:
        name: A name from :func:`available_benchmarks`, e.g. ``"F9"``,
            ``"cec2017_F30"``, ``"spring"``.
        **kwargs: The problem's own keyword arguments (e.g. ``n_var`` for the
            scalable F1-F13 and CEC2017, ``noise``/``seed`` for F7,
            ``discrete`` for ``pressure_vessel``).

    Returns:
        The pymoo Problem.

    Raises:
        UnknownNameError: If ``name`` is not registered.
        ParameterError: If a keyword is not accepted by that problem.
    """
    try:
        factory = _REGISTRY[name]
    except (KeyError, TypeError):
        raise UnknownNameError("benchmark", name, _REGISTRY) from None
    signature = inspect.signature(factory)
    unknown = sorted(set(kwargs) - set(signature.parameters))
    if unknown:
        accepted = ", ".join(signature.parameters) or "none"
        raise ParameterError(
            f"benchmark {name!r} got unknown keyword(s) {unknown}; accepted: {accepted}"
        )
    return factory(**kwargs)


__all__ = [
    "CEC2017",
    "IRB2600PoseIK",
    "PressureVessel",
    "SpringDesign",
    "available_benchmarks",
    "get_benchmark",
]
