"""Metrics for comparing results: hypervolume, its reference-point policy, compromise picks,
statistics over runs (summaries, Wilcoxon tests, Friedman ranks)."""

from typing import TYPE_CHECKING

from moik._lazy import lazy_names
from moik.metrics.compromise import (
    closest_to_utopia,
    compromise,
    normalized_front,
    weighted_choice,
)
from moik.metrics.hypervolume import EOSMA_TABLE8_REF_POINTS, hypervolume, reference_point

if TYPE_CHECKING:
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

_LAZY: dict[str, tuple[str, str | None]] = {
    name: ("moik.metrics.stats", name)
    for name in ("FriedmanResult", "SignedRank", "Summary", "friedman_ranks", "ranksum_pvalues",
                 "signed_rank", "success_rate", "summarize")
}
"""Loaded at first use: the statistics import scipy.stats, which the solver's verdict
(the compromise picks) does not need (start-up time; pymoo's HV is imported by
:func:`~moik.metrics.hypervolume.hypervolume` at its first call for the same reason)."""

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

__getattr__, __dir__ = lazy_names("moik.metrics", _LAZY, globals(), __all__)
