"""Optimization algorithms: array-state single-objective metaheuristics and a registry."""

from moik.algorithms.base import ArrayAlgorithm
from moik.algorithms.registry import available, get_algorithm, register
from moik.algorithms.soo.eo import EO
from moik.algorithms.soo.eosma import EOSMA
from moik.algorithms.soo.mpso import MPSO
from moik.algorithms.soo.pso import PSO
from moik.algorithms.soo.sma import SMA

__all__ = ["EO", "EOSMA", "MPSO", "PSO", "SMA", "ArrayAlgorithm", "available", "get_algorithm",
           "register"]
