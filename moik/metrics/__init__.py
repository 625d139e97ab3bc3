"""Metrics for comparing results: hypervolume, its reference-point policy, compromise picks,
statistics over runs (summaries, Wilcoxon tests, Friedman ranks)."""

from moik.metrics.compromise import (
    closest_to_utopia,
    compromise,
    normalized_front,
    weighted_choice,
)
from moik.metrics.hypervolume import EOSMA_TABLE8_REF_POINTS, hypervolume, reference_point
from moik.metrics.stats import (
    FriedmanResult,
    SignedRank,
    Summary,
    friedman_ranks,
    ranksum_pvalues,
    signed_rank,
    success_rate,
    summarize,
)

__all__ = [
    "EOSMA_TABLE8_REF_POINTS",
    "FriedmanResult",
    "SignedRank",
    "Summary",
    "closest_to_utopia",
    "compromise",
    "friedman_ranks",
    "hypervolume",
    "normalized_front",
    "ranksum_pvalues",
    "reference_point",
    "signed_rank",
    "success_rate",
    "summarize",
    "weighted_choice",
]
