"""Shared pytest configuration: the ``slow`` marker, the hypothesis profiles, and the fake
child process of the background compiles (:func:`fake_popen`).

Tests marked ``slow`` are measurements that take tens of seconds; deselect them
with ``pytest -m "not slow"``.

The property tests draw the same examples on every run and machine (hypothesis'
``derandomize``): a clean clone passes or fails as the last run did, and a failure
seen once is seen again. ``pytest --hypothesis-profile explore`` draws new random
examples at each run, to look for cases the fixed ones miss.
"""

import os
import shutil
import tempfile
from pathlib import Path

import pytest
from hypothesis import settings

settings.register_profile("reproducible", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile("reproducible")  # --hypothesis-profile loads another after this


def pytest_configure(config):
    config.addinivalue_line(
        "markers", "slow: long accuracy measurements (deselect with -m 'not slow')")


class FakePopen:
    """Stands in for subprocess.Popen in :mod:`moik.warmup.background`: keeps what the
    child would read on its stdin."""

    started: list = []

    def __init__(self, argv, stdin=None, stdout=None, **kwargs):
        self.argv, self.kwargs, self.written = argv, kwargs, b""
        self.stdin = self
        FakePopen.started.append(self)

    def write(self, data):
        self.written += data

    def close(self):
        pass

    def poll(self):
        return 0

    def wait(self, timeout=None):
        return 0


@pytest.fixture()
def fake_popen(monkeypatch):
    """Background compiles start a :class:`FakePopen` (two idle CPUs, nothing cached, the
    switch unset): tests see what a child would be given, and no child runs."""
    from moik import _jit
    from moik.warmup import background as _background

    FakePopen.started = []
    monkeypatch.setattr(_background.subprocess, "Popen", FakePopen)
    monkeypatch.setattr(_background, "available_cores", lambda: 2)
    monkeypatch.setattr(_background, "idle_cpus", lambda: 2.0)
    monkeypatch.setattr(_jit, "is_cached", lambda kernel: False)
    monkeypatch.delenv(_background.ENV_SWITCH, raising=False)
    return FakePopen


SEEDS = Path(__file__).parent / "data" / "collision_cache"


@pytest.fixture(scope="session", autouse=True)
def seeded_collision_cache():
    """The collision cache entries of the test arms (tests/data/collision_cache/README.md)
    copied into moik's collision cache where absent (atomically: two workers may copy)."""
    from moik.collision.mesh_fit import cache_dir

    folder = cache_dir()
    try:
        folder.mkdir(parents=True, exist_ok=True)
        for seed in SEEDS.glob("*.json"):
            if not (folder / seed.name).exists():
                fd, tmp = tempfile.mkstemp(dir=folder, suffix=".tmp")
                os.close(fd)
                shutil.copyfile(seed, tmp)
                os.replace(tmp, folder / seed.name)
    except OSError:  # an unwritable cache: the tests compute what they need
        pass
