"""The algorithm registry: one entry per name with its class, kind and source.

``get_algorithm(name, **params)`` builds one, ``available()`` lists the names,
``entry(name)`` gives the :class:`AlgorithmEntry` (class, kind, source) and
``algorithm_kind(name)`` / ``is_multi_objective(name)`` answer what a caller
needs to pick a problem. This table is the one list of moik's algorithms:
:mod:`moik.algorithms` re-exports the classes named here.

moik's own algorithms validate their hyperparameters and refuse unknown
keywords in ``__init__`` (a bad value raises
:class:`~moik.exceptions.ParameterError` with the valid range). pymoo's DE (as
``pymoo-de``; ``de`` is moik's array-state DE/rand/1/bin), GA, NSGA2 and SMS-EMOA
are registered as they are, for comparisons (pymoo's MOEA/D as ``moead-pymoo`` and
MOPSO-CD as moik subclasses that add default directions and constraint handling;
``moead`` is moik's own MOEA/D); for them :func:`get_algorithm` refuses an unknown
keyword (pymoo's classes would swallow it through ``**kwargs``) and checks their sizes.

More entries are added with :func:`register`, either as ``register("name", cls)``
or as a class decorator ``@register("name")``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, cast

from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.algorithms.moo.sms import SMSEMOA
from pymoo.algorithms.soo.nonconvex.de import DE as PymooDE  # noqa: N811
from pymoo.algorithms.soo.nonconvex.ga import GA
from pymoo.core.algorithm import Algorithm

from moik._validate import choice, integer, keywords, optional_integer
from moik.algorithms.array_state import constructor_keywords
from moik.algorithms.moo.base import MOArrayAlgorithm
from moik.algorithms.moo.mo_classic_pso import MOClassicPSO
from moik.algorithms.moo.mo_csa import MOCSA
from moik.algorithms.moo.mo_jaya import MOJAYA
from moik.algorithms.moo.mo_modified_pso import MOMPSO
from moik.algorithms.moo.moalo import MOALO
from moik.algorithms.moo.moda import MODA
from moik.algorithms.moo.moead import MOEAD
from moik.algorithms.moo.moead_pymoo import PymooMOEAD
from moik.algorithms.moo.moeosma import MOEOSMA
from moik.algorithms.moo.mogwo import MOGWO
from moik.algorithms.moo.mompa import MOMPA
from moik.algorithms.moo.momvo import MOMVO
from moik.algorithms.moo.mopso_cd import MOPSOCD
from moik.algorithms.moo.mopso_grid import MOPSO
from moik.algorithms.moo.mosma import MOSMA
from moik.algorithms.moo.mssa import MSSA
from moik.algorithms.soo.bes import BES
from moik.algorithms.soo.choa import ChOA
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
from moik.algorithms.soo.modified_pso import MPSO
from moik.algorithms.soo.mpa import MPA
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

SINGLE_OBJECTIVE = "single-objective"
MULTI_OBJECTIVE = "multi-objective"
KINDS = (SINGLE_OBJECTIVE, MULTI_OBJECTIVE)


@dataclass(frozen=True)
class AlgorithmEntry:
    """One registered algorithm.

    Attributes:
        name: The registry name (lower case).
        cls: The pymoo ``Algorithm`` subclass built by :func:`get_algorithm`.
        kind: ``"single-objective"`` or ``"multi-objective"`` (:data:`KINDS`).
        source: The paper it implements (authors, year, venue, DOI), or ``"pymoo: ..."``
            for pymoo's own algorithms.
        preset: The classmethod of ``cls`` that builds this entry (``"ibes"`` for
            ``BES.ibes``), or None for the plain constructor.
    """

    name: str
    cls: type[Algorithm]
    kind: str
    source: str
    preset: str | None = None

    def build(self, **params) -> Algorithm:
        """An instance: ``cls(**params)``, or the preset classmethod's."""
        return getattr(self.cls, self.preset)(**params) if self.preset else self.cls(**params)


_YIN_2022 = "Yin et al. 2022, Sci. Rep. 12, 9421, DOI 10.1038/s41598-022-13516-3"
_ROKBANI_2022 = "Rokbani et al. 2022, Appl. Sci. 12, 7091, DOI 10.3390/app12147091"
_SSA_2017 = ("Mirjalili et al. 2017, Adv. Eng. Softw. 114, 163-191, "
             "DOI 10.1016/j.advengsoft.2017.07.002")
_MCHOA = ("Hou, Luo, Wu, Sun & Zhang, Solution of Inverse Kinematics for Industry Robot "
          "Based on MChOA")

