"""Statistics over runs, checked on hand-computable data."""

import numpy as np
import pytest

from moik.exceptions import NonFiniteError, ParameterError, ShapeError
from moik.metrics import (
    friedman_ranks,
    ranksum_pvalues,
    signed_rank,
    success_rate,
    summarize,
)


def test_summarize_by_hand():
    s = summarize([4.0, 1.0, 3.0, 2.0], times=[0.5, 1.5, 1.0, 1.0])
    assert (s.best, s.worst, s.mean, s.median, s.n, s.time) == (1.0, 4.0, 2.5, 2.5, 4, 1.0)
    assert s.std == pytest.approx(np.sqrt(5 / 3))  # ddof=1: sum of squares 5 over 3
    assert summarize([7.0]).std == 0.0
    assert np.isnan(summarize([1.0]).time)


def test_summarize_rejects_bad_input():
    with pytest.raises(ShapeError, match="at least 1"):
        summarize([])
    with pytest.raises(NonFiniteError):
        summarize([1.0, np.nan])
    with pytest.raises(ShapeError, match="times must match"):
        summarize([1.0, 2.0], times=[1.0])


def test_success_rate_is_strict():
    assert success_rate([0.0, 1e-7, 1e-6, 1.0], 1e-6) == 0.5
    with pytest.raises(ParameterError):
        success_rate([1.0], np.inf)


def test_ranksum_separated_samples():
    # 3 vs 3 fully separated: exact two-sided p = 2 / C(6, 3) = 0.1
    p = ranksum_pvalues({"a": [1, 2, 3], "b": [4, 5, 6], "c": [1, 2, 3]}, "a")
    assert list(p) == ["b", "c"]
    assert p["b"] == pytest.approx(0.1) and p["c"] == pytest.approx(1.0)
    assert ranksum_pvalues({"a": [0, 0], "b": [0, 0]}, "a") == {"b": 1.0}
    with pytest.raises(ParameterError, match="proposed 'z'"):
        ranksum_pvalues({"a": [1]}, "z")


def test_signed_rank_r_plus_r_minus_by_hand():
    # a - b = (-1, -2, -3, -4): all negative, R+ = 0, R- = 1+2+3+4 = 10, exact p = 2/16
    t = signed_rank([1, 2, 3, 4], [2, 4, 6, 8])
    assert (t.r_plus, t.r_minus, t.n) == (0.0, 10.0, 4)
    assert t.p_value == pytest.approx(0.125)
    assert t.better("m-pso", "pso", alpha=0.2) == "m-pso" and t.better("x", "y") == "="
    # d = (4, -1, 0): zero dropped; ranks |d| -> (2, 1); R+ = 2, R- = 1
    t = signed_rank([5, 1, 3], [1, 2, 3])
    assert (t.r_plus, t.r_minus, t.n) == (2.0, 1.0, 2)
    # 30 pairs all in favour of the first: R+ = 0, R- = 465 (MO-m-PSO Table 5 pattern)
    t = signed_rank(np.arange(30) * 0.0, np.arange(1, 31))
    assert (t.r_plus, t.r_minus) == (0.0, 465.0)
    assert signed_rank([1, 2], [1, 2]).p_value == 1.0
    with pytest.raises(ShapeError, match="paired"):
        signed_rank([1, 2], [1])


def test_friedman_mean_ranks_by_hand():
    # blocks (rows): a best twice, b best once; c always last
    r = friedman_ranks({"a": [1, 1, 3], "b": [2, 2, 1], "c": [3, 3, 4]})
    assert r.mean_ranks == pytest.approx({"a": 4 / 3, "b": 5 / 3, "c": 3.0})
    assert r.order == {"a": 1, "b": 2, "c": 3} and 0 < r.p_value < 1
    hv = friedman_ranks({"a": [5.0, 5.0], "b": [4.0, 5.0]}, higher_is_better=True)
    assert hv.mean_ranks == {"a": 1.25, "b": 1.75} and np.isnan(hv.p_value)
    with pytest.raises(ShapeError, match="same number of blocks"):
        friedman_ranks({"a": [1, 2], "b": [1]})
    with pytest.raises(ShapeError, match="at least 2"):
        friedman_ranks({"a": [1]})
