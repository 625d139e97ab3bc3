"""Multi-objective algorithms: the array-state base, the per-objective-swarm base and one
module per algorithm (registered in :mod:`moik.algorithms.registry`)."""

from moik.algorithms.moo.around_best import around_best
from moik.algorithms.moo.base import MOArrayAlgorithm
from moik.algorithms.moo.dominance import (
    constrained_dominates,
    dominance_memory,
    dominates,
    pareto_memory,
)
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
from moik.algorithms.moo.objective_swarms import ObjectiveSwarms

__all__ = ["MOALO", "MOCSA", "MODA", "MOEAD", "MOEOSMA", "MOGWO", "MOJAYA", "MOMPA", "MOMPSO",
           "MOMVO", "MOPSO", "MOPSOCD", "MOSMA", "MSSA", "MOArrayAlgorithm", "MOClassicPSO",
           "ObjectiveSwarms", "PymooMOEAD", "around_best", "constrained_dominates",
           "dominance_memory", "dominates", "pareto_memory"]
