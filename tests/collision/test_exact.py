"""The exact stage on convex hulls (moik/collision/exact.py): sound and tighter than the
capsules, against coal on the meshes of an arm moik does not ship."""

from pathlib import Path

import numpy as np
import pytest

from moik import load_urdf
from moik.collision import Box, CollisionChecker, HalfSpace, Scene
from moik.collision.exact import ExactStage, hull_pieces
from moik.collision.meshes import read_mesh, resolve_mesh
from moik.collision.urdf import robot_model
from moik.robots.urdf_geometry import mesh_geometry

coal = pytest.importorskip("coal")
DATA = Path(__file__).resolve().parents[1] / "data" / "urdf"


def test_hull_pieces_enclose_every_triangle():
    trimesh = pytest.importorskip("trimesh")
    m = trimesh.creation.annulus(r_min=0.05, r_max=0.08, height=0.3)
    V = np.asarray(m.vertices) + np.random.default_rng(0).normal(0, 1e-3, m.vertices.shape)
    F = np.asarray(m.faces)  # (the noise: no flat piece, which Delaunay could not take)
    pieces = hull_pieces(V, F, 5)
    assert len(pieces) == 5
    # every triangle's vertices are all among one piece's hull's points (or inside it)
    from scipy.spatial import Delaunay

    inside = np.array([Delaunay(P).find_simplex(V, tol=1e-12) >= 0 for P in pieces]).T
    assert np.all(inside[F].all(axis=1).any(axis=1))


def _meshes(urdf, robot):
    _, items = mesh_geometry(urdf, robot)
    out = {}
    for item in items:
        path = resolve_mesh(item["filename"], link=item["link"], urdf_dir=urdf.parent,
                            package_dirs=[DATA / "packages"])
        mesh = read_mesh(path, link=item["link"], scale=item["scale"])
        bvh = coal.BVHModelOBBRSS()
        bvh.beginModel(len(mesh.faces), len(mesh.vertices))
        bvh.addVertices(mesh.vertices @ item["pose"][:3, :3].T + item["pose"][:3, 3])
        bvh.addTriangles(np.ascontiguousarray(mesh.faces))
        bvh.endModel()
        out.setdefault(item["body"], []).append(bvh)
    return out


def test_sound_and_tighter_than_the_capsules_on_the_ur10():
    urdf = DATA / "ur10_robot.urdf"
    robot = load_urdf(urdf, tip_link="tool0", package_dirs=[DATA / "packages"])
    checker = CollisionChecker(model=robot_model(robot))
    Q = robot.random_q(150, rng=np.random.default_rng(7))
    exact = ExactStage(checker).min_distance(Q) >= 0.0
    capsules = checker.min_distance(Q) >= 0.0
    meshes = _meshes(urdf, robot)
    touch = np.zeros(len(Q), dtype=bool)
    for k, q in enumerate(Q):
        F = robot.frames(q)
        tf = {b: coal.Transform3s(F[b][:3, :3], F[b][:3, 3]) for b in meshes}
        touch[k] = any(coal.collide(a, tf[i], b, tf[j], coal.CollisionRequest(),
                                    coal.CollisionResult())
                       for i in meshes for j in meshes if j > i + 1
                       for a in meshes[i] for b in meshes[j])
    assert touch.any() and not np.any(exact & touch) and not np.any(capsules & touch)
    assert np.all(exact >= capsules)  # the exact stage only accepts more
    assert (~exact & ~touch).sum() < (~capsules & ~touch).sum()


def test_obstacles_are_measured_on_the_hulls_too():
    urdf = DATA / "kr16_2.urdf"
    robot = load_urdf(urdf, tip_link="tool0", package_dirs=[DATA / "packages"])
    scene = Scene({"floor": HalfSpace.plane([0, 0, 1], -0.02),
                   "post": Box(size=[0.1, 0.1, 2.0], pose=np.eye(4) + _at(0.9, 0.0, 1.0))},
                  allowed={("floor", "base_link")})
    checker = CollisionChecker(model=robot_model(robot), scene=scene, self_collision=False)
    Q = robot.random_q(50, rng=np.random.default_rng(1))
    D = ExactStage(checker).distances(Q, below=np.inf)
    assert np.all(checker.distances(Q) - 1e-12 <= D)


def _at(x, y, z):
    T = np.zeros((4, 4))
    T[:3, 3] = [x, y, z]
    return T


def test_every_entry_is_a_lower_bound_of_the_mesh_distance():
    urdf = DATA / "ur10_robot.urdf"
    robot = load_urdf(urdf, tip_link="tool0", package_dirs=[DATA / "packages"])
    checker = CollisionChecker(model=robot_model(robot))
    meshes = _meshes(urdf, robot)
    Q = robot.random_q(30, rng=np.random.default_rng(11))
    for below in (0.0, 0.05, np.inf):
        D = ExactStage(checker).distances(Q, below=below)
        for i, q in enumerate(Q):
            F = robot.frames(q)
            tf = {b: coal.Transform3s(F[b][:3, :3], F[b][:3, 3]) for b in meshes}
            for a, b in set(checker.pair_bodies):  # the smallest over the body pair's shapes
                # (ur10's wrist_3 also has a primitive box, ee_link's, not among the meshes)
                ours = min(D[i, k] for k, p in enumerate(checker.pair_bodies) if p == (a, b))
                d = min(coal.distance(x, tf[a], y, tf[b], coal.DistanceRequest(),
                                      coal.DistanceResult())
                        for x in meshes[a] for y in meshes[b])
                assert ours <= max(d, 0.0) + 1e-9
