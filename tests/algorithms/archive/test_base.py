"""What every external archive keeps (moik.algorithms.archive.base): the non-dominated
filter, no duplicate objective rows, the capacity, input checks; run for each preset."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from moik.algorithms.archive import (
    CrowdingArchive,
    GridArchive,
    first_unique_mask,
    nondominated_mask,
)
from moik.exceptions import NonFiniteError, ParameterError, ShapeError

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
