"""The disk cache of reference fronts: fingerprint, round trip, unwritable folders."""

import inspect
import os
from dataclasses import replace

import numpy as np
import pytest

from moik.fronts import cache
from moik.robots.catalog import get_robot


def _planar_target(psi=0.8, phi=-0.4, dist=0.9):
    c, s = np.cos(phi), np.sin(phi)
    return (np.array([dist * np.cos(psi), dist * np.sin(psi), 0.0]),
            np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]))


def test_fingerprint_moves_with_robot_target_metric_and_settings():
    robot = get_robot("planar2")
    p, R = _planar_target()
    settings = {"levels": 40, "starts": 16, "checks": 1, "tol": 1e-9, "seed": 1}
    base = cache.fingerprint(robot, p, R, "geodesic", settings)
    assert base == cache.fingerprint(robot, p.copy(), R.copy(), "geodesic", dict(settings))
    # the last bits of a numpy-computed target (they differ between kinds of machine)
    # and the sign of a zero do not move it
    ulp = np.spacing(np.abs(p)) * np.array([1, -2, 3])
    assert base == cache.fingerprint(robot, p + ulp, np.where(R == 0, -0.0, R), "geodesic",
                                     settings)
    other_robot = replace(robot, upper=robot.upper * 0.5)
    moved = [cache.fingerprint(robot, p + [0, 1e-8, 0], R, "geodesic", settings),
             cache.fingerprint(robot, p, R.T, "geodesic", settings),
             cache.fingerprint(robot, p, R, "frobenius", settings),
             cache.fingerprint(robot, p, R, "geodesic", {**settings, "seed": 2}),
             cache.fingerprint(get_robot("eosma7-m"), p, R, "geodesic", settings),
             cache.fingerprint(other_robot, p, R, "geodesic", settings)]
    assert base not in moved and len(set(moved)) == len(moved)


def test_round_trip_through_the_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    robot = get_robot("planar2")
    p, R = _planar_target()
    first = cache.cached_front(robot, p, R, metric="geodesic", levels=6, starts=2)
    files = list((tmp_path / "moik" / "fronts").glob("*.npz"))
    assert len(files) == 1
    again = cache.cached_front(robot, p, R, metric="geodesic", levels=6, starts=2)
    np.testing.assert_array_equal(first.F, again.F)
    np.testing.assert_array_equal(first.Q, again.Q)
    assert again.guarantee == first.guarantee and again.reachable == first.reachable
    files[0].write_bytes(b"damaged")  # a damaged file is recomputed, not an error
    third = cache.cached_front(robot, p, R, metric="geodesic", levels=6, starts=2)
    np.testing.assert_array_equal(first.F, third.F)


def test_unwritable_cache_still_returns_the_front(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocker))
    p, R = _planar_target()
    front = cache.cached_front(get_robot("planar2"), p, R, metric="geodesic", levels=4,
                               starts=1)
    assert len(front.F) >= 2


def test_ship_uses_cached_fronts_defaults():
    defaults = {k: v.default for k, v in inspect.signature(cache.cached_front).parameters.items()
                if k in cache.DEFAULT_SETTINGS}
    assert defaults == cache.DEFAULT_SETTINGS


@pytest.mark.parametrize("name", ["cache_dir"])
def test_cache_dir_follows_xdg(monkeypatch, tmp_path, name):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert getattr(cache, name)() == tmp_path / "moik" / "fronts"


def _flip_bit(data: bytes) -> bytes:
    middle = len(data) // 2
    return data[:middle] + bytes([data[middle] ^ 0x10]) + data[middle + 1:]


@pytest.mark.parametrize("damage", [
    lambda d: d[: len(d) // 2],  # truncated: BadZipFile
    lambda d: b"",  # emptied: EOFError
    _flip_bit,  # a flipped bit: a CRC error
    lambda d: b"PK\x03\x04" + b"\x00" * 40,  # a zip header with nothing behind
    lambda d: b"\x93NUMPY" + d,  # garbage before the archive
])
def test_a_damaged_cache_file_is_recomputed_and_replaced(tmp_path, monkeypatch, damage):
    """Before: BadZipFile and EOFError escaped _load, breaking pareto_front() for good."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    robot = get_robot("planar2")
    p, R = _planar_target()
    first = cache.cached_front(robot, p, R, metric="geodesic", levels=6, starts=2)
    (path,) = (tmp_path / "moik" / "fronts").glob("*.npz")
    path.write_bytes(damage(path.read_bytes()))
    again = cache.cached_front(robot, p, R, metric="geodesic", levels=6, starts=2)
    np.testing.assert_array_equal(first.F, again.F)
    assert cache._load(path, path.stem) is not None  # healed: the file is whole again
    assert [f.name for f in path.parent.iterdir()] == [path.name]


def test_a_failed_store_leaves_no_temporary(tmp_path, monkeypatch):
    """Before: an exception during the write left the mkstemp temporary behind."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    robot = get_robot("planar2")
    p, R = _planar_target()

    def interrupted(fd):
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        cache.cached_front(robot, p, R, metric="geodesic", levels=6, starts=2)
    folder = tmp_path / "moik" / "fronts"
    assert not folder.exists() or list(folder.iterdir()) == []
