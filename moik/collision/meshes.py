"""The mesh files a URDF's ``<mesh filename=...>`` names, found and read as its package ships them.

Where a reference is looked for (:func:`resolve_mesh`):

* ``package://NAME/rest``: in the package folder ``NAME`` found through ``package_dirs``
  (pinocchio's name and meaning: folders that *hold* package folders, so ``DIR/NAME/rest``;
  a folder that *is* the package, named ``NAME``, counts too; or a ``{NAME: folder}``
  mapping, ``folder/rest``), then through the folders of the ``ROS_PACKAGE_PATH``
  environment variable (the same two rules), then beside the URDF file (its folder and
  the folders above it, for a URDF that sits inside its package);
* ``file:///abs/path`` and absolute paths: as they are;
* any other path: relative to the URDF file's folder.

A reference found nowhere is a :class:`~moik.exceptions.GeometryError` naming the link,
the reference and every folder it was looked for in.

:func:`read_mesh` reads STL, OBJ, PLY and (with pycollada installed) COLLADA ``.dae``
with trimesh (a core dependency: most URDF arms describe their collision geometry as
meshes; trimesh's only required dependency is numpy, and it is imported at the first
mesh read, never by ``import moik``). A binary STL (the usual URDF collision mesh: an
80-byte header, a triangle count, 50 bytes per triangle) is read with numpy instead
(:func:`binary_stl`: the arrays trimesh gives it, tested equal), because importing
trimesh takes most of a second of every collision-aware command. The file's vertices are
checked: at least one triangle, finite coordinates, and after ``scale`` a size between 1
micrometre and 100 m (the unit is metres: a mesh in millimetres without
``scale="0.001 0.001 0.001"`` is refused).
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urlparse

import numpy as np

from moik.exceptions import GeometryError, MoikError

SMALLEST_SIZE = 1e-6  # m: a mesh smaller than a micrometre is a unit mistake
LARGEST_SIZE = 100.0  # m: a robot link larger than 100 m is a unit mistake


@dataclass(frozen=True)
class Mesh:
    """One mesh as read: its vertices ``(n, 3)`` (scaled, in the file's frame, metres),
    triangles ``(m, 3)`` (vertex indices), and the digest of the file's bytes."""

    vertices: np.ndarray
    faces: np.ndarray
    digest: str


def package_search(package_dirs: Any = None) -> tuple[dict[str, Path], list[Path]]:
    """``package_dirs`` as ``({name: package folder}, [folders holding packages])``, with
    the folders of ``ROS_PACKAGE_PATH`` after the given ones.

    Args:
        package_dirs: ``None``, one folder, a sequence of folders, or a mapping
            ``{package name: its folder}``.

    Raises:
        GeometryError: Not one of those.
    """
    named: dict[str, Path] = {}
    folders: list[Path] = []
    if isinstance(package_dirs, Mapping):
        for name, folder in package_dirs.items():
            if not isinstance(name, str) or not isinstance(folder, (str, Path)):
                raise GeometryError("package_dirs as a mapping must be {package name: folder}, "
                                    f"got {name!r}: {folder!r}")
            named[name] = Path(folder).expanduser()
    elif isinstance(package_dirs, (str, Path)):
        folders.append(Path(package_dirs).expanduser())
    elif isinstance(package_dirs, Sequence):
        for folder in package_dirs:
            if not isinstance(folder, (str, Path)):
                raise GeometryError(f"package_dirs must be folders (str or Path), got "
                                    f"{type(folder).__name__}")
            folders.append(Path(folder).expanduser())
    elif package_dirs is not None:
        raise GeometryError("package_dirs must be a folder, a list of folders or a mapping "
                            f"{{package name: folder}}, got {type(package_dirs).__name__}")
    for entry in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep):
        if entry.strip():
            folders.append(Path(entry.strip()).expanduser())
    return named, folders


def resolve_mesh(filename: str, *, link: str, urdf_dir: Path | None,
                 package_dirs: Any = None) -> Path:
    """The file a URDF mesh reference names (see the module doc for where it is looked for).

    Args:
        filename: The ``filename`` attribute as written.
        link: The URDF link the mesh belongs to (for messages).
        urdf_dir: The URDF file's folder (``None`` for a URDF given as text).
        package_dirs: As :func:`package_search` takes it.

    Raises:
        GeometryError: The file is not found; the message lists where it was looked for.
    """
    looked: list[Path] = []
    if filename.startswith("package://"):
        rest = filename[len("package://"):]
        name, _, inner = rest.partition("/")
        if not name or not inner:
            raise GeometryError(f"link {link!r}: mesh reference {filename!r} must be "
                                "package://NAME/path")
        named, folders = package_search(package_dirs)
        candidates = [named[name] / inner] if name in named else []
        for folder in folders:
            candidates.append(folder / name / inner)
            if folder.name == name:
                candidates.append(folder / inner)
        if urdf_dir is not None:
            for up in (urdf_dir, *urdf_dir.parents):
                if up.name == name:
                    candidates.append(up / inner)
        hint = ("pass package_dirs=[a folder holding the folder " f"{name!r}] or "
                f"{{{name!r}: its folder}}, or set ROS_PACKAGE_PATH")
    elif filename.startswith("file://"):
        candidates = [Path(unquote(urlparse(filename).path))]
        hint = "the file:// path must exist"
    elif "://" in filename:
        raise GeometryError(f"link {link!r}: mesh reference {filename!r}: moik reads package://, "
                            "file:// and file paths")
    else:
        path = Path(filename).expanduser()
        if path.is_absolute():
            candidates = [path]
        elif urdf_dir is None:
            raise GeometryError(f"link {link!r}: mesh {filename!r} is relative, but the URDF was "
                                "given as text: give its file path (relative paths are taken "
                                "from the URDF's folder)")
        else:
            candidates = [urdf_dir / path]
        hint = "relative paths are taken from the URDF file's folder"
    for path in candidates:
        looked.append(path)
        if path.is_file():
            return path
        if path.exists():  # a folder, a FIFO, a device: never opened (a FIFO would block)
            raise GeometryError(f"link {link!r}: mesh {filename!r} is {str(path)!r}, which is "
                                "not a regular file (a folder, FIFO or device)")
    where = ", ".join(str(os.path.normpath(p)) for p in looked)
    if not where:
        where = ("nowhere: package_dirs names no package of that name" if package_dirs
                 else "nowhere (no package folder given)")
    raise GeometryError(f"link {link!r}: mesh {filename!r} not found; looked for {where}; {hint}")


