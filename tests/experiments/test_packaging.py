"""The papers' configs ship inside the wheel as ``moik.paper_configs`` (pyproject.toml)."""

import importlib.util
from pathlib import Path

import pytest

from moik.experiments import registry

tomllib = pytest.importorskip("tomllib")

ROOT = Path(__file__).resolve().parents[2]


def _setuptools() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]


def _configs(folder: Path) -> set[str]:
    return {p.name for p in folder.glob("*.toml") if not p.name.startswith("_")}


def test_the_experiments_folder_is_mapped_into_the_package():
    tool = _setuptools()
    assert tool["package-dir"]["moik.paper_configs"] == "experiments"
    assert "moik.paper_configs" in tool["packages"]
    assert (ROOT / "experiments" / "__init__.py").is_file()


def test_every_package_folder_is_listed():
    """The package list is explicit (the finder cannot see mapped packages): none is missing."""
    folders = {".".join(p.parent.relative_to(ROOT).parts) for p in (ROOT / "moik").rglob("*.py")
               if "__pycache__" not in p.parts}
    assert folders <= set(_setuptools()["packages"])


def test_the_type_marker_ships_in_the_wheel():
    """PEP 561: ``moik/py.typed`` exists and is package data of ``moik``."""
    assert (ROOT / "moik" / "py.typed").is_file()
    assert "py.typed" in _setuptools()["package-data"]["moik"]


def test_the_packaged_configs_list_every_config():
    packaged = registry.packaged_dir()
    assert packaged is not None
    expected = _configs(ROOT / "experiments")
    assert len(expected) >= 14 and _configs(packaged) == expected
    listed = registry.experiment_files()
    assert {p.name for p in listed.values() if p.parent == packaged} == expected
    if importlib.util.find_spec(registry.PACKAGE) is not None:  # installed with the mapping
        from importlib import resources

        assert _configs(Path(str(resources.files(registry.PACKAGE)))) == expected


def test_the_toml_configs_are_package_data():
    """A wheel ships only .py files of a package unless package-data names the others."""
    assert "*.toml" in _setuptools()["package-data"]["moik.paper_configs"]
