"""The convex parts of a mesh link, its decomposition cached on disk with the fits.

:func:`cached_parts` gives the vertices of the convex parts of a link's compound: the
pieces of its triangles (:mod:`moik.collision.decompose`), each piece's hull, or the
enclosing polytope that replaces a hull of more than
:data:`~moik.collision.outer_hull.MAX_EXACT_VERTICES` vertices
(:func:`moik.collision.outer_hull.enclosing_polytope`). The decomposition takes a second or
more on a detailed link, so its cuts are cached (:func:`moik.collision.mesh_fit.load_cached`:
the shipped arms' in moik's data, others in the user's cache), keyed by the meshes (their
digests, scales and poses) and every setting. Any list of cuts tiles the mesh, so a read
entry is sound whatever file it came from; one that is not a list of cuts (damaged,
foreign) is recomputed and rewritten. An arm's links missing from the cache are decomposed
side by side, one child process per CPU (:func:`parts_of_meshes`): the same cuts, sooner
(measured on example-robot-data's Z1, 16,000-56,000 triangles per link, 2 CPUs: 143 s
one after the other, 101-117 s side by side; its largest link alone takes most of it).
"""

from __future__ import annotations

import contextlib
import os
import pickle
import subprocess
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from moik.collision import decompose
from moik.collision.mesh_fit import digest, load_cached, store_cached
from moik.collision.outer_hull import enclosing_polytope

PIECES_VERSION = 4  # bump when the decomposition changes: old cache entries are not read


def _read(payload: Any) -> list[decompose.Cut] | None:
    """The cuts stored as ``[[piece, nx, ny, nz, offset], ...]``, or None when it is not
    that (finite numbers, a non-zero normal, a piece that exists when it is cut)."""
    if not isinstance(payload, list):
        return None
    cuts: list[decompose.Cut] = []
    for k, row in enumerate(payload):
        if (not isinstance(row, list) or len(row) != 5 or type(row[0]) is not int
                or not 0 <= row[0] <= k
                or not all(isinstance(x, (int, float)) and np.isfinite(x) for x in row[1:])):
            return None
        normal = (float(row[1]), float(row[2]), float(row[3]))
        if not any(normal):
            return None
        cuts.append((row[0], normal, float(row[4])))
    return cuts


PARALLEL_FACES = 20_000  # triangles to decompose before the links share the CPUs
Mesh = tuple[np.ndarray, np.ndarray, Sequence[Any]]  # vertices, faces, identity


def _cpus() -> int:
    """The CPUs this process may run on (as :func:`moik._machine.available_cores`, which the
    design's dependency direction keeps out of the collision package's reach)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # macOS, Windows
        return os.cpu_count() or 1


def _key(identity: Sequence[Any]) -> str:
    settings = {"version": PIECES_VERSION, "resolution": decompose.RESOLUTION,
                "max_resolution": decompose.MAX_RESOLUTION, "fine_pitch": decompose.FINE_PITCH,
                "slabs": decompose.SLABS, "elongated": decompose.ELONGATED,
                "tolerance_cells": decompose.TOLERANCE_CELLS,
                "max_pieces": decompose.MAX_PIECES, "quantiles": list(decompose.QUANTILES),
                "max_empty": decompose.MAX_EMPTY}
    return digest([settings, *identity])


CHILD = "from moik.collision.mesh_pieces import child; child()"


def child() -> None:
    """A child of :func:`_decompose_all`: the cuts of the meshes pickled on stdin, pickled
    on stdout."""
    meshes = pickle.loads(sys.stdin.buffer.read())
    sys.stdout.buffer.write(pickle.dumps([decompose.decompose(V, F) for V, F in meshes]))


def _start_child() -> subprocess.Popen | None:
    """A :func:`child` of the moik this process imported (run from its folder: another moik
    in the working folder would come first on its path), or None."""
    root = str(Path(__file__).resolve().parents[2])
    env = {**os.environ,
           "PYTHONPATH": os.pathsep.join(p for p in (root, os.environ.get("PYTHONPATH")) if p)}
    try:
        return subprocess.Popen([sys.executable, "-c", CHILD], stdin=subprocess.PIPE,
                                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env,
                                cwd=root)
    except (OSError, ValueError):
        return None


def _decompose_all(meshes: Sequence[Mesh]) -> list[list[decompose.Cut]]:
    """The cuts of each mesh: side by side in child processes (:func:`child`) when there
    are several large ones and several CPUs (a link's decomposition is independent of the
    others'), else one after the other; the same cuts either way. What a child does not
    deliver (it cannot start, fails) is computed here."""
    done: dict[int, list[decompose.Cut]] = {}
    workers = min(len(meshes), _cpus())
    if workers > 1 and sum(len(F) for _, F, _ in meshes) >= PARALLEL_FACES:
        shares: list[list[int]] = [[] for _ in range(workers)]  # the largest first, each
        loads = [0] * workers  # to the share with the fewest triangles so far
        for i in sorted(range(len(meshes)), key=lambda i: -len(meshes[i][1])):
            w = loads.index(min(loads))
            shares[w].append(i)
            loads[w] += len(meshes[i][1])
        children = [(share, p) for share in shares[1:]  # the first share is ours
                    if (p := _start_child()) is not None]
        for share, process in children:
            with contextlib.suppress(OSError, ValueError):
                assert process.stdin is not None
                process.stdin.write(pickle.dumps([meshes[i][:2] for i in share]))
                process.stdin.close()
        for i in shares[0]:
            done[i] = decompose.decompose(*meshes[i][:2])
        for share, process in children:
            with contextlib.suppress(Exception):  # noqa: BLE001 - computed below instead
                assert process.stdout is not None
                result = pickle.loads(process.stdout.read())
                if process.wait() == 0 and len(result) == len(share):
                    done.update(zip(share, result, strict=True))
            if process.poll() is None:
                process.kill()
            process.wait()
    return [done[i] if i in done else decompose.decompose(V, F)
            for i, (V, F, _) in enumerate(meshes)]


def parts_of_meshes(meshes: Sequence[Mesh], *, use_cache: bool = True) -> list[list[np.ndarray]]:
    """:func:`cached_parts` of each ``(vertices, faces, identity)``; the meshes whose cuts
    are not cached are decomposed side by side (:func:`_decompose_all`)."""
    keys = [_key(identity) for _, _, identity in meshes]
    cuts = [_read(load_cached("pieces", key)) if use_cache else None for key in keys]
    missing = [i for i, c in enumerate(cuts) if c is None]
    for i, new in zip(missing, _decompose_all([meshes[i] for i in missing]), strict=True):
        cuts[i] = new
        if use_cache:
            store_cached("pieces", keys[i], [[k, *normal, offset] for k, normal, offset in new])
    out = []
    for (V, F, _), c in zip(meshes, cuts, strict=True):
        assert c is not None
        pieces = decompose.apply_cuts(V, F, c)
        out.append([np.ascontiguousarray(enclosing_polytope(p.points())) for p in pieces])
    return out


def cached_parts(vertices: np.ndarray, faces: np.ndarray, *, identity: Sequence[Any],
                 use_cache: bool = True) -> list[np.ndarray]:
    """The vertices of the convex parts of the mesh ``vertices``, ``faces`` (module
    docstring); its cuts read from / written to the disk cache under the digest of
    ``identity`` (the meshes' digests, scales and poses) and the settings."""
    return parts_of_meshes([(vertices, faces, identity)], use_cache=use_cache)[0]

