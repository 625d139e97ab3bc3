"""Adaptive-grid archive (moik.algorithms.archive.grid); shared invariants are in test_base.py."""

from __future__ import annotations

import numpy as np
import pytest

from moik.algorithms.archive import GridArchive, grid_bounds, grid_index
from moik.exceptions import ParameterError

FRONT = np.array([[0.0, 10.0], [5.0, 5.0], [10.0, 0.0]])


def test_grid_bounds_and_index_by_hand():
    lower, upper = grid_bounds(FRONT, 0.0)
    np.testing.assert_array_equal(lower, [0.0, 0.0])
    np.testing.assert_array_equal(upper, [10.0, 10.0])
    # 4 intervals: edges 2.5, 5, 7.5; 5.0 sits on an edge and goes to the upper interval
    np.testing.assert_array_equal(grid_index(FRONT, lower, upper, 4), [[0, 3], [2, 2], [3, 0]])
    lower, upper = grid_bounds(FRONT, 0.25)
    np.testing.assert_array_equal(lower, [-2.5, -2.5])
    np.testing.assert_array_equal(upper, [12.5, 12.5])
    # 3 intervals of width 5: edges 2.5 and 7.5
    np.testing.assert_array_equal(grid_index(FRONT, lower, upper, 3), [[0, 2], [1, 1], [2, 0]])


def test_archive_grid_with_the_mopso_preset():
    archive = GridArchive.mopso(10)
    F = np.array([[0.0, 10.0], [0.5, 9.0], [5.0, 5.0], [10.0, 0.0]])
    archive.add(np.zeros((4, 1)), F, rng=np.random.default_rng(0))
    np.testing.assert_allclose(archive.lower, [-1.0, -1.0])
    np.testing.assert_allclose(archive.upper, [11.0, 11.0])
    # 7 intervals of width 12/7 from -1: 0 -> 0, 0.5 -> 0, 5 -> 3, 9 -> 5, 10 -> 6
    np.testing.assert_array_equal(archive.grid_index, [[0, 6], [0, 5], [3, 3], [6, 0]])
    assert archive.cells.tolist() == [1, 0, 2, 3]  # ids in lexicographic order of the index
    assert archive.cell_counts.tolist() == [1, 1, 1, 1]


def test_shared_cells_are_counted():
    archive = GridArchive(10, n_grid=2, inflation=0.0)
    F = np.array([[0.0, 4.0], [1.0, 3.0], [3.0, 1.0], [4.0, 0.0]])
    archive.add(np.zeros((4, 1)), F, rng=np.random.default_rng(0))
    np.testing.assert_array_equal(archive.grid_index, [[0, 1], [0, 1], [1, 0], [1, 0]])
    assert archive.cells.tolist() == [0, 0, 1, 1]
    assert archive.cell_counts.tolist() == [2, 2]


def test_constant_objective_puts_everyone_in_interval_zero():
    archive = GridArchive.mogwo(10)
    F = np.array([[0.0, 1.0, 5.0], [1.0, 0.0, 5.0]])
    archive.add(np.zeros((2, 1)), F, rng=np.random.default_rng(0))
    np.testing.assert_array_equal(archive.grid_index[:, 2], [0, 0])
    assert set(archive.leaders(50, rng=np.random.default_rng(1)).tolist()) == {0, 1}


def test_leaders_favour_emptier_cells():
    # cell A holds 3 members, cell B holds 1: P(B) = 1 / (1 + exp(-2 * beta))
    archive = GridArchive(10, n_grid=2, inflation=0.0, beta=1.0)
    F = np.array([[0.0, 4.0], [0.5, 3.5], [1.0, 3.0], [4.0, 0.0]])
    archive.add(np.zeros((4, 1)), F, rng=np.random.default_rng(0))
    assert sorted(archive.cell_counts.tolist()) == [1, 3]
    picks = archive.leaders(20000, rng=np.random.default_rng(5))
    p_lonely = np.mean(picks == 3)
    assert p_lonely == pytest.approx(1 / (1 + np.exp(-2.0)), abs=0.015)
    crowded = np.bincount(picks, minlength=4)[:3] / np.sum(picks != 3)
    np.testing.assert_allclose(crowded, [1 / 3] * 3, atol=0.03)  # uniform inside a cell


def test_removal_favours_crowded_cells():
    # one removal: P(crowded cell) = 3 e^{3 g} / ... per cell, with gamma = 1
    F = np.array([[0.0, 4.0], [0.5, 3.5], [1.0, 3.0], [4.0, 0.0]])
    removed_lonely = 0
    trials = 2000
    for seed in range(trials):
        archive = GridArchive(3, n_grid=2, inflation=0.0, gamma=1.0)
        archive.add(np.arange(4.0)[:, None], F, rng=np.random.default_rng(seed))
        removed_lonely += 3.0 not in archive.X[:, 0]
    expected = np.exp(1.0) / (np.exp(1.0) + np.exp(3.0))
    assert removed_lonely / trials == pytest.approx(expected, abs=0.03)


def test_grid_is_rebuilt_after_truncation():
    rng = np.random.default_rng(3)
    archive = GridArchive.mopso(5)
    t = np.sort(rng.random(40))
    archive.add(np.zeros((40, 1)), np.c_[t, 1.0 - t], rng=rng)
    assert len(archive) == 5
    lower, upper = grid_bounds(archive.F, 0.1)
    np.testing.assert_allclose(archive.lower, lower)
    np.testing.assert_allclose(archive.upper, upper)
    assert archive.cell_counts.sum() == 5


def test_presets_and_repr():
    a = GridArchive.mopso(100)
    assert (a.n_grid, a.inflation, a.beta, a.gamma) == (7, 0.1, 2.0, 2.0)
    b = GridArchive.mogwo(100)
    assert (b.n_grid, b.inflation, b.beta, b.gamma) == (10, 0.1, 4.0, 2.0)
    assert repr(b).startswith("GridArchive(capacity=100, n_grid=10")


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"n_grid": 0}, "n_grid must be an integer >= 1; got 0"),
        ({"inflation": -0.1}, "inflation must be a finite number >= 0; got -0.1"),
        ({"inflation": "wide"}, "inflation must be a finite number >= 0; got 'wide'"),
        ({"beta": 0}, "beta must be a finite number > 0; got 0"),
        ({"gamma": float("nan")}, "gamma must be a finite number > 0; got nan"),
    ],
)
def test_bad_parameters(kwargs, match):
    with pytest.raises(ParameterError, match=match):
        GridArchive(10, **kwargs)


def test_pressure_must_be_exp_or_power():
    with pytest.raises(ParameterError, match="pressure must be one of exp, power"):
        GridArchive(5, pressure="linear")
