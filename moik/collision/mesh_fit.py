"""Capsules that enclose a link's collision meshes, fitted at load and cached on disk.

Soundness first: every triangle of every mesh of the link lies inside one of the link's
capsules, so a configuration whose capsules keep a distance ``d`` has meshes at least
``d`` apart. One capsule (:func:`moik.collision.fit.enclosing_capsule`: it contains every
vertex given, hence, being convex, every triangle between them) is fitted to all the
link's vertices; then, up to ``capsules`` per link, the piece with the largest capsule is
split in two at the median of its triangles' centroids along that capsule's axis, each
half keeping *whole* triangles (a triangle's three vertices go to the half its centroid
falls in), and each half gets its own enclosing capsule: a triangle is inside the capsule
of its half, so the union still encloses the mesh. A split is kept only when the two
capsules' volumes add up to less than ``split_gain`` times the one they replace.

The capsules are padded by :data:`PAD` (1 nm) against the rounding of placing them.

Fits are cached in ``$XDG_CACHE_HOME/moik/collision`` (``~/.cache/moik/collision``
when unset; those of the shipped arms also ship in ``moik/collision/data/urdf``, read
first, ``python -m studies.ship_urdf_fits`` writes them) as small JSON files named by
the digest of everything they depend on: the mesh files' bytes (sha256), their scale
and pose on the body, the candidate axes, the settings and :data:`FIT_VERSION`. A file
whose stored digest differs, that cannot be parsed, or whose capsules do not enclose
the triangles (checked at every read, :func:`encloses`) is recomputed and rewritten; an
unwritable cache is not an error.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from moik.collision.fit import capsule_volume, enclosing_capsule

FIT_VERSION = 1  # bump when the fit changes: old cache files are then not read
PAD = 1e-9  # m added to every fitted radius (rounding of placing the capsule)
KEY_DECIMALS = 9  # of the numbers in a key: computed poses differ in their last bits
SHIPPED = Path(__file__).with_name("data") / "urdf"  # fits of the shipped arms, by key


def cache_dir() -> Path:
    """Where fits and allowed-collision matrices are kept."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "moik" / "collision"


def digest(parts: Sequence[Any]) -> str:
    """A hex digest of JSON-able parts and numpy arrays (rounded to :data:`KEY_DECIMALS`)."""
    h = hashlib.sha256()
    for part in parts:
        if isinstance(part, np.ndarray):
            arr = np.ascontiguousarray(np.round(part.astype(float), KEY_DECIMALS) + 0.0)
            h.update(str(arr.shape).encode())
            h.update(arr.tobytes())
        else:
            h.update(json.dumps(part, sort_keys=True).encode())
    return h.hexdigest()[:40]


def load_cached(kind: str, key: str) -> Any | None:
    """The payload stored under ``key`` in the shipped data or the cache, or None
    (absent, damaged, or another key's)."""
    for folder in (SHIPPED, cache_dir()):
        try:
            data = json.loads((folder / f"{kind}-{key}.json").read_text())
        except (OSError, ValueError):
            continue
        if isinstance(data, dict) and data.get("key") == key and "payload" in data:
            return data["payload"]
    return None


def store_cached(kind: str, key: str, payload: Any) -> bool:
    """Write ``payload`` under ``key`` atomically; False when the cache is not writable."""
    path = cache_dir() / f"{kind}-{key}.json"
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(fd, "w") as f:
            json.dump({"key": key, "payload": payload}, f)
        os.replace(tmp, path)
        return True
    except OSError:
        return False


def _capsule(points: np.ndarray, axes: Sequence[np.ndarray]) -> tuple[np.ndarray, np.ndarray,
                                                                       float, float]:
    a, b, r = enclosing_capsule(points, axes)
    return a, b, r, capsule_volume(r, float(np.linalg.norm(b - a)))


def fit_link(vertices: np.ndarray, faces: np.ndarray, *, axes: Sequence[np.ndarray] = (),
             capsules: int = 1, split_gain: float = 0.85) -> list[tuple[np.ndarray, np.ndarray,
                                                                        float]]:
    """Capsules ``(a, b, radius)`` enclosing the triangles ``faces`` of ``vertices``.

    Args:
        vertices: ``(n, 3)`` in the body's frame.
        faces: ``(m, 3)`` vertex indices.
        axes: Candidate axis directions beside the principal axes.
        capsules: Largest number of capsules (>= 1).
        split_gain: A split is kept when its two volumes add up to less than this
            fraction of the volume it replaces.
    """
    pieces = [(faces, *_capsule(vertices[np.unique(faces)], axes))]
    while len(pieces) < capsules:
        k = max(range(len(pieces)), key=lambda i: pieces[i][4])
        F, a, b, r, vol = pieces[k]
        length = float(np.linalg.norm(b - a))
        if length == 0.0 or len(F) < 2:
            break
        u = (b - a) / length
        t = vertices[F].mean(axis=1) @ u
        cut = float(np.median(t))
        lo, hi = F[t <= cut], F[t > cut]
        if len(lo) == 0 or len(hi) == 0:
            break
        halves = [(G, *_capsule(vertices[np.unique(G)], axes)) for G in (lo, hi)]
        if halves[0][4] + halves[1][4] >= split_gain * vol:
            break
        pieces[k:k + 1] = halves
    return [(a, b, r + PAD) for _, a, b, r, _ in pieces]


def encloses(vertices: np.ndarray, faces: np.ndarray,
             fits: Sequence[tuple[np.ndarray, np.ndarray, float]]) -> bool:
    """Whether every triangle has its three vertices inside one of the capsules."""
    inside = np.empty((len(vertices), len(fits)), dtype=bool)
    for k, (a, b, r) in enumerate(fits):
        d = b - a
        L2 = float(d @ d)
        s = np.zeros(len(vertices)) if L2 == 0.0 else np.clip((vertices - a) @ d / L2, 0.0, 1.0)
        inside[:, k] = np.linalg.norm(vertices - (a + s[:, None] * d), axis=1) <= r
    return bool(np.all(inside[faces].all(axis=1).any(axis=1)))


def cached_link_fit(vertices: np.ndarray, faces: np.ndarray, *, identity: Sequence[Any],
                    axes: Sequence[np.ndarray], capsules: int, split_gain: float,
                    use_cache: bool = True) -> list[tuple[np.ndarray, np.ndarray, float]]:
    """:func:`fit_link` read from / written to the disk cache under the digest of
    ``identity`` (the meshes' digests, scales and poses), ``axes`` and the settings."""
    settings = {"version": FIT_VERSION, "capsules": capsules, "split_gain": split_gain,
                "pad": PAD}
    key = digest([settings, *identity, *[np.asarray(x, dtype=float) for x in axes]])
    if use_cache:
        payload = load_cached("fit", key)
        try:
            if payload is not None:
                out = [(np.array(c["a"], dtype=float), np.array(c["b"], dtype=float),
                        float(c["radius"])) for c in payload]
                if out and all(a.shape == (3,) and b.shape == (3,) and np.isfinite(r) and r > 0
                               for a, b, r in out) and encloses(vertices, faces, out):
                    return out
        except (KeyError, TypeError, ValueError):
            pass
    out = fit_link(vertices, faces, axes=axes, capsules=capsules, split_gain=split_gain)
    if use_cache:
        store_cached("fit", key, [{"a": a.tolist(), "b": b.tolist(), "radius": r}
                                  for a, b, r in out])
    return out
