"""Config files from elsewhere: every malformed file ends in a ConfigError naming it."""

import pytest

from moik.exceptions import ConfigError
from moik.experiments.config import ExperimentConfig, load_config
from moik.experiments.config_files import read_config

GOOD = '''name = "mine"
title = "t"
source = "s"
robot = "planar2"
pop_size = 8
iterations = 6
runs = 1
seed = 1
problem = {kind = "position"}
targets = {kind = "random", n = 1, seed = 1, with_orientation = false}
'''


def _write(tmp_path, text, name="mine.toml", raw=False):
    path = tmp_path / name
    path.write_bytes(text) if raw else path.write_text(text)
    return path


def test_a_good_file_loads(tmp_path):
    path = _write(tmp_path, GOOD + 'algorithms = [{name = "eosma"}]\n')
    assert load_config(path).name == "mine"


@pytest.mark.parametrize("text, match", [
    (b'name = "\xff"\n', "not UTF-8"),
    (b"x = " + b"[" * 5000 + b"]" * 5000 + b"\n", "nest"),
    (b'extends = "../x"\n', "extends"),
    (b'extends = "a\\u0000b"\n', "extends"),
])
def test_malformed_files_end_in_a_config_error(tmp_path, text, match):
    """Before: UnicodeDecodeError, RecursionError, ValueError from Path.with_name."""
    with pytest.raises(ConfigError, match=match):
        read_config(_write(tmp_path, text, raw=True))


def test_a_non_string_algorithm_name_is_refused(tmp_path):
    """Before: TypeError (unhashable list) at the registry lookup."""
    path = _write(tmp_path, GOOD + "algorithms = [{name = [1, 2]}]\n")
    with pytest.raises(ConfigError, match="algorithm name"):
        load_config(path)


def test_a_label_longer_than_a_file_name_is_refused(tiny):
    tiny["algorithms"][0]["label"] = "a" * 300
    with pytest.raises(ConfigError, match="at most 120"):
        ExperimentConfig.from_dict(tiny)


def test_a_misspelt_key_names_the_nearest_one(tiny):
    tiny["iteratons"] = tiny.pop("iterations")
    with pytest.raises(ConfigError, match="did you mean 'iterations'"):
        ExperimentConfig.from_dict(tiny)


def test_dev_null_is_not_called_missing():
    """Before: '/dev/null' does not exist."""
    with pytest.raises(ConfigError, match="not a regular file"):
        read_config("/dev/null")
