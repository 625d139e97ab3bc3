"""Finding and reading a URDF's mesh files (moik/collision/meshes.py)."""

import os
import sys
from pathlib import Path

import numpy as np
import pytest

import moik
from moik.collision.meshes import binary_stl, package_search, read_mesh, resolve_mesh
from moik.exceptions import GeometryError, MoikError

trimesh = pytest.importorskip("trimesh")


@pytest.fixture
def package(tmp_path, monkeypatch):
    """A folder ``pkgs`` holding the package ``arm_support`` with one box mesh."""
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    mesh = tmp_path / "pkgs" / "arm_support" / "meshes" / "box.stl"
    mesh.parent.mkdir(parents=True)
    trimesh.creation.box(extents=(0.1, 0.2, 0.3)).export(mesh)
    return tmp_path, mesh


def test_package_uri_through_folders_a_mapping_and_ros_package_path(package, monkeypatch):
    root, mesh = package
    uri = "package://arm_support/meshes/box.stl"
    for dirs in ([root / "pkgs"], str(root / "pkgs"), [root / "pkgs" / "arm_support"],
                 {"arm_support": root / "pkgs" / "arm_support"}):
        assert resolve_mesh(uri, link="l", urdf_dir=None, package_dirs=dirs) == mesh
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(root / "pkgs"))
    assert resolve_mesh(uri, link="l", urdf_dir=None) == mesh


def test_a_urdf_inside_its_package_finds_it(package):
    _, mesh = package
    urdf_dir = mesh.parent.parent / "urdf"
    got = resolve_mesh("package://arm_support/meshes/box.stl", link="l", urdf_dir=urdf_dir)
    assert got == mesh


def test_file_uri_absolute_and_relative_paths(package):
    root, mesh = package
    assert resolve_mesh(f"file://{mesh}", link="l", urdf_dir=None) == mesh
    assert resolve_mesh(str(mesh), link="l", urdf_dir=None) == mesh
    assert resolve_mesh("meshes/box.stl", link="l", urdf_dir=mesh.parent.parent) == mesh
    with pytest.raises(GeometryError, match="relative.*given as text"):
        resolve_mesh("meshes/box.stl", link="l", urdf_dir=None)


def test_not_found_names_the_link_the_file_and_where_it_looked(package):
    root, _ = package
    with pytest.raises(GeometryError, match=r"link 'arm'.*package://other/m\.stl.*not found; "
                       r"looked for .*pkgs/other/m\.stl.*package_dirs="):
        resolve_mesh("package://other/m.stl", link="arm", urdf_dir=None,
                      package_dirs=[root / "pkgs"])
    with pytest.raises(GeometryError, match="nowhere"):
        resolve_mesh("package://other/m.stl", link="arm", urdf_dir=None)
    with pytest.raises(GeometryError, match="reads package://, file://"):
        resolve_mesh("http://example.com/m.stl", link="arm", urdf_dir=None)
    with pytest.raises(GeometryError, match="package_dirs must be"):
        package_search(3)


def test_read_applies_scale_and_keeps_the_triangles(package):
    _, mesh = package
    m = read_mesh(mesh, link="l", scale=(2.0, 1.0, 0.5))
    np.testing.assert_allclose(np.ptp(m.vertices, axis=0), [0.2, 0.2, 0.15], atol=1e-12)
    assert m.faces.shape == (12, 3) and m.faces.max() < len(m.vertices)
    assert len(m.digest) == 64


