"""Optimization algorithms: array-state single- and multi-objective metaheuristics, a registry."""

from moik.algorithms.base import ArrayAlgorithm
from moik.algorithms.moo.base import MOArrayAlgorithm
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
from moik.algorithms.registry import available, get_algorithm, register
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

__all__ = ["EO", "EOSMA", "MOEOSMA", "MOMPSO", "MPSO", "PSO", "SMA", "ArrayAlgorithm",
           "DE", "FPA", "GBO", "MPA", "MRFO", "PFA", "TLBO",
           "CODE", "HHO", "IGWO", "MTDE", "PSOGSA", "SASS",
           "MOArrayAlgorithm", "available", "get_algorithm", "register",
           "MOALO", "MODA", "MOGWO", "MOMVO", "MSSA",
           "MOCSA", "MOJAYA", "MOClassicPSO", "MOMPA", "MOPSO", "MOSMA",
           "BES", "CPSOAT", "CSA", "FA", "IBES", "JAYA", "MTSA", "SSA",
           "CChOA", "ChOA", "MChOA", "OChOA", "OIChOA", "WChOA"]