def _trimesh() -> Any:
    try:
        import trimesh
    except ImportError:
        raise MoikError("reading a URDF's meshes needs trimesh (a dependency of moik): "
                        "pip install 'trimesh>=4' (and pycollada for .dae files)") from None
    return trimesh


STL_TRIANGLE = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)),
                         ("attribute", "<u2")])  # one binary STL record (50 bytes)


def binary_stl(data: bytes) -> tuple[np.ndarray, np.ndarray] | None:
    """The vertices ``(3 n, 3)`` and faces ``(n, 3)`` of a binary STL file's bytes, as
    trimesh reads them without processing (each triangle's corners in order, none merged),
    or None when ``data`` is not exactly an 80-byte header, a count ``n >= 1`` and ``n``
    records (an ASCII STL, a damaged file: left to trimesh)."""
    if len(data) < 84:
        return None
    n = int(np.frombuffer(data, dtype="<u4", count=1, offset=80)[0])
    if n == 0 or len(data) != 84 + n * STL_TRIANGLE.itemsize:
        return None
    records = np.frombuffer(data, dtype=STL_TRIANGLE, count=n, offset=84)
    vertices = records["corners"].reshape(-1, 3).astype(np.float64)
    return vertices, np.arange(3 * n, dtype=np.int64).reshape(-1, 3)


def _trimesh_arrays(path: Path, what: str) -> tuple[np.ndarray, np.ndarray]:
    """The vertices and faces trimesh reads from ``path`` (unprocessed)."""
    trimesh = _trimesh()
    try:
        loaded = trimesh.load(str(path), force="mesh", process=False)
    except OSError as exc:
        raise GeometryError(f"{what} cannot be read: {exc}") from None
    except Exception as exc:  # trimesh raises many kinds on a damaged or foreign file
        dae = path.suffix.lower() == ".dae"
        hint = " (COLLADA needs pycollada: pip install pycollada)" if dae else ""
        raise GeometryError(f"{what} cannot be read as a mesh{hint}: "
                            f"{type(exc).__name__}: {exc}") from None
    if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0:
        raise GeometryError(f"{what} holds no triangles")
    return (np.asarray(loaded.vertices, dtype=float),
            np.asarray(loaded.faces, dtype=np.int64))


def read_mesh(path: Path, *, link: str, scale: Any = (1.0, 1.0, 1.0)) -> Mesh:
    """A mesh file's triangles, scaled and checked (see the module doc).

    Raises:
        GeometryError: Unreadable file, no triangles, non-finite vertices, or a size
            (after ``scale``) outside [1 um, 100 m].
        MoikError: trimesh is not installed.
    """
    what = f"link {link!r}: mesh {str(path)!r}"
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise GeometryError(f"{what} cannot be read: {exc}") from None
    digest = hashlib.sha256(data).hexdigest()  # the mesh's identity in the fit cache
    stl = binary_stl(data) if path.suffix.lower() == ".stl" else None
    if stl is None:
        V, faces = _trimesh_arrays(path, what)
    else:
        V, faces = stl
    with np.errstate(all="ignore"):
        s = np.asarray(scale, dtype=float)
        if not np.all(np.isfinite(V)):
            raise GeometryError(f"{what} has non-finite (NaN or infinite) vertices")
        if s.shape != (3,) or not np.all(np.isfinite(s)) or np.any(s == 0.0):
            raise GeometryError(f"{what}: scale must be 3 finite non-zero numbers, got {s}")
        V = V[np.unique(faces)] if faces.size else V
        faces = np.searchsorted(np.unique(faces), faces)
        V = V * s
    size = float(np.ptp(V, axis=0).max()) if len(V) else 0.0
    if not SMALLEST_SIZE <= size <= LARGEST_SIZE:
        hint = ("a URDF's unit is the metre; a mesh in millimetres needs "
                "scale=\"0.001 0.001 0.001\"" if size > LARGEST_SIZE else
                "its triangles have no extent (a point), or the scale is too small")
        raise GeometryError(f"{what} is {size:.3g} m across after scale {s.tolist()}: expected "
                            f"{SMALLEST_SIZE:g} to {LARGEST_SIZE:g} m ({hint})")
    V.flags.writeable = False
    faces.flags.writeable = False
    return Mesh(vertices=V, faces=faces, digest=digest)
