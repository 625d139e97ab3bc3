"""Statistics over independent runs, as the papers report them.

- :func:`summarize`: best / worst / mean / median / std (``ddof=1``, MATLAB's
  ``std``, which the papers used) and mean time over runs (EOSMA Tables 5, 7;
  MO-m-PSO Tables 2-4).
- :func:`success_rate`: fraction of runs strictly below a threshold (the
  EOSMA protocol counts a run as solved when ``f < 1e-6``).
- :func:`ranksum_pvalues`: Wilcoxon rank-sum test (two-sided Mann-Whitney U,
  ``scipy.stats.mannwhitneyu``) of the proposed algorithm against each
  baseline (EOSMA Figs. 11, 16).
- :func:`signed_rank`: Wilcoxon signed-rank test of paired samples with the
  rank sums R+ and R- (``scipy.stats.wilcoxon``; MO-m-PSO Table 5).
- :func:`friedman_ranks`: Friedman mean ranks of algorithms over blocks (runs)
  and the Friedman test p-value (``scipy.stats.rankdata``,
  ``scipy.stats.friedmanchisquare``; EOSMA Table 8 "FR").

Conventions: R+ is the rank sum of the pairs where the first sample is the
larger (``a - b > 0``); zero differences are dropped (``zero_method="wilcox"``).
For minimized errors, R+ = 0 means the first algorithm was better in every pair.
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from moik.exceptions import NonFiniteError, ParameterError, ShapeError


def _scipy_stats():
    """``scipy.stats``, imported at the first test that needs it.

    Its import would be most of moik's start-up time, and only the rank tests below use
    it: deferred for start-up time (not for an import cycle).
    """
    return importlib.import_module("scipy.stats")


def _sample(name: str, values: object, *, min_size: int = 1) -> np.ndarray:
    arr = np.asarray(values, dtype=float)
    if arr.ndim != 1 or arr.size < min_size:
        raise ShapeError(f"{name} must be a 1-D sequence of at least {min_size} value(s); "
                         f"got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise NonFiniteError(f"{name} must hold finite values only; got {arr[~np.isfinite(arr)]}")
    return arr


@dataclass(frozen=True)
class Summary:
    """Descriptive statistics of one sample (the papers' table rows).

    Attributes:
        best: Minimum.
        worst: Maximum.
        mean: Arithmetic mean.
        median: Median.
        std: Sample standard deviation (``ddof=1``; 0 for one value).
        n: Number of values.
        time: Mean time per run in seconds (``nan`` when no times were given).
    """

    best: float
    worst: float
    mean: float
    median: float
    std: float
    n: int
    time: float = float("nan")

    def as_dict(self) -> dict[str, float]:
        """The fields as a plain dict."""
        return {"best": self.best, "worst": self.worst, "mean": self.mean,
                "median": self.median, "std": self.std, "n": self.n, "time": self.time}


def summarize(values: ArrayLike, times: ArrayLike | None = None) -> Summary:
    """Best, worst, mean, median, std of ``values`` and the mean of ``times``.

    Args:
        values: Final errors (or any minimized quantity) of the runs.
        times: Wall times of the same runs, in seconds.

    Returns:
        A :class:`Summary`.

    Raises:
        ShapeError: If ``values`` is empty or not 1-D, or ``times`` has another length.
        NonFiniteError: If a value or time is NaN or infinite.

    Example:
        >>> summarize([1.0, 2.0, 3.0]).std
        1.0
    """
    v = _sample("values", values)
    t = float("nan")
    if times is not None:
        tt = _sample("times", times)
        if tt.shape != v.shape:
            raise ShapeError(f"times must match values: {tt.shape} vs {v.shape}")
        t = float(tt.mean())
    std = float(np.std(v, ddof=1)) if v.size > 1 else 0.0
    return Summary(best=float(v.min()), worst=float(v.max()), mean=float(v.mean()),
                   median=float(np.median(v)), std=std, n=int(v.size), time=t)


def success_rate(values: ArrayLike, threshold: float) -> float:
    """Fraction of ``values`` strictly below ``threshold`` (in [0, 1]).

    Raises:
        ParameterError: If ``threshold`` is not a finite number.
    """
    if not np.isfinite(threshold):
        raise ParameterError(f"threshold must be finite, got {threshold!r}")
    v = _sample("values", values)
    return float(np.mean(v < threshold))


def ranksum_pvalues(samples: Mapping[str, ArrayLike], proposed: str) -> dict[str, float]:
    """Two-sided Wilcoxon rank-sum p-value of ``proposed`` against every other sample.

    Uses ``scipy.stats.mannwhitneyu(method="auto")`` (exact for small samples
    without ties, normal approximation with tie correction otherwise). Two
    samples that are identical constants give p = 1.

    Args:
        samples: Algorithm name -> final values of its runs (independent samples).
        proposed: The name compared with the others.

    Returns:
        Baseline name -> p-value, in the order of ``samples``.

    Raises:
        ParameterError: If ``proposed`` is not a key of ``samples``.
    """
    if proposed not in samples:
        raise ParameterError(f"proposed {proposed!r} is not among the samples: "
                             f"{', '.join(samples)}")
    x = _sample(f"samples[{proposed!r}]", samples[proposed])
    out = {}
    for name, values in samples.items():
        if name == proposed:
            continue
        y = _sample(f"samples[{name!r}]", values)
        if np.ptp(np.concatenate([x, y])) == 0:
            out[name] = 1.0
            continue
        out[name] = float(_scipy_stats().mannwhitneyu(x, y, alternative="two-sided").pvalue)
    return out


@dataclass(frozen=True)
class SignedRank:
    """Wilcoxon signed-rank test of paired samples ``a`` and ``b``.

    Attributes:
        r_plus: Rank sum of the pairs with ``a > b``.
        r_minus: Rank sum of the pairs with ``a < b``.
        p_value: Two-sided p-value (1.0 when all pairs are equal).
        n: Number of non-zero differences used.
    """

    r_plus: float
    r_minus: float
    p_value: float
    n: int

    def better(self, first: str, second: str, *, alpha: float = 0.05) -> str:
        """Which of two minimized samples is better at level ``alpha`` ("=" if neither)."""
        if self.p_value >= alpha or self.r_plus == self.r_minus:
            return "="
        return first if self.r_plus < self.r_minus else second


def signed_rank(a: ArrayLike, b: ArrayLike) -> SignedRank:
    """Wilcoxon signed-rank test with R+ and R- (MO-m-PSO Table 5).

    ``R+`` is the statistic of ``scipy.stats.wilcoxon(a - b,
    alternative="greater")`` and ``R- = n (n + 1) / 2 - R+`` (``n`` non-zero
    differences); the p-value is the two-sided one.

    Raises:
        ShapeError: If ``a`` and ``b`` differ in length or are empty.
    """
    x, y = _sample("a", a), _sample("b", b)
    if x.shape != y.shape:
        raise ShapeError(f"a and b must be paired samples of equal length; got {x.size} and "
                         f"{y.size}")
    d = x - y
    n = int(np.count_nonzero(d))
    if n == 0:
        return SignedRank(r_plus=0.0, r_minus=0.0, p_value=1.0, n=0)
    stats = _scipy_stats()
    r_plus = float(stats.wilcoxon(d, zero_method="wilcox", alternative="greater").statistic)
    p = float(stats.wilcoxon(d, zero_method="wilcox", alternative="two-sided").pvalue)
    return SignedRank(r_plus=r_plus, r_minus=n * (n + 1) / 2 - r_plus, p_value=p, n=n)


@dataclass(frozen=True)
class FriedmanResult:
    """Friedman mean ranks (rank 1 = best) and test p-value.

    Attributes:
        mean_ranks: Algorithm -> mean rank over the blocks.
        order: Algorithm -> position (1 = lowest mean rank), ties share the lower position.
        p_value: Friedman chi-square p-value (``nan`` with fewer than 3 algorithms).
    """

    mean_ranks: dict[str, float]
    order: dict[str, int]
    p_value: float


def friedman_ranks(samples: Mapping[str, ArrayLike], *,
                   higher_is_better: bool = False) -> FriedmanResult:
    """Friedman mean ranks of algorithms over blocks (EOSMA Table 8 "FR").

    Block ``j`` is the ``j``-th value of every sample (e.g. run ``j`` with the
    same seed); within a block the algorithms are ranked with
    ``scipy.stats.rankdata`` (ties get the average rank), rank 1 for the best.

    Args:
        samples: Algorithm -> values, all of the same length (the blocks).
        higher_is_better: True for hypervolume, False for errors.

    Returns:
        A :class:`FriedmanResult`.

    Raises:
        ShapeError: With fewer than 2 algorithms or samples of unequal length.

    Example:
        >>> friedman_ranks({"a": [1, 1], "b": [2, 3]}).mean_ranks
        {'a': 1.0, 'b': 2.0}
    """
    if len(samples) < 2:
        raise ShapeError(f"friedman_ranks needs at least 2 algorithms, got {len(samples)}")
    names = list(samples)
    cols = [_sample(f"samples[{k!r}]", samples[k]) for k in names]
    if len({c.size for c in cols}) != 1:
        raise ShapeError("every sample must have the same number of blocks; got "
                         + ", ".join(f"{k}: {c.size}" for k, c in zip(names, cols, strict=True)))
    table = np.column_stack(cols)
    stats = _scipy_stats()
    ranks = stats.rankdata(-table if higher_is_better else table, axis=1)
    mean = ranks.mean(axis=0)
    order_ranks = stats.rankdata(mean, method="min")
    p = float("nan")
    if len(names) >= 3 and table.shape[0] >= 2 and np.ptp(table) > 0:
        p = float(stats.friedmanchisquare(*cols).pvalue)
    return FriedmanResult(mean_ranks={k: float(m) for k, m in zip(names, mean, strict=True)},
                          order={k: int(o) for k, o in zip(names, order_ranks, strict=True)},
                          p_value=p)
