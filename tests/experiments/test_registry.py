"""Where experiments are found (moik.experiments.registry): packaged configs, the env var."""

import sys

import pytest
import tomli_w

from moik.exceptions import ConfigError, UnknownNameError
from moik.experiments import registry
from moik.experiments.registry import ENV_VAR, available_experiments, get_experiment

PAPER_EXPERIMENTS = ["eosma-table5", "eosma-table7", "eosma-table8", "eosma-table9",
                     "mpso-single", "mpso-table2", "mpso-table3", "mpso-circle", "mpso-table5"]


def test_all_paper_experiments_are_listed_and_valid():
    assert set(PAPER_EXPERIMENTS) <= set(available_experiments())
    for name in PAPER_EXPERIMENTS:
        cfg = get_experiment(name)
        assert cfg.name == name and cfg.quick().is_quick


def test_dropping_a_file_adds_an_experiment(tmp_path, monkeypatch, tiny):
    (tmp_path / "tiny_test.toml").write_text(tomli_w.dumps(tiny))
    monkeypatch.setenv(ENV_VAR, str(tmp_path))
    assert "tiny-test" in available_experiments()
    assert get_experiment("tiny-test").labels == ["eosma", "pso"]
    (tmp_path / "other_name.toml").write_text(tomli_w.dumps(tiny))
    with pytest.raises(ConfigError, match="must match the file name"):
        get_experiment("other-name")
    with pytest.raises(UnknownNameError, match="unknown experiment 'zzz'; expected one of"):
        get_experiment("zzz")


def test_a_later_folder_replaces_an_earlier_experiment_of_the_same_name(tmp_path, monkeypatch,
                                                                        tiny):
    first, second = tmp_path / "a", tmp_path / "b"
    for folder, title in ((first, "first"), (second, "second")):
        folder.mkdir()
        (folder / "tiny_test.toml").write_text(tomli_w.dumps(dict(tiny, title=title)))
    (first / "_helper.py").write_text("X = 1\n")  # files starting with _ are not experiments
    monkeypatch.setenv(ENV_VAR, f"{first}{registry.os.pathsep}{second}")
    assert get_experiment("tiny-test")["title"] == "second"
    assert "-helper" not in available_experiments() and "_helper" not in available_experiments()


def test_a_config_path_is_an_experiment_name(tmp_path, tiny):
    path = tmp_path / "tiny_test.toml"
    path.write_text(tomli_w.dumps(tiny))
    assert get_experiment(str(path)).path == str(path)


def test_the_packaged_configs_are_found_with_importlib_resources(tmp_path, monkeypatch, tiny):
    """An installed moik: the configs are the files of the package ``moik.paper_configs``."""
    package = tmp_path / "fake_paper_configs"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "tiny_test.toml").write_text(tomli_w.dumps(tiny))
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(registry, "PACKAGE", "fake_paper_configs")
    monkeypatch.setattr(registry, "_CHECKOUT", tmp_path / "no-checkout" / "experiments")
    monkeypatch.delenv(ENV_VAR, raising=False)
    try:
        assert registry.packaged_dir() == package
        assert available_experiments() == ["tiny-test"]
        assert get_experiment("tiny-test").path == str(package / "tiny_test.toml")
    finally:
        sys.modules.pop("fake_paper_configs", None)


def test_a_checkout_without_the_installed_package_uses_its_experiments_folder(monkeypatch):
    monkeypatch.setattr(registry, "PACKAGE", "moik_no_such_package_here")
    assert registry.packaged_dir() == registry._CHECKOUT
    assert set(PAPER_EXPERIMENTS) <= set(available_experiments())


def test_a_source_checkout_uses_its_own_folder_over_an_installed_package(tmp_path, monkeypatch):
    """An editable install made from another checkout maps the package elsewhere: the
    configs still come from the tree the code runs from."""
    package = tmp_path / "elsewhere_paper_configs"
    package.mkdir()
    (package / "__init__.py").write_text("")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(registry, "PACKAGE", "elsewhere_paper_configs")
    try:
        assert registry.packaged_dir() == registry._CHECKOUT
    finally:
        sys.modules.pop("elsewhere_paper_configs", None)