_SINGLE: list[tuple[Any, ...]] = [
    ("eosma", EOSMA, _YIN_2022),
    ("sma", SMA, "Li et al. 2020, Future Gener. Comput. Syst. 111, 300-323, "
                 "DOI 10.1016/j.future.2020.03.055"),
    ("eo", EO, "Faramarzi et al. 2020, Knowl.-Based Syst. 191, 105190, "
               "DOI 10.1016/j.knosys.2019.105190"),
    ("m-pso", MPSO, _ROKBANI_2022),
    ("pso", PSO, "Shi & Eberhart 1998, IEEE ICEC, DOI 10.1109/ICEC.1998.699146"),
    ("de", DE, "Storn & Price 1997, J. Glob. Optim. 11, 341-359, DOI 10.1023/A:1008202821328"),
    ("pymoo-de", PymooDE, "pymoo: differential evolution (Storn & Price 1997)"),
    ("mrfo", MRFO, "Zhao, Zhang & Wang 2020, Eng. Appl. Artif. Intell. 87, 103300, "
                   "DOI 10.1016/j.engappai.2019.103300"),
    ("mpa", MPA, "Faramarzi et al. 2020, Expert Syst. Appl. 152, 113377, "
                 "DOI 10.1016/j.eswa.2020.113377"),
    ("pfa", PFA, "Yapici & Cetinkaya 2019, Appl. Soft Comput. 78, 545-568, "
                 "DOI 10.1016/j.asoc.2019.03.012"),
    ("fpa", FPA, "Yang 2012, UCNC 2012, LNCS 7445, 240-249, DOI 10.1007/978-3-642-32894-7_27"),
    ("gbo", GBO, "Ahmadianfar, Bozorg-Haddad & Chu 2020, Inf. Sci. 540, 131-159, "
                 "DOI 10.1016/j.ins.2020.06.037"),
    ("tlbo", TLBO, "Rao, Savsani & Vakharia 2011, Comput.-Aided Des. 43, 303-315, "
                   "DOI 10.1016/j.cad.2010.12.015"),
    ("hho", HHO, "Heidari et al. 2019, Future Gener. Comput. Syst. 97, 849-872, "
                 "DOI 10.1016/j.future.2019.02.028"),
    ("igwo", IGWO, "Nadimi-Shahraki, Taghian & Mirjalili 2021, Expert Syst. Appl. 166, "
                   "113917, DOI 10.1016/j.eswa.2020.113917"),
    ("psogsa", PSOGSA, "Mirjalili & Hashim 2010, ICCIA 2010, 374-377, "
                       "DOI 10.1109/ICCIA.2010.6141614"),
    ("code", CODE, "Rahnamayan et al. 2014, IEEE CEC 2014, 1800-1807, "
                   "DOI 10.1109/CEC.2014.6900329"),
    ("mtde", MTDE, "Nadimi-Shahraki et al. 2020, Appl. Soft Comput. 97, 106761, "
                   "DOI 10.1016/j.asoc.2020.106761"),
    ("sass", SASS, "Kumar, Das & Zelinka 2020, GECCO 2020 Companion, 13-14, "
                   "DOI 10.1145/3377929.3398186"),
    ("ga", GA, "pymoo: genetic algorithm (SBX crossover, polynomial mutation)"),
    ("bes", BES, "Alsattar, Zaidan & Zaidan 2020, Artif. Intell. Rev. 53, 2237-2264, "
                 "DOI 10.1007/s10462-019-09732-5"),
    ("ibes", BES, "Zhao et al. 2024, Biomimetics 9, 627, DOI 10.3390/biomimetics9100627",
     "ibes"),
    ("fa", FA, "Yang 2009, SAGA 2009, LNCS 5792, 169-178, DOI 10.1007/978-3-642-04944-6_14"),
    ("mtsa", MTSA, "Beskirli, Ozdemir & Temurtas 2020, Neural Comput. Appl. 32, 6877-6911, "
                   "DOI 10.1007/s00521-019-04155-1"),
    ("cpso-at", CPSOAT, "Ma et al. 2019, Symmetry 11, 876, DOI 10.3390/sym11070876"),
    ("choa", ChOA, "Khishe & Mosavi 2020, Expert Syst. Appl. 149, 113338, "
                   "DOI 10.1016/j.eswa.2020.113338"),
    ("cchoa", ChOA, f"{_MCHOA} (ablation: chaotic initialization only)", "cchoa"),
    ("oichoa", ChOA, f"{_MCHOA} (ablation: opposition-inspired coefficient only)", "oichoa"),
    ("ochoa", ChOA, f"{_MCHOA} (ablation: shared random number only)", "ochoa"),
    ("wchoa", ChOA, f"{_MCHOA} (ablation: adaptive leader weights only)", "wchoa"),
    ("mchoa", ChOA, _MCHOA, "mchoa"),
    ("ssa", SSA, _SSA_2017),
    ("csa", CSA, "Askarzadeh 2016, Comput. Struct. 169, 1-12, "
                 "DOI 10.1016/j.compstruc.2016.03.001"),
    ("jaya", JAYA, "Rao 2016, Int. J. Ind. Eng. Comput. 7, 19-34, "
                   "DOI 10.5267/j.ijiec.2015.8.004"),
]
_MULTI: list[tuple[Any, ...]] = [
    ("moeosma", MOEOSMA, _YIN_2022),
    ("mo-m-pso", MOMPSO, _ROKBANI_2022),
    ("mssa", MSSA, _SSA_2017),
    ("moalo", MOALO, "Mirjalili, Jangir & Saremi 2017, Appl. Intell. 46, 79-95, "
                     "DOI 10.1007/s10489-016-0825-8"),
    ("moda", MODA, "Mirjalili 2016, Neural Comput. Appl. 27, 1053-1073, "
                   "DOI 10.1007/s00521-015-1920-1"),
    ("momvo", MOMVO, "Mirjalili et al. 2017, Knowl.-Based Syst. 134, 50-71, "
                     "DOI 10.1016/j.knosys.2017.07.018"),
    ("mogwo", MOGWO, "Mirjalili et al. 2016, Expert Syst. Appl. 47, 106-119, "
                     "DOI 10.1016/j.eswa.2015.10.039"),
    ("mosma", MOSMA, "Premkumar et al. 2021, IEEE Access 9, 3229-3248, "
                     "DOI 10.1109/ACCESS.2020.3047936"),
    ("mopso", MOPSO, "Coello Coello, Toscano Pulido & Salazar Lechuga 2004, IEEE Trans. "
                     "Evol. Comput. 8(3), 256-279, DOI 10.1109/TEVC.2004.826067"),
    ("mompa", MOMPA, "Zhong et al. 2021, Comput. Methods Appl. Mech. Eng. 385, 114029, "
                     "DOI 10.1016/j.cma.2021.114029"),
    ("mo-pso", MOClassicPSO, f"{_ROKBANI_2022} (baseline, Section 5.2)"),
    ("mo-jaya", MOJAYA, f"{_ROKBANI_2022} (baseline, Section 5.2)"),
    ("mo-csa", MOCSA, f"{_ROKBANI_2022} (baseline, Section 5.2)"),
    ("nsga2", NSGA2, "pymoo: NSGA-II (Deb et al. 2002, DOI 10.1109/4235.996017)"),
    ("moead", MOEAD, "Zhang & Li 2007, IEEE Trans. Evol. Comput. 11(6), 712-731, "
                     "DOI 10.1109/TEVC.2007.892759"),
    ("moead-pymoo", PymooMOEAD, "pymoo: MOEA/D (Zhang & Li 2007, DOI 10.1109/TEVC.2007.892759), "
                                "Das-Dennis directions by default"),
    ("sms-emoa", SMSEMOA, "pymoo: SMS-EMOA (Beume, Naujoks & Emmerich 2007, "
                          "DOI 10.1016/j.ejor.2006.08.008)"),
    ("mopso-cd", MOPSOCD, "pymoo: MOPSO-CD (Raquel & Naval 2005, DOI 10.1145/1068009.1068047), "
                          "with constraint-domination"),
]

