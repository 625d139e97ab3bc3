"""Single-objective algorithms, one module each (registered in :mod:`moik.algorithms.registry`)."""

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

__all__ = ["BES", "CODE", "CPSOAT", "CSA", "DE", "EO", "EOSMA", "FA", "FPA", "GBO", "HHO",
           "IGWO", "JAYA", "MPA", "MPSO", "MRFO", "MTDE", "MTSA", "PFA", "PSO", "PSOGSA", "SASS",
           "SMA", "SSA", "TLBO", "ChOA"]
