"""Multi-objective algorithms: the array-state base, MOEOSMA, MO-m-PSO, pymoo wrappers."""

from moik.algorithms.moo.base import MOArrayAlgorithm, dominates, pareto_memory
from moik.algorithms.moo.moeosma import MOEOSMA
from moik.algorithms.moo.mompso import MOMPSO
from moik.algorithms.moo.pymoo_moo import MOEAD

__all__ = ["MOEAD", "MOEOSMA", "MOMPSO", "MOArrayAlgorithm", "dominates", "pareto_memory"]
