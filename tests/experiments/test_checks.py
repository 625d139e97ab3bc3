"""The config validators (moik.experiments.checks): moik._validate's rules, ConfigError."""

import numpy as np
import pytest

from moik.exceptions import ConfigError
from moik.experiments.checks import check_keys, flag, integer, number, numbers


def test_integers_reject_bools_and_floats():
    assert integer("x: runs", np.int64(3), 1) == 3 and isinstance(integer("r", 3, 1), int)
    for bad in (True, 2.0, "2", None):
        with pytest.raises(ConfigError, match=r"x: runs must be an integer >= 1, got"):
            integer("x: runs", bad, 1)
    with pytest.raises(ConfigError, match=r"seed must be an integer >= 0, got -1"):
        integer("seed", -1, 0)


def test_numbers_are_finite_and_never_bools():
    assert number("w", 2) == 2.0 and number("t", 1e-6, positive=True) == 1e-6
    for bad in (float("nan"), float("inf"), True, "1"):
        with pytest.raises(ConfigError, match="w must be a finite number"):
            number("w", bad)
    with pytest.raises(ConfigError, match="t must be a positive finite number"):
        number("t", 0.0, positive=True)
    assert numbers("c", (1, 2.5, 3), 3) == [1.0, 2.5, 3.0]
    with pytest.raises(ConfigError, match=r"c must be a list of 3 numbers, got \[1, 2\]"):
        numbers("c", [1, 2], 3)
    with pytest.raises(ConfigError, match=r"c\[1\] must be a finite number, got None"):
        numbers("c", [1, None, 3], 3)


def test_flags_and_keys():
    assert flag("o", False) is False
    with pytest.raises(ConfigError, match="o must be True or False, got 1"):
        flag("o", 1)
    assert check_keys("p", {"a": 1}, {"a", "b"}, ("a",)) == {"a": 1}
    with pytest.raises(ConfigError, match=r"p: unknown key\(s\) c; expected some of: a, b"):
        check_keys("p", {"a": 1, "c": 2}, {"a", "b"})
    with pytest.raises(ConfigError, match=r"p: missing key\(s\) b"):
        check_keys("p", {"a": 1}, {"a", "b"}, ("a", "b"))
    with pytest.raises(ConfigError, match="p must be a dict, got list"):
        check_keys("p", [], {"a"})
