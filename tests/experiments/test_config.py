"""Experiment configs (moik.experiments.config): validation messages, quick overrides, loading."""

from pathlib import Path

import pytest
import tomli_w
import tomllib

from moik.exceptions import ConfigError
from moik.experiments.config import ExperimentConfig, load_config, merge


@pytest.mark.parametrize("change, match", [
    ({"robot": "nope"}, "robot: unknown robot 'nope'"),
    ({"runs": 0}, "runs must be an integer >= 1, got 0"),
    ({"iterations": 2.5}, "iterations must be an integer >= 1"),
    ({"colour": 1}, "unknown key\\(s\\) colour"),
    ({"algorithms": [{"name": "nope"}]}, "algorithms\\[0\\].name: unknown algorithm 'nope'"),
    ({"algorithms": [{"name": "eosma", "params": {"zz": 1}}]}, "params: unknown key"),
    ({"algorithms": [{"name": "eosma", "params": {"q": 7.0}}]}, "params: .*q"),
    ({"algorithms": [{"name": "nsga2"}]}, "'nsga2' is multi-objective"),
    ({"problem": {"kind": "torque"}}, "problem.kind must be one of"),
    ({"targets": {"kind": "random", "n": 0, "seed": 1}}, "targets.n must be an integer >= 1"),
    ({"analyses": ["magic"]}, "analyses must be a list of"),
    ({"proposed": "sma"}, "proposed 'sma' is not an algorithm label"),
    ({"protocol": {"threshold": -1, "max_failures": 2}}, "protocol.threshold must be"),
    ({"algorithms": [{"name": "eosma"}, {"name": "eosma"}]}, "label must be a unique"),
])
def test_bad_configs_raise_clear_errors(tiny, change, match):
    tiny.update(change)
    with pytest.raises(ConfigError, match=match):
        ExperimentConfig.from_dict(tiny)


def test_the_former_n_gen_key_is_refused_naming_iterations(tiny):
    tiny["n_gen"] = tiny.pop("iterations")
    with pytest.raises(ConfigError, match="'n_gen' was renamed 'iterations'.*n_gen=6"):
        ExperimentConfig.from_dict(tiny)
    tiny["iterations"] = tiny.pop("n_gen")
    tiny["quick"] = {"n_gen": 2}
    with pytest.raises(ConfigError, match="quick: the key 'n_gen' was renamed 'iterations'"):
        ExperimentConfig.from_dict(tiny)


def test_missing_keys_and_orientation_requirements(tiny):
    del tiny["seed"]
    with pytest.raises(ConfigError, match="missing key\\(s\\) seed"):
        ExperimentConfig.from_dict(tiny)
    tiny["seed"] = 1
    tiny["problem"] = {"kind": "pose"}
    tiny["robot"] = "eosma7"
    with pytest.raises(ConfigError, match="needs with_orientation true"):
        ExperimentConfig.from_dict(tiny)


def test_optional_algorithms_are_left_out_when_not_registered(tiny):
    tiny["algorithms"].append({"name": "not-yet-written", "optional": True})
    cfg = ExperimentConfig.from_dict(tiny)
    assert cfg.labels == ["eosma", "pso"] and cfg.skipped == ("not-yet-written",)


def test_quick_overrides_merge_deeply(tiny_config):
    q = tiny_config.quick()
    assert q["runs"] == 1 and q["targets"]["n"] == 2 and q.is_quick
    assert q.fingerprint() != tiny_config.fingerprint()
    assert merge({"a": {"b": 1, "c": 2}}, {"a": {"b": 5}}) == {"a": {"b": 5, "c": 2}}


def test_load_config_file_errors(tmp_path):
    with pytest.raises(ConfigError, match="does not exist"):
        load_config(tmp_path / "none.toml")
    bad = tmp_path / "bad_one.py"
    bad.write_text("EXPERIMENT = {}\n")
    with pytest.raises(ConfigError, match=r"TOML data files \(.toml\); this is Python code"):
        load_config(bad)
    bad = tmp_path / "bad_one.toml"
    bad.write_text("name = \n")
    with pytest.raises(ConfigError, match="not valid TOML"):
        load_config(bad)


def test_extends_merges_the_base_under_the_variant(tmp_path, tiny):
    (tmp_path / "tiny_test.toml").write_text(tomli_w.dumps(tiny))
    variant = tmp_path / "tiny_test_long.toml"
    variant.write_text('extends = "tiny-test"\nname = "tiny-test-long"\nruns = 5\n'
                       '[targets]\nn = 3\n')
    cfg = load_config(variant)
    assert cfg["runs"] == 5 and cfg["targets"] == dict(tiny["targets"], n=3)
    assert cfg["pop_size"] == tiny["pop_size"] and cfg.labels == ["eosma", "pso"]
    direct = ExperimentConfig.from_dict(dict(tiny, name="tiny-test-long", runs=5,
                                             targets=dict(tiny["targets"], n=3)))
    assert cfg.fingerprint() == direct.fingerprint()  # the merged data is the config
    (tmp_path / "loop_a.toml").write_text('extends = "loop-b"\n')
    (tmp_path / "loop_b.toml").write_text('extends = "loop-a"\n')
    with pytest.raises(ConfigError, match="makes a cycle"):
        load_config(tmp_path / "loop_a.toml")
    (tmp_path / "orphan.toml").write_text('extends = "no-such-base"\n')
    with pytest.raises(ConfigError, match="'no-such-base', which is not a known experiment"):
        load_config(tmp_path / "orphan.toml")


def test_the_registry_configs_are_toml_and_three_variants_extend_their_base():
    folder = Path(__file__).resolve().parents[2] / "experiments"
    assert not list(folder.glob("[!_]*.py")) and len(list(folder.glob("*.toml"))) >= 21
    for variant, base in (("moo_suite_10k", "moo-suite"), ("mpso_circle_full_range",
                                                         "mpso-circle"),
                          ("mpso_table3_independent", "mpso-table3")):
        with (folder / f"{variant}.toml").open("rb") as f:
            assert tomllib.load(f)["extends"] == base


def test_a_free_joint_is_free_in_toml(tmp_path):
    """TOML has no null: ``"free"`` in locked_joints_deg is the free joint (None)."""
    folder = Path(__file__).resolve().parents[2] / "experiments"
    cfg = load_config(folder / "ibes_table9.toml")
    assert cfg["problem"]["locked_joints_deg"] == [None, None, None, 0.0, 0.0, 0.0]