_REGISTRY: dict[str, AlgorithmEntry] = {
    row[0]: AlgorithmEntry(row[0], row[1], kind, row[2], *row[3:])
    for kind, table in ((SINGLE_OBJECTIVE, _SINGLE), (MULTI_OBJECTIVE, _MULTI))
    for row in table
}

# Keywords a class forwards through **kwargs to a collaborator (pymoo's DE -> Variant).
_FORWARDED: dict[type, tuple[str, ...]] = {
    PymooDE: ("CR", "F", "jitter", "prob_mut", "control", "crossover", "selection", "n_diffs"),
}
_PYMOO_MULTI_OBJECTIVE = (NSGA2, PymooMOEAD, SMSEMOA, MOPSOCD)
_PYMOO_GENETIC = (GA, PymooDE, NSGA2, SMSEMOA)


def register(name: str, cls: type[Algorithm] | None = None, *, kind: str | None = None,
             source: str = "") -> Callable | type[Algorithm]:
    """Register ``cls`` under ``name`` (lower case); usable as a class decorator.

    Args:
        name: The registry name.
        cls: The algorithm class; None to use ``register`` as a decorator.
        kind: ``"single-objective"`` or ``"multi-objective"``; None infers it (moik's
            multi-objective base or one of pymoo's multi-objective classes, else
            single-objective).
        source: The paper (or library) the class implements.

    Raises:
        ParameterError: If ``name`` is already taken by another class.
        UnknownNameError: For a ``kind`` outside :data:`KINDS`.
    """

    def add(klass: type[Algorithm]) -> type[Algorithm]:
        key = name.lower()
        if key in _REGISTRY and _REGISTRY[key].cls is not klass:
            raise ParameterError(f"algorithm name {key!r} is already registered "
                                 f"to {_REGISTRY[key].cls.__name__}")
        if key in _REGISTRY and kind is None and not source:
            return klass  # registered again as it is: keep its kind and source
        multi = issubclass(klass, (MOArrayAlgorithm, *_PYMOO_MULTI_OBJECTIVE))
        found = (MULTI_OBJECTIVE if multi else SINGLE_OBJECTIVE) if kind is None else \
            choice("algorithm kind", kind, KINDS)
        _REGISTRY[key] = AlgorithmEntry(key, klass, found, source)
        return klass

    return add if cls is None else add(cls)


