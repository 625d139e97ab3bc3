"""Algorithm registry: ``get_algorithm(name, **params)`` and ``available()``.

moik's own algorithms validate their hyperparameters in ``__init__`` (a bad value
raises :class:`~moik.exceptions.ParameterError` with the valid range). pymoo's
DE (as ``pymoo-de``; ``de`` is moik's array-state DE/rand/1/bin) and ``ga`` are
registered as they are, for comparisons; for every entry an
unknown keyword raises ``ParameterError`` naming the accepted ones (pymoo's
classes would otherwise swallow it through ``**kwargs``).

Later issues add entries with :func:`register`, either as
``register("name", cls)`` or as a class decorator ``@register("name")``.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable

from pymoo.algorithms.moo.mopso_cd import MOPSO_CD
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.algorithms.moo.sms import SMSEMOA
from pymoo.algorithms.soo.nonconvex.de import DE as PymooDE  # noqa: N811
from pymoo.algorithms.soo.nonconvex.ga import GA
from pymoo.core.algorithm import Algorithm

from moik.algorithms.moo.mo_csa import MOCSA
from moik.algorithms.moo.mo_jaya import MOJAYA
from moik.algorithms.moo.mo_pso import MOClassicPSO
from moik.algorithms.moo.moalo import MOALO
from moik.algorithms.moo.moda import MODA
from moik.algorithms.moo.moeosma import MOEOSMA
from moik.algorithms.moo.mogwo import MOGWO
from moik.algorithms.moo.mompa import MOMPA
from moik.algorithms.moo.mompso import MOMPSO
from moik.algorithms.moo.momvo import MOMVO
from moik.algorithms.moo.mopso import MOPSO
from moik.algorithms.moo.mosma import MOSMA
from moik.algorithms.moo.mssa import MSSA
from moik.algorithms.moo.pymoo_moo import MOEAD
from moik.algorithms.soo.bes import BES, IBES
from moik.algorithms.soo.choa import CChOA, ChOA, MChOA, OChOA, OIChOA, WChOA
from moik.algorithms.soo.code import CODE
from moik.algorithms.soo.cpso_at import CPSOAT
from moik.algorithms.soo.csa import CSA
from moik.algorithms.soo.de import DE
from moik.algorithms.soo.eo import EO
from moik.algorithms.soo.eosma import EOSMA
from moik.algorithms.soo.fa import FA
from moik.algorithms.soo.fpa import FPA
from moik.algorithms.soo.gbo import GBO
from moik.algorithms.soo.hho import HHO
from moik.algorithms.soo.igwo import IGWO
from moik.algorithms.soo.jaya import JAYA
from moik.algorithms.soo.mpa import MPA
from moik.algorithms.soo.mpso import MPSO
from moik.algorithms.soo.mrfo import MRFO
from moik.algorithms.soo.mtde import MTDE
from moik.algorithms.soo.mtsa import MTSA
from moik.algorithms.soo.pfa import PFA
from moik.algorithms.soo.pso import PSO
from moik.algorithms.soo.psogsa import PSOGSA
from moik.algorithms.soo.sass import SASS
from moik.algorithms.soo.sma import SMA
from moik.algorithms.soo.ssa import SSA
from moik.algorithms.soo.tlbo import TLBO
from moik.exceptions import ParameterError, UnknownNameError

_REGISTRY: dict[str, type[Algorithm]] = {
    "eosma": EOSMA,
    "sma": SMA,
    "eo": EO,
    "m-pso": MPSO,
    "pso": PSO,
    "de": DE,
    "pymoo-de": PymooDE,
    # EOSMA paper baselines (issue 7)
    "mrfo": MRFO,
    "mpa": MPA,
    "pfa": PFA,
    "fpa": FPA,
    "gbo": GBO,
    "tlbo": TLBO,
    "hho": HHO,
    "igwo": IGWO,
    "psogsa": PSOGSA,
    "code": CODE,
    "mtde": MTDE,
    "sass": SASS,
    "ga": GA,
    # I-BES and MChOA papers and their comparisons (issue 8)
    "bes": BES,
    "ibes": IBES,
    "fa": FA,
    "mtsa": MTSA,
    "cpso-at": CPSOAT,
    "choa": ChOA,
    "cchoa": CChOA,
    "oichoa": OIChOA,
    "ochoa": OChOA,
    "wchoa": WChOA,
    "mchoa": MChOA,
    "ssa": SSA,
    "csa": CSA,
    "jaya": JAYA,
    # multi-objective (issue 4): moik's array-state algorithms, then pymoo's for comparisons
    "moeosma": MOEOSMA,
    "mo-m-pso": MOMPSO,
    # Mirjalili baselines of the EOSMA paper, Table 4
    "mssa": MSSA,
    "moalo": MOALO,
    "moda": MODA,
    "momvo": MOMVO,
    "mogwo": MOGWO,
    "mosma": MOSMA,
    "mopso": MOPSO,
    "mompa": MOMPA,
    "mo-pso": MOClassicPSO,
    "mo-jaya": MOJAYA,
    "mo-csa": MOCSA,
    "nsga2": NSGA2,
    "moead": MOEAD,
    "sms-emoa": SMSEMOA,
    "mopso-cd": MOPSO_CD,
}


# Keywords a class forwards through **kwargs to a collaborator (pymoo's DE -> Variant).
_FORWARDED: dict[type, tuple[str, ...]] = {
    PymooDE: ("CR", "F", "jitter", "prob_mut", "control", "crossover", "selection", "n_diffs"),
}


def register(name: str, cls: type[Algorithm] | None = None) -> Callable | type[Algorithm]:
    """Register ``cls`` under ``name`` (lower case); usable as a class decorator.

    Raises:
        ParameterError: If ``name`` is already taken by another class.
    """

    def add(klass: type[Algorithm]) -> type[Algorithm]:
        key = name.lower()
        if key in _REGISTRY and _REGISTRY[key] is not klass:
            raise ParameterError(f"algorithm name {key!r} is already registered "
                                 f"to {_REGISTRY[key].__name__}")
        _REGISTRY[key] = klass
        return klass

    return add if cls is None else add(cls)


_PYMOO_MULTI_OBJECTIVE = (NSGA2, MOEAD, SMSEMOA, MOPSO_CD)


def is_multi_objective(name: str) -> bool:
    """Whether the algorithm registered as ``name`` solves multi-objective problems."""
    from moik.algorithms.moo.base import MOArrayAlgorithm

    cls = _lookup(name)
    return issubclass(cls, (MOArrayAlgorithm, *_PYMOO_MULTI_OBJECTIVE))


def available() -> list[str]:
    """Names accepted by :func:`get_algorithm`, sorted."""
    return sorted(_REGISTRY)


def accepted_parameters(name: str) -> list[str]:
    """Keyword names ``get_algorithm(name, ...)`` accepts (class and pymoo options)."""
    cls = _lookup(name)
    names: set[str] = set()
    for klass in (cls, Algorithm):
        for p in inspect.signature(klass.__init__).parameters.values():
            if p.kind in (p.KEYWORD_ONLY, p.POSITIONAL_OR_KEYWORD) and p.name != "self":
                names.add(p.name)
    return sorted(names | set(_FORWARDED.get(cls, ())))


def get_algorithm(name: str, **params) -> Algorithm:
    """Build the algorithm registered as ``name`` with hyperparameters ``params``.

    Raises:
        UnknownNameError: If ``name`` is not registered (lists the valid names).
        ParameterError: For an unknown keyword or a value outside its range.
    """
    cls = _lookup(name)
    valid = accepted_parameters(name)
    unknown = sorted(set(params) - set(valid))
    if unknown:
        raise ParameterError(f"unknown parameter(s) {', '.join(unknown)} for algorithm "
                             f"{name!r}; accepted: {', '.join(valid)}")
    pop_size = params.get("pop_size", 1)
    if cls in (PymooDE, GA) and (isinstance(pop_size, bool) or not isinstance(pop_size, int)
                            or pop_size < 1):
        raise ParameterError(f"pop_size must be a positive integer, got {pop_size!r}")
    return cls(**params)


def _lookup(name: str) -> type[Algorithm]:
    key = name.lower() if isinstance(name, str) else name
    if key not in _REGISTRY:
        raise UnknownNameError("algorithm", name, _REGISTRY)
    return _REGISTRY[key]
