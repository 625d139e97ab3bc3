"""The pieces of a link's mesh (moik.collision.decompose, moik.collision.mesh_pieces): they
hold every triangle, follow a fork's gap, are cached, and a damaged cache entry is
recomputed."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull

from moik.collision import decompose, mesh_pieces
from moik.collision.decompose import SLABS, convex_pieces
from moik.collision.mesh_pieces import cached_parts


def _fork(gap: float = 0.06) -> trimesh.Trimesh:
    """A U: a base 0.2 x 0.2 x 0.04 m and two tines 0.3 m long, ``gap`` apart (a wrist fork)."""
    t = (0.2 - gap) / 2
    parts = [trimesh.creation.box((0.2, 0.2, 0.04)),
             trimesh.creation.box((t, 0.2, 0.3)), trimesh.creation.box((t, 0.2, 0.3))]
    parts[1].apply_translation([-(gap + t) / 2, 0, 0.17])
    parts[2].apply_translation([(gap + t) / 2, 0, 0.17])
    return trimesh.util.concatenate(parts)


def _inside_some(pieces: list[np.ndarray], points: np.ndarray, tol: float = 1e-9) -> np.ndarray:
    """Which points lie within ``tol`` (relative to the piece's size) of a piece's hull
    (a flat piece's hull joggled into a thin solid by qhull's QJ)."""
    inside = np.zeros(len(points), dtype=bool)
    for P in pieces:
        eq = ConvexHull(P, qhull_options="QJ").equations
        size = float(np.ptp(P, axis=0).max())
        inside |= (points @ eq[:, :3].T + eq[:, 3] <= tol * size).all(axis=1)
    return inside


def _surface_points(V: np.ndarray, F: np.ndarray, n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    w = rng.dirichlet(np.ones(3), size=(len(F), n))
    return np.einsum("fnk,fkd->fnd", w, V[F]).reshape(-1, 3)


MESHES = {
    "fork": _fork,
    "annulus": lambda: trimesh.creation.annulus(0.1, 0.2, 0.05),
    "capsule": lambda: trimesh.creation.capsule(0.3, 0.05),
    "box": lambda: trimesh.creation.box((0.4, 0.1, 0.05)),
}


@settings(max_examples=8, deadline=None)
@given(name=st.sampled_from(sorted(MESHES)), seed=st.integers(0, 2**16),
       stretch=st.tuples(*[st.floats(0.3, 3.0)] * 3))
def test_the_pieces_hold_every_triangle(name, seed, stretch):
    """Points drawn on the mesh's own triangles (and its vertices) lie in a piece's hull."""
    mesh = MESHES[name]()
    V = np.asarray(mesh.vertices) * np.asarray(stretch)
    F = np.asarray(mesh.faces)
    pieces = convex_pieces(V, F)
    assert 1 <= len(pieces) <= decompose.pieces_of(V)
    assert _inside_some(pieces, np.vstack([V, _surface_points(V, F, 3, seed)]), 1e-8).all()


def test_a_fork_is_cut_along_its_gap():
    """Slabs across the tines each span the gap (checked: the decomposition stopped before
    its concavity cuts); the cuts leave the gap outside every piece, the space another link
    would move in."""
    mesh = _fork()
    V, F = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    gap = np.array([[0.0, y, z] for y in (-0.05, 0.0, 0.05) for z in (0.15, 0.2, 0.25, 0.3)])
    slabs = convex_pieces(V, F, max_pieces=1)
    assert _inside_some(slabs, gap).any()
    pieces = convex_pieces(V, F)
    assert len(pieces) > len(slabs)
    assert not _inside_some(pieces, gap).any()


def _mushroom() -> trimesh.Trimesh:
    """A rod (radius 0.035 m, 0.13 m long, along x) under a flange (radius 0.1 m, 0.04 m
    thick): a compact link (a wrist flange) with empty space around its rod."""
    rod = trimesh.creation.cylinder(radius=0.035, height=0.13, sections=24)
    flange = trimesh.creation.cylinder(radius=0.1, height=0.04, sections=48)
    flange.apply_translation([0, 0, 0.085])
    mesh = trimesh.util.concatenate([rod, flange])
    mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [0, 1, 0]))
    return mesh


def test_the_space_around_a_flange_rod_is_left_out():
    """The empty space beside the rod, under the flange, is outside every piece. Measured
    on the ABB IRB 140's flange (rtb-data): its concavity was read as 0 when the measure
    kept the deepest empty cells of the whole grid (the corners, outside every hull), and
    its slabs were cut across the flange, so the forearm's fork, 6-9 mm from the flange's
    mesh, overlapped its pieces in every configuration."""
    mesh = _mushroom()
    V, F = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    beside = np.array([[x, r * np.cos(a), r * np.sin(a)] for x in (-0.04, 0.0, 0.03)
                       for r in (0.06, 0.08) for a in np.linspace(0, 2 * np.pi, 8, endpoint=False)])
    assert not _inside_some(convex_pieces(V, F), beside).any()


def test_a_compact_convex_mesh_stays_whole_and_a_long_one_keeps_its_slabs():
    ball = trimesh.creation.icosphere(subdivisions=3)
    assert len(convex_pieces(np.asarray(ball.vertices), np.asarray(ball.faces))) == 1
    rod = trimesh.creation.capsule(0.6, 0.05)
    assert len(convex_pieces(np.asarray(rod.vertices), np.asarray(rod.faces))) == SLABS


def test_the_pieces_are_cached_and_a_damaged_entry_recomputed(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    mesh = _fork()
    V, F = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    first = cached_parts(V, F, identity=["fork"])
    (entry,) = (tmp_path / "moik" / "collision").glob("pieces-*.json")
    stored = entry.read_text()

    def fail(*args, **kwargs):
        raise AssertionError("recomputed")

    with monkeypatch.context() as m:
        m.setattr(mesh_pieces.decompose, "decompose", fail)
        again = cached_parts(V, F, identity=["fork"])
    assert len(again) == len(first)
    assert all(np.array_equal(a, b) for a, b in zip(first, again, strict=True))
    head = stored[:stored.index('"payload"')]
    for damaged in ('"text"', "12", "[[0, 1, 0]]", "[[5, 1, 0, 0, 0.1]]", "[[0, 0, 0, 0, 0.1]]",
                    '[[0, NaN, 0, 1, 0.1]]', '[[true, 1, 0, 0, 0.1]]'):
        entry.write_text(head + f'"payload": {damaged}}}')
        parts = cached_parts(V, F, identity=["fork"])
        assert [len(p) for p in parts] == [len(p) for p in first]
        assert entry.read_text() == stored  # rewritten


def test_any_stored_cuts_tile_the_mesh(tmp_path, monkeypatch):
    """Cuts that parse but are not the decomposition's (a foreign entry under the key) still
    give parts that hold every triangle: soundness never rests on the cache."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    mesh = _fork()
    V, F = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    cached_parts(V, F, identity=["fork"])
    (entry,) = (tmp_path / "moik" / "collision").glob("pieces-*.json")
    text = entry.read_text()
    cuts = "[[0, 1, 0, 0, 0.0], [1, 0.3, 0.5, 0.8, 0.1], [0, 0, 0, 1, 5.0], [2, 0, 1, 0, -0.02]]"
    entry.write_text(text[:text.index('"payload"')] + f'"payload": {cuts}}}')
    parts = cached_parts(V, F, identity=["fork"])
    assert len(parts) == 4  # the cut at z = 5 leaves an empty piece out
    points = np.vstack([V, _surface_points(V, F, 4, 0)])
    assert _inside_some(parts, points, 1e-8).all()


def test_use_cache_false_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    mesh = trimesh.creation.box((0.3, 0.1, 0.1))
    cached_parts(np.asarray(mesh.vertices), np.asarray(mesh.faces), identity=["box"],
                 use_cache=False)
    assert not list(tmp_path.rglob("*.json"))


@pytest.mark.parametrize("scale", [1e-3, 1.0, 20.0])
def test_the_cuts_scale_with_the_mesh(scale):
    """The grid is relative to the mesh's size: the same fork at any scale, the same pieces."""
    mesh = _fork()
    V, F = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    base = convex_pieces(V, F)
    scaled = convex_pieces(V * scale, F)
    assert len(scaled) == len(base)


def test_links_decomposed_side_by_side_give_the_same_cuts(monkeypatch):
    """Several links are decomposed in child processes (one per CPU): the cuts are the
    same as one after the other, and a child that cannot start leaves its links to this
    process."""
    fork = _fork()  # three meshes of a second or less each (a mushroom takes five)
    meshes = [(np.asarray(m.vertices) * stretch, np.asarray(m.faces), [name])
              for name, m, stretch in (("fork", fork, 1.0), ("box", MESHES["box"](), 1.0),
                                       ("long fork", fork, np.array([1.0, 1.5, 0.8])))]
    serial = [decompose.decompose(V, F) for V, F, _ in meshes]
    monkeypatch.setattr(mesh_pieces, "PARALLEL_FACES", 0)
    monkeypatch.setattr(mesh_pieces, "_cpus", lambda: 2)
    assert mesh_pieces._decompose_all(meshes) == serial
    monkeypatch.setattr(mesh_pieces, "CHILD", "raise SystemExit(3)")
    assert mesh_pieces._decompose_all(meshes) == serial
