"""Crowding-radius archive (moik.algorithms.archive.crowding): counts by hand, leaders,
the roulette removal, presets and parameters."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from moik.algorithms.archive import (
    CrowdingArchive,
    crowding_counts,
    crowding_radius,
    first_unique_mask,
    nondominated_mask,
)
from moik.algorithms.archive.crowding import _crowding_counts_front_2d, _crowding_counts_pairwise
from moik.exceptions import ParameterError, ShapeError, UnknownNameError


@settings(max_examples=60, deadline=None)
@given(
    arrays(
        np.float64, st.tuples(st.integers(2, 30), st.just(2)), elements=st.floats(-5, 5, width=16)
    ),
    st.sampled_from([1, 2, 3, 7, 20]),
)
def test_two_objective_counts_match_the_pairwise_test(F, divisor):
    F = F[nondominated_mask(F)]
    F = F[first_unique_mask(F)]
    dr = crowding_radius(F, divisor)
    fast = _crowding_counts_front_2d(F, dr)
    assert fast.size == len(F)  # a front: counted by binary search, not refused
    np.testing.assert_array_equal(fast, _crowding_counts_pairwise(F, dr))


def test_crowding_counts_by_hand():
    F = np.array([[0.0, 4.0], [1.0, 3.0], [1.5, 2.5], [4.0, 0.0]])
    np.testing.assert_allclose(crowding_radius(F, 4), [1.0, 1.0])
    # |0 - 1| = 1 is not < 1; members 1 and 2 are 0.5 apart in both objectives
    np.testing.assert_array_equal(crowding_counts(F, 4), [1, 2, 2, 1])
    # dr = 2: the first three are within 1.5 of each other, (4, 0) is 2.5 away
    np.testing.assert_array_equal(crowding_counts(F, 2), [3, 3, 3, 1])
    np.testing.assert_array_equal(crowding_counts(F, 20), [1, 1, 1, 1])
    archive = CrowdingArchive(4)
    archive.add(np.zeros((4, 1)), F, rng=np.random.default_rng(0))
    np.testing.assert_array_equal(archive.counts, [1, 2, 2, 1])


def test_zero_radius_objective_is_ignored_and_single_member_counts_itself():
    F = np.array([[0.0, 1.0, 5.0], [1.0, 0.0, 5.0], [0.5, 0.5, 5.0]])
    np.testing.assert_allclose(crowding_radius(F, 2), [0.5, 0.5, 0.0])
    np.testing.assert_array_equal(crowding_counts(F, 2), [1, 1, 1])
    np.testing.assert_array_equal(crowding_counts(F, 1), [2, 2, 3])
    np.testing.assert_array_equal(crowding_counts(F[:1], 100), [1])


def test_min_count_leaders_come_from_the_least_crowded():
    archive = CrowdingArchive(4)
    F = np.array([[0.0, 4.0], [1.0, 3.0], [1.5, 2.5], [4.0, 0.0]])
    archive.add(np.zeros((4, 1)), F, rng=np.random.default_rng(0))
    picks = archive.leaders(400, rng=np.random.default_rng(1))
    assert set(picks.tolist()) == {0, 3}


def test_roulette_leaders_favour_low_counts():
    archive = CrowdingArchive(4, radius_divisor=4, leader="roulette")
    F = np.array([[0.0, 4.0], [1.0, 3.0], [1.5, 2.5], [4.0, 0.0]])
    archive.add(np.zeros((4, 1)), F, rng=np.random.default_rng(0))
    freq = np.bincount(archive.leaders(30000, rng=np.random.default_rng(2)), minlength=4) / 30000
    np.testing.assert_allclose(freq, np.array([1, 0.5, 0.5, 1]) / 3, atol=0.015)


def test_overflow_removes_by_roulette_on_counts():
    F = np.array([[0.0, 4.0], [1.0, 3.0], [1.5, 2.5], [4.0, 0.0]])  # counts 1, 2, 2, 1 with dr 1
    removed = np.zeros(4)
    for seed in range(3000):
        archive = CrowdingArchive(3, radius_divisor=4)
        archive.add(np.arange(4.0)[:, None], F, rng=np.random.default_rng(seed))
        removed[np.setdiff1d(np.arange(4), archive.X[:, 0].astype(int))] += 1
    np.testing.assert_allclose(removed / 3000, np.array([1, 2, 2, 1]) / 6, atol=0.03)


def test_presets_and_repr():
    a = CrowdingArchive.moeosma(100)
    assert (a.radius_divisor, a.leader, a.recount) == (100, "min-count", False)
    b = CrowdingArchive.mirjalili(100)
    assert (b.radius_divisor, b.leader) == (20, "roulette")
    assert "members=0" in repr(b)


def test_empty_and_zero_row_additions():
    archive = CrowdingArchive(3)
    archive.add(np.zeros((0, 2)), np.zeros((0, 2)), rng=np.random.default_rng(0))
    assert len(archive) == 0
    with pytest.raises(ShapeError, match="empty"):
        archive.leaders(1, rng=np.random.default_rng(0))
    archive.add([[1.0, 2.0]], [[3.0, 4.0]], rng=np.random.default_rng(0))
    assert archive.counts.tolist() == [1]
    assert archive.leaders(0, rng=np.random.default_rng(0)).shape == (0,)


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"capacity": 0}, ParameterError, "capacity must be an integer >= 1; got 0"),
        ({"capacity": 2.5}, ParameterError, "capacity must be an integer"),
        ({"capacity": 5, "radius_divisor": 0}, ParameterError, "radius_divisor"),
        ({"capacity": 5, "leader": "best"}, UnknownNameError, "min-count, roulette"),
    ],
)
def test_bad_parameters(kwargs, error, match):
    with pytest.raises(error, match=match):
        CrowdingArchive(**kwargs)


def test_sorted_positions_is_numpys_searchsorted():
    """The compiled bisection of the 2-D counts (numba's searchsorted compiles for seconds)."""
    from moik.algorithms.archive.crowding import sorted_positions

    rng = np.random.default_rng(0)
    for _ in range(200):
        a = np.sort(rng.integers(0, 10, rng.integers(0, 20)).astype(float))
        v = rng.integers(-1, 11, 15) + rng.choice([0.0, 0.5], 15)
        for right in (True, False):
            np.testing.assert_array_equal(sorted_positions(a, v, right),
                                          np.searchsorted(a, v, "right" if right else "left"))
