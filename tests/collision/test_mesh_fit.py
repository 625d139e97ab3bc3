"""Capsules enclosing a link's triangles, and their disk cache (moik/collision/mesh_fit.py)."""

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.collision import mesh_fit
from moik.collision.mesh_fit import cached_link_fit, encloses, fit_link

trimesh = pytest.importorskip("trimesh")


def _mesh(seed: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    m = trimesh.creation.capsule(height=rng.uniform(0.05, 0.4), radius=rng.uniform(0.02, 0.08))
    m.vertices = m.vertices * rng.uniform(0.5, 1.5, 3) + rng.normal(0, 0.01, (len(m.vertices), 3))
    return np.asarray(m.vertices), np.asarray(m.faces)


@settings(max_examples=15, deadline=None, derandomize=True)
@given(seed=st.integers(0, 10_000), capsules=st.integers(1, 3))
def test_every_point_of_every_triangle_is_inside(seed, capsules):
    V, F = _mesh(seed)
    fits = fit_link(V, F, capsules=capsules, split_gain=10.0)
    assert 1 <= len(fits) <= capsules and encloses(V, F, fits)
    w = np.random.default_rng(seed).dirichlet(np.ones(3), size=len(F))
    points = np.einsum("fk,fkd->fd", w, V[F])  # a random point on each triangle
    dist = np.full(len(points), np.inf)
    for a, b, r in fits:
        d = b - a
        s = np.clip((points - a) @ d / max(float(d @ d), 1e-300), 0.0, 1.0)
        dist = np.minimum(dist, np.linalg.norm(points - (a + s[:, None] * d), axis=1) - r)
    assert dist.max() <= 0.0


def test_the_cache_is_read_and_heals(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    V, F = _mesh(1)
    kwargs = {"identity": ["digest-1"], "axes": [], "capsules": 1, "split_gain": 0.85}
    first = cached_link_fit(V, F, **kwargs)
    (path,) = (tmp_path / "moik" / "collision").glob("fit-*.json")
    calls = []
    real = mesh_fit.fit_link
    monkeypatch.setattr(mesh_fit, "fit_link", lambda *a, **k: calls.append(1) or real(*a, **k))
    again = cached_link_fit(V, F, **kwargs)
    assert not calls and np.allclose(again[0][2], first[0][2])
    data = json.loads(path.read_text())
    data["payload"][0]["radius"] *= 0.5  # a tampered file no longer encloses the mesh
    path.write_text(json.dumps(data))
    healed = cached_link_fit(V, F, **kwargs)
    assert calls == [1] and healed[0][2] == first[0][2]
    path.write_text("{damaged")
    cached_link_fit(V, F, **kwargs)
    assert calls == [1, 1] and json.loads(path.read_text())["payload"]
    other = cached_link_fit(V, F, **{**kwargs, "identity": ["digest-2"]})
    assert calls == [1, 1, 1] and len(list(path.parent.glob("fit-*.json"))) == 2
    assert other[0][2] == first[0][2]
