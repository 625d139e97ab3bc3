"""Metrics for comparing results: hypervolume, its reference-point policy, compromise picks."""

from moik.metrics.compromise import closest_to_utopia, normalized_front, weighted_choice
from moik.metrics.hypervolume import EOSMA_TABLE8_REF_POINTS, hypervolume, reference_point

__all__ = [
    "EOSMA_TABLE8_REF_POINTS",
    "closest_to_utopia",
    "hypervolume",
    "normalized_front",
    "reference_point",
    "weighted_choice",
]
