"""Bounded reading of JSON and TOML from elsewhere (moik/_validate/reading.py): size,
nesting, numbers, UTF-8, and only regular files."""

import pytest

from moik._validate import reading as _reading
from moik.exceptions import ConfigError, GeometryError


def test_deep_nesting_is_refused_not_a_recursion_error():
    with pytest.raises(GeometryError, match="nested deeper|nesting deeper"):
        _reading.parse_json("[" * 100_000 + "]" * 100_000, "scene", GeometryError)
    with pytest.raises(GeometryError, match="nesting deeper than 64"):
        _reading.parse_json("[" * 70 + "]" * 70, "scene", GeometryError)
    assert _reading.parse_json("[" * 60 + "]" * 60, "scene", GeometryError) is not None


def test_numbers_out_of_range_are_refused():
    with pytest.raises(GeometryError, match="digits"):
        _reading.parse_json('{"length": ' + "9" * 400 + "}", "scene", GeometryError)
    for text in ('{"x": NaN}', '{"x": Infinity}', '{"x": 1e400}'):
        with pytest.raises(GeometryError):
            _reading.parse_json(text, "scene", GeometryError)
    assert _reading.parse_json('{"seed": 340282366920938463463374607431768211455}', "m",
                               GeometryError)["seed"] == 2**128 - 1


def test_invalid_utf8_is_refused(tmp_path):
    path = tmp_path / "c.toml"
    path.write_bytes(b'name = "\xff\xfe"\n')
    with pytest.raises(ConfigError, match="not UTF-8"):
        _reading.read_toml(path, "experiment file", ConfigError)
    with pytest.raises(GeometryError, match="not UTF-8"):
        _reading.parse_json(b'{"a": "\xff"}', "scene", GeometryError)


def test_only_regular_files_are_read_and_never_without_limit(tmp_path):
    with pytest.raises(GeometryError, match="not a regular file"):
        _reading.read_json("/dev/zero", "scene", GeometryError)
    with pytest.raises(GeometryError, match="not a regular file"):
        _reading.read_json(tmp_path, "scene", GeometryError)
    big = tmp_path / "big.json"
    big.write_bytes(b" " * 2000)
    with pytest.raises(GeometryError, match="larger than 1000 bytes"):
        _reading.read_json(big, "scene", GeometryError, limit=1000)


def test_deep_toml_is_refused(tmp_path):
    path = tmp_path / "deep.toml"
    path.write_text("x = " + "[" * 5000 + "]" * 5000 + "\n")
    with pytest.raises(ConfigError, match="nest"):
        _reading.read_toml(path, "experiment file", ConfigError)
