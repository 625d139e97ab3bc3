"""Checks of a paper's printed statistics (moik.experiments.consistency)."""

import math

import numpy as np
import pytest

from moik.experiments.consistency import bhatia_davis_std_bound, smallest_p_values


def test_bound_is_reached_by_values_at_the_two_ends():
    x = np.array([0.0] * 3 + [1.0])  # mean 0.25
    assert bhatia_davis_std_bound(0.0, 1.0, 0.25) == pytest.approx(np.std(x))
    assert bhatia_davis_std_bound(0.0, 1.0, 0.25, n=4) == pytest.approx(np.std(x, ddof=1))
    rng = np.random.default_rng(0)
    for _ in range(50):
        y = rng.random(int(rng.integers(2, 40)))
        assert np.std(y, ddof=1) <= bhatia_davis_std_bound(y.min(), y.max(), y.mean(), y.size)


def test_paper_table2_position_std_is_impossible():
    # MO-m-PSO Table 2: best 3.81e-10, worst 0.0492, mean 0.0150, std 0.1973, 100 runs
    assert bhatia_davis_std_bound(3.81e-10, 0.0492, 0.0150, 100) < 0.03 < 0.1973


def test_smallest_p_values_of_30_runs():
    p_signed, p_ranksum = smallest_p_values(30)
    assert p_signed == pytest.approx(2 / 2**30)
    assert p_ranksum == pytest.approx(3.02e-11, rel=1e-2)  # the paper's 3.01e-11
    assert math.isclose(smallest_p_values(5)[0], 2 / 32)
