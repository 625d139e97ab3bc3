"""Tests of the external archives: shared invariants, CrowdingArchive specifics."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from moik.algorithms.archive import (
    CrowdingArchive,
    GridArchive,
    crowding_counts,
    crowding_radius,
    first_unique_mask,
    nondominated_mask,
)
from moik.algorithms.archive.crowding import _crowding_counts_front_2d, _crowding_counts_pairwise
from moik.exceptions import NonFiniteError, ParameterError, ShapeError, UnknownNameError

FACTORIES = {
    "moeosma": CrowdingArchive.moeosma,
    "mirjalili": CrowdingArchive.mirjalili,
    "recount": lambda c: CrowdingArchive(c, recount=True),
    "mopso": GridArchive.mopso,
    "mogwo": GridArchive.mogwo,
}


def naive_nondominated(F: np.ndarray) -> np.ndarray:
    """Eq. 11 by definition, one pair at a time (reference for the vectorized code)."""
    m = F.shape[0]
    return np.array(
        [
            not any(np.all(F[j] <= F[i]) and np.any(F[j] < F[i]) for j in range(m) if j != i)
            for i in range(m)
        ],
        dtype=bool,
    )


def batches(n_obj: int):
    """Batches of objective rows on a coarse lattice, so ties and duplicates occur."""
    rows = st.integers(0, 12)
    return st.lists(
        arrays(np.int64, st.tuples(rows, st.just(n_obj)), elements=st.integers(0, 6)).map(
            lambda a: a / 3.0
        ),
        min_size=1,
        max_size=6,
    )


def fill(archive, batch_list, seed=0):
    """Add the batches; X row = [global row id], so members can be traced back."""
    rng = np.random.default_rng(seed)
    start = 0
    for F in batch_list:
        X = np.arange(start, start + F.shape[0], dtype=float)[:, None]
        archive.add(X, F, rng=rng)
        start += F.shape[0]
    return archive


@pytest.mark.parametrize("kind", sorted(FACTORIES))
@settings(max_examples=40, deadline=None)
@given(n_obj=st.sampled_from([2, 3]), data=st.data(), capacity=st.integers(1, 8))
def test_invariants_after_any_additions(kind, n_obj, data, capacity):
    batch_list = data.draw(batches(n_obj))
    archive = fill(FACTORIES[kind](capacity), batch_list)
    added = np.concatenate(batch_list)
    F, X = archive.F, archive.X
    assert len(archive) <= capacity
    assert len(archive) >= 1 or added.shape[0] == 0
    assert naive_nondominated(F).all()
    assert first_unique_mask(F).all()
    np.testing.assert_array_equal(added[X[:, 0].astype(int)], F)  # X stays paired with F
    last = batch_list[-1]  # nothing in the latest batch dominates a member
    for f in last:
        assert not np.any(np.all(f <= F, axis=1) & np.any(f < F, axis=1))


@pytest.mark.parametrize("kind", sorted(FACTORIES))
@settings(max_examples=30, deadline=None)
@given(n_obj=st.sampled_from([2, 3]), data=st.data())
def test_without_overflow_the_archive_is_the_front_of_everything(kind, n_obj, data):
    batch_list = data.draw(batches(n_obj))
    archive = fill(FACTORIES[kind](1000), batch_list)
    added = np.concatenate(batch_list)
    front = added[naive_nondominated(added)]
    front = front[first_unique_mask(front)]
    key = np.lexsort(front.T[::-1])
    got = archive.F[np.lexsort(archive.F.T[::-1])]
    np.testing.assert_array_equal(got, front[key])


@pytest.mark.parametrize("kind", sorted(FACTORIES))
def test_same_seed_gives_the_same_archive_and_leaders(kind):
    F_batches = [np.random.default_rng(s).random((40, 2)) ** 0.3 for s in range(5)]
    runs = []
    for _ in range(2):
        archive = fill(FACTORIES[kind](10), F_batches, seed=7)
        runs.append(
            (archive.X.copy(), archive.F.copy(), archive.leaders(20, rng=np.random.default_rng(3)))
        )
    for a, b in zip(runs[0], runs[1], strict=True):
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("kind", sorted(FACTORIES))
def test_a_point_dominating_every_member_empties_the_rest(kind):
    rng = np.random.default_rng(1)
    archive = FACTORIES[kind](50)
    F = rng.random((30, 2))
    archive.add(np.zeros((30, 3)), F, rng=rng)
    archive.add(np.ones((1, 3)), F.min(axis=0, keepdims=True) - 0.1, rng=rng)
    assert len(archive) == 1
    np.testing.assert_array_equal(archive.X, np.ones((1, 3)))
    assert archive.leaders(4, rng=rng).tolist() == [0, 0, 0, 0]


@pytest.mark.parametrize("kind", sorted(FACTORIES))
def test_duplicates_keep_the_first_member(kind):
    rng = np.random.default_rng(0)
    archive = FACTORIES[kind](5)
    archive.add([[1.0], [2.0]], [[0.0, 1.0], [0.0, 1.0]], rng=rng)
    archive.add([[3.0]], [[0.0, 1.0]], rng=rng)
    np.testing.assert_array_equal(archive.X, [[1.0]])
    assert archive.X.flags.writeable is False and archive.F.flags.writeable is False


@settings(max_examples=60, deadline=None)
@given(
    arrays(
        np.int64, st.tuples(st.integers(0, 25), st.sampled_from([2, 3])), elements=st.integers(0, 5)
    )
)
def test_nondominated_mask_matches_the_definition(F):
    F = F.astype(float)
    np.testing.assert_array_equal(nondominated_mask(F), naive_nondominated(F))


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
    assert fast is not None
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


@pytest.mark.parametrize("kind", sorted(FACTORIES))
def test_bad_inputs(kind):
    rng = np.random.default_rng(0)
    archive = FACTORIES[kind](5)
    with pytest.raises(ShapeError, match=r"F must be a 2-D array .* got shape \(2,\)"):
        archive.add([[0.0], [1.0]], [0.0, 1.0], rng=rng)
    with pytest.raises(ShapeError, match="same number of rows"):
        archive.add([[0.0]], [[0.0, 1.0], [1.0, 0.0]], rng=rng)
    with pytest.raises(NonFiniteError, match="F must hold finite values only; got nan"):
        archive.add([[0.0]], [[np.nan, 1.0]], rng=rng)
    with pytest.raises(NonFiniteError, match="X must hold finite values only; got inf"):
        archive.add([[np.inf]], [[0.0, 1.0]], rng=rng)
    archive.add([[0.0]], [[0.0, 1.0]], rng=rng)
    with pytest.raises(ShapeError, match="F must have 2 columns"):
        archive.add([[0.0]], [[0.0, 1.0, 2.0]], rng=rng)
    with pytest.raises(ShapeError, match="X must have 1 columns"):
        archive.add([[0.0, 1.0]], [[0.0, 1.0]], rng=rng)
    with pytest.raises(ParameterError, match="k must be an integer >= 0; got -1"):
        archive.leaders(-1, rng=rng)
