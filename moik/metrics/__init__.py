"""Metrics for comparing results: hypervolume and its reference-point policy."""

from moik.metrics.hypervolume import EOSMA_TABLE8_REF_POINTS, hypervolume, reference_point

__all__ = ["EOSMA_TABLE8_REF_POINTS", "hypervolume", "reference_point"]
