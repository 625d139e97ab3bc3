"""The one set of validators: one rule each (moik/_validate.py)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from moik import _validate as v
from moik.exceptions import (
    ConfigError,
    NonFiniteError,
    ParameterError,
    ShapeError,
    UnknownNameError,
)


@given(st.integers(min_value=-10**6, max_value=10**6))
def test_integer_accepts_ints_in_range(x):
    if x >= 0:
        assert v.integer("n", x, minimum=0) == x
    else:
        with pytest.raises(ParameterError, match=r"n must be an integer >= 0, got"):
            v.integer("n", x, minimum=0)


@pytest.mark.parametrize("bad", [True, False, 2.0, "3", None, np.float64(2.0)])
def test_integer_refuses_bools_floats_and_strings(bad):
    with pytest.raises(ParameterError, match=r"pop_size must be an integer >= 2"):
        v.integer("pop_size", bad, minimum=2)


def test_integer_numpy_ints_and_error_class():
    assert v.integer("n", np.int64(4), minimum=1, maximum=4) == 4
    with pytest.raises(ConfigError, match=r"runs must be an integer in \[1, 3\], got 5"):
        v.integer("runs", 5, minimum=1, maximum=3, error=ConfigError)


@given(st.floats(allow_nan=True, allow_infinity=True))
def test_number_is_finite_and_in_range(x):
    if np.isfinite(x) and 0 < x <= 1:
        assert v.number("w", x, minimum=0, maximum=1, lo_open=True) == x
    else:
        with pytest.raises(ParameterError, match=r"w must be a finite number in \(0, 1\]"):
            v.number("w", x, minimum=0, maximum=1, lo_open=True)


@pytest.mark.parametrize("value", [-0.1, 1.1, "0.5", None, True, np.nan])
def test_interval_rejects_with_range(value):
    with pytest.raises(ParameterError, match=r"z must be a number in \[0.0, 1.0\]"):
        v.interval("z", value, 0.0, 1.0)


def test_interval_open_bounds():
    assert v.interval("V", 1, 0.0, np.inf, lo_open=True, hi_open=True) == 1.0
    with pytest.raises(ParameterError, match=r"\(0.0, inf\)"):
        v.interval("V", 0.0, 0.0, np.inf, lo_open=True, hi_open=True)


def test_number_refuses_bool_and_positive():
    with pytest.raises(ParameterError):
        v.number("x", True)
    assert v.positive("tol", 0.0, allow_zero=True) == 0.0
    with pytest.raises(ParameterError, match="tol must be a positive finite number, got 0.0"):
        v.positive("tol", 0.0)


def test_finite_array_normalises_and_locates_bad_values():
    view = np.arange(12.0).reshape(3, 4)[:, ::2]
    view.flags.writeable = False
    a = v.finite_array("Q", view, shape=(None, 2))
    assert a.flags.c_contiguous and a.flags.writeable and a.dtype == np.float64
    with pytest.raises(ShapeError, match=r"Q must have shape \(n, 3\), got \(3, 2\)"):
        v.finite_array("Q", view, shape=(None, 3))
    with pytest.raises(NonFiniteError, match=r"at index \(1,\)"):
        v.finite_array("q", [0.0, np.nan])
    with pytest.raises(ShapeError, match="array of real numbers"):
        v.finite_array("q", ["a", "b"])


def test_seed_choice_flag_keywords():
    assert v.seed("seed", 3) == 3 and v.seed("seed", None) is None
    with pytest.raises(ParameterError, match="non-negative integer"):
        v.seed("seed", -1)
    assert v.choice("metric", "Geodesic", ["geodesic", "frobenius"]) == "geodesic"
    with pytest.raises(UnknownNameError, match="expected one of: frobenius, geodesic"):
        v.choice("metric", "bogus", ["geodesic", "frobenius"])
    with pytest.raises(ParameterError, match="True or False"):
        v.flag("polish", 1)
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) pop_sise for EOSMA; "
                                             r"accepted: a1, pop_size"):
        v.keywords("EOSMA", {"pop_sise": 50}, ["pop_size", "a1"])


@pytest.mark.parametrize(("bad", "what"), [
    (["1.5", "2"], "got strings"),
    ("1 2 3", "got a str"),
    (b"12", "got a bytes"),
    ([1 + 2j, 0.0], "got complex numbers"),
    (np.array([1.0, 2.0]) + 0j, "got complex numbers"),
    ([True, False], "got booleans"),
    ({"x": 1.0}, "got a dict"),
    (None, "got a NoneType"),
    ([1.0, None], "got object entries"),
    ([[1.0, 2.0], [3.0]], "with rows of equal length"),
])
def test_real_array_refuses_what_is_not_real_numbers(bad, what):
    with pytest.raises(ShapeError, match=f"q must be an array of real numbers.*{what}"):
        v.real_array("q", bad)
    with pytest.raises(ConfigError, match="x must be an array of real numbers"):
        v.finite_array("x", bad, error=ConfigError)


def test_real_array_normalises_without_checking_finiteness():
    a = v.real_array("q", [1, 2, np.inf])
    assert a.dtype == np.float64 and a.flags.c_contiguous and a.flags.writeable
    b = v.real_array("q", np.arange(3, dtype=np.int32))
    np.testing.assert_array_equal(b, [0.0, 1.0, 2.0])
    frozen = np.zeros(2)
    frozen.flags.writeable = False
    assert v.real_array("q", frozen).flags.writeable  # a copy


def test_named_numbers_checks_names_and_each_interval():
    limits = {"a": (0.0, 1.0), "b": (-np.inf, np.inf)}
    assert v.named_numbers("vals", {"a": 1, "b": -5.5}, limits) == {"a": 1.0, "b": -5.5}
    for bad, what in [({"c": 0.0}, r"unknown key\(s\) c; expected some of: a, b"),
                      ({"a": 1.5}, r"vals\['a'\] must be a number in \[0.0, 1.0\], got 1.5"),
                      ({"b": np.nan}, r"vals\['b'\] must be a number"),
                      ({"a": True}, r"vals\['a'\] must be a number"),
                      ([1.0], "vals must be a mapping")]:
        with pytest.raises(ConfigError, match=what):
            v.named_numbers("vals", bad, limits, error=ConfigError)