def test_bad_meshes_are_clear_errors(tmp_path):
    missing = tmp_path / "none.stl"
    with pytest.raises(GeometryError, match="cannot be read"):
        read_mesh(missing, link="l")
    garbage = tmp_path / "garbage.stl"
    garbage.write_bytes(b"\x00\x01 not a mesh" * 10)
    with pytest.raises(GeometryError, match="link 'l'.*garbage.stl"):
        read_mesh(garbage, link="l")
    nan = tmp_path / "nan.obj"
    nan.write_text("v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n")
    with pytest.raises(GeometryError, match="non-finite"):
        read_mesh(nan, link="l")
    points = tmp_path / "points.obj"
    points.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n")
    with pytest.raises(GeometryError, match="no triangles"):
        read_mesh(points, link="l")
    box = tmp_path / "box.stl"
    trimesh.creation.box(extents=(100.0, 200.0, 300.0)).export(box)  # millimetres
    with pytest.raises(GeometryError, match=r"300 m across.*scale=\"0.001"):
        read_mesh(box, link="l")
    with pytest.raises(GeometryError, match="scale must be 3 finite non-zero"):
        read_mesh(box, link="l", scale=(0.0, 1.0, 1.0))


def test_without_trimesh_the_error_says_what_to_install(package, monkeypatch, tmp_path):
    """A binary STL is read without trimesh (numpy); any other file needs it."""
    _, mesh = package
    obj = tmp_path / "tri.obj"
    obj.write_text("v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nf 1 2 3\n")
    monkeypatch.setitem(sys.modules, "trimesh", None)
    assert read_mesh(mesh, link="l").faces.shape == (12, 3)
    with pytest.raises(MoikError, match="needs trimesh.*pip install"):
        read_mesh(obj, link="l")


FOLDERS = (Path(moik.__file__).parent, Path(__file__).parents[1] / "data")
STL_FILES = sorted(path for folder in FOLDERS for path in folder.rglob("*")
                   if path.suffix.lower() == ".stl")


def test_binary_stl_gives_the_arrays_trimesh_reads():
    """Every binary STL that moik ships or tests with (its arms' collision meshes): the
    numpy reader's vertices and faces are trimesh's (unprocessed), to the bit."""
    read = 0
    for path in STL_FILES:
        arrays = binary_stl(path.read_bytes())
        if arrays is None:
            continue
        loaded = trimesh.load(str(path), force="mesh", process=False)
        np.testing.assert_array_equal(arrays[0], np.asarray(loaded.vertices, dtype=float))
        np.testing.assert_array_equal(arrays[1], np.asarray(loaded.faces))
        read += 1
    assert read >= 20


def test_an_ascii_or_truncated_stl_is_left_to_trimesh(tmp_path):
    box = trimesh.creation.box(extents=(0.1, 0.2, 0.3))
    text = trimesh.exchange.stl.export_stl_ascii(box).encode()
    data = trimesh.exchange.stl.export_stl(box)
    assert binary_stl(text) is None and binary_stl(data[:-10]) is None
    assert binary_stl(data[:80] + bytes(4)) is None  # no triangle
    ascii_file = tmp_path / "box.stl"
    ascii_file.write_bytes(text)
    np.testing.assert_allclose(np.ptp(read_mesh(ascii_file, link="l").vertices, axis=0),
                               [0.1, 0.2, 0.3])
    truncated = tmp_path / "cut.stl"
    truncated.write_bytes(data[:-10])
    with pytest.raises(GeometryError, match="link 'l'.*cut.stl"):
        read_mesh(truncated, link="l")


def test_a_mesh_path_that_is_not_a_regular_file_is_named_so(tmp_path):
    """A folder (or a FIFO, which would block a read) where a mesh should be: refused as not
    a regular file, not 'not found' (it exists)."""
    (tmp_path / "m").mkdir()
    (tmp_path / "m" / "link.stl").mkdir()
    with pytest.raises(GeometryError, match="not a regular file"):
        resolve_mesh("m/link.stl", link="l1", urdf_dir=tmp_path)
    if hasattr(os, "mkfifo"):
        os.mkfifo(tmp_path / "m" / "pipe.stl")
        with pytest.raises(GeometryError, match="not a regular file"):
            resolve_mesh("m/pipe.stl", link="l1", urdf_dir=tmp_path)
