"""Tests of moik.metrics.hypervolume and the EOSMA reference-point policy."""

from __future__ import annotations

import numpy as np
import pytest

from moik.exceptions import NonFiniteError, ParameterError, ShapeError
from moik.metrics import EOSMA_TABLE8_REF_POINTS, hypervolume, reference_point


def authors_hv_2d(front: np.ndarray, ref: np.ndarray) -> float:
    """The slice sum of the EOSMA authors' HV.m for a 2-D non-dominated front."""
    front = front[np.all(front < ref, axis=1)]
    front = front[np.argsort(front[:, 0])]
    previous_f2 = np.concatenate([[ref[1]], front[:-1, 1]])
    return float(np.sum((ref[0] - front[:, 0]) * (previous_f2 - front[:, 1])))


def test_hand_computed_fronts():
    # [1,2]x[1,2] plus [0.5,2]x[1.5,2] overlap in [1,2]x[1.5,2]: 1 + 0.75 - 0.5
    assert hypervolume([[1.0, 1.0], [0.5, 1.5]], [2.0, 2.0]) == pytest.approx(1.25)
    assert hypervolume([[0.0, 0.0]], [2.0, 3.0]) == pytest.approx(6.0)
    # staircase: 3 * 1 + 2 * 1 + 1 * 1
    assert hypervolume([[1.0, 3.0], [2.0, 2.0], [3.0, 1.0]], [4.0, 4.0]) == pytest.approx(6.0)
    assert hypervolume([[1.0, 1.0, 1.0]], [2.0, 3.0, 4.0]) == pytest.approx(6.0)


def test_points_outside_the_reference_box_add_nothing():
    front = np.array([[1.0, 3.0], [2.0, 2.0], [3.0, 1.0]])
    outside = np.array([[5.0, 0.0], [0.0, 5.0], [4.0, 0.5], [0.5, 4.0], [9.0, 9.0]])
    assert hypervolume(np.vstack([front, outside]), [4.0, 4.0]) == pytest.approx(6.0)
    assert hypervolume(outside, [4.0, 4.0]) == 0.0


def test_dominated_points_add_nothing_and_empty_front_is_zero():
    front = np.array([[1.0, 3.0], [2.0, 2.0], [3.0, 1.0]])
    dominated = np.array([[2.5, 2.5], [3.0, 3.0], [2.0, 2.0]])
    assert hypervolume(np.vstack([front, dominated]), [4.0, 4.0]) == pytest.approx(6.0)
    assert hypervolume(np.zeros((0, 2)), [1.0, 1.0]) == 0.0


def test_matches_the_authors_slice_sum_on_random_fronts():
    rng = np.random.default_rng(0)
    for _ in range(20):
        t = np.sort(rng.random(rng.integers(1, 30)))
        front = np.c_[t, (1.0 - t) ** 2] * rng.uniform(0.5, 2.0)
        ref = np.array([1.5, 1.7])
        assert hypervolume(front, ref) == pytest.approx(authors_hv_2d(front, ref), rel=1e-12)


def test_reference_point_is_1_1_times_the_maximum_over_all_fronts():
    fronts = [np.array([[1.0, 0.5], [0.2, 2.0]]), np.zeros((0, 2)), np.array([[3.0, 0.1]])]
    np.testing.assert_allclose(reference_point(fronts), [3.3, 2.2])
    np.testing.assert_allclose(reference_point(fronts, factor=1.0), [3.0, 2.0])


def test_paper_reference_points():
    assert EOSMA_TABLE8_REF_POINTS == {
        "P1": (2.088567, 2.466816),
        "P2": (1.695669, 2.524178),
    }


@pytest.mark.parametrize(
    ("F", "ref", "error", "match"),
    [
        ([1.0, 2.0], [3.0, 3.0], ShapeError, r"F must be a 2-D array .* got shape \(2,\)"),
        ([[1.0, 2.0]], [3.0], ShapeError, r"ref_point must have shape \(2,\) .* got \(1,\)"),
        ([[np.nan, 2.0]], [3.0, 3.0], NonFiniteError, "F must hold finite values only"),
        ([[1.0, 2.0]], [np.inf, 3.0], NonFiniteError, "ref_point must hold finite values"),
    ],
)
def test_hypervolume_bad_input(F, ref, error, match):
    with pytest.raises(error, match=match):
        hypervolume(F, ref)


def test_reference_point_bad_input():
    with pytest.raises(ParameterError, match="at least one front with at least one point"):
        reference_point([np.zeros((0, 2))])
    with pytest.raises(ParameterError, match="must be > 0 for the factor policy"):
        reference_point([np.array([[-1.0, 2.0]])])
    with pytest.raises(ParameterError, match="factor must be a finite number >= 1; got 0.5"):
        reference_point([np.ones((1, 2))], factor=0.5)
    with pytest.raises(ShapeError, match=r"same n_obj; got \[2, 3\]"):
        reference_point([np.ones((1, 2)), np.ones((1, 3))])
    with pytest.raises(NonFiniteError, match=r"fronts\[0\] must hold finite values"):
        reference_point([np.array([[np.inf, 1.0]])])