def available(kind: str | None = None) -> list[str]:
    """Names accepted by :func:`get_algorithm`, sorted; only those of ``kind`` if given.

    Raises:
        UnknownNameError: For a ``kind`` outside :data:`KINDS`.
    """
    if kind is None:
        return sorted(_REGISTRY)
    kind = choice("algorithm kind", kind, KINDS)
    return sorted(n for n, e in _REGISTRY.items() if e.kind == kind)


def entry(name: str) -> AlgorithmEntry:
    """The :class:`AlgorithmEntry` registered as ``name`` (case-insensitive).

    Raises:
        UnknownNameError: If ``name`` is not registered (lists the valid names).
    """
    key = name.lower() if isinstance(name, str) else name
    if key not in _REGISTRY:
        raise UnknownNameError("algorithm", name, _REGISTRY)
    return _REGISTRY[key]


def algorithm_kind(name: str) -> str:
    """``"single-objective"`` or ``"multi-objective"``: the kind of problem ``name`` solves."""
    return entry(name).kind


def is_multi_objective(name: str) -> bool:
    """Whether the algorithm registered as ``name`` solves multi-objective problems."""
    return entry(name).kind == MULTI_OBJECTIVE


def accepted_parameters(name: str) -> list[str]:
    """Keyword names ``get_algorithm(name, ...)`` accepts (class and pymoo options), sorted."""
    cls = entry(name).cls
    # the named parameters along the MRO (pymoo's GeneticAlgorithm takes repair, mating ...
    # that NSGA2 forwards through **kwargs); type[Algorithm] is type[Any] to mypy (pymoo has
    # no types), which is not Hashable
    return sorted(constructor_keywords(cast(type, cls)) | set(_FORWARDED.get(cls, ())))


def _check_pymoo_options(cls: type, params: dict) -> None:
    """What pymoo's own GA, DE, NSGA2 and SMS-EMOA take unchecked (moik's classes, MOPSO-CD
    and pymoo's MOEA/D subclass check their own): sizes are positive integers."""
    if not issubclass(cls, _PYMOO_GENETIC):
        return
    if "pop_size" in params:
        integer("pop_size", params["pop_size"], minimum=1)
    optional_integer("n_offsprings", params.get("n_offsprings"), minimum=1)


def get_algorithm(name: str, **params) -> Algorithm:
    """Build the algorithm registered as ``name`` with hyperparameters ``params``.

    Raises:
        UnknownNameError: If ``name`` is not registered (lists the valid names).
        ParameterError: For an unknown keyword or a value outside its range.
    """
    found = entry(name)
    keywords(f"algorithm {name!r}", params, accepted_parameters(name))
    _check_pymoo_options(found.cls, params)
    return found.build(**params)


__all__ = ["KINDS", "MULTI_OBJECTIVE", "SINGLE_OBJECTIVE", "AlgorithmEntry",
           "accepted_parameters", "algorithm_kind", "available", "entry", "get_algorithm",
           "is_multi_objective", "register",
           *sorted({e.cls.__name__ for e in _REGISTRY.values()
                    if e.cls.__module__.startswith("moik.")})]
