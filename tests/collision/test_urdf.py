"""URDF <collision> primitives on the loaded chain's bodies (moik/collision/urdf.py and
moik/robots/urdf_geometry.py)."""

from pathlib import Path

import numpy as np
import pytest

import moik
from moik import load_urdf, solve_ik
from moik.collision import Box, Capsule, CollisionChecker, Scene, Sphere
from moik.collision.meshes import read_mesh, resolve_mesh
from moik.collision.shapes import Compound
from moik.collision.urdf import model_from_urdf, robot_model
from moik.exceptions import GeometryError, URDFError
from moik.robots.urdf_geometry import mesh_geometry

URDF = """<robot name="two">
  <link name="base"><collision><origin xyz="0 0 0.05"/><geometry><box size="0.2 0.2 0.1"/>
    </geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.25" rpy="0 0 0"/><geometry>
    <cylinder radius="0.04" length="0.5"/></geometry></collision></link>
  <link name="fore"><collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.05"/>
    </geometry></collision>
    <collision><geometry><mesh filename="package://x/fore.stl"/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 1 0"/><limit lower="-2" upper="2"/></joint>
  <joint name="j2" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.5" rpy="0 1.5707963267948966 0"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2"/></joint>
</robot>"""


PRIMITIVES = URDF.replace(
    '<collision><geometry><mesh filename="package://x/fore.stl"/></geometry></collision>', "")


def test_primitives_on_the_bodies():
    robot = load_urdf(PRIMITIVES)
    model = model_from_urdf(PRIMITIVES, robot, samples=0)
    assert model.links == ("base", "upper", "fore")
    assert isinstance(model.shapes["base"][0], Box)
    upper = model.shapes["upper"][0]  # the cylinder: a prism in its enclosing capsule
    assert isinstance(upper, Compound) and isinstance(upper.bound, Capsule)
    assert (upper.bound.radius, upper.bound.length) == (0.04, 0.5)
    assert isinstance(model.shapes["fore"][0], Sphere)
    checker = CollisionChecker(model=model, self_collision=True)
    for q in ([0.0, 0.0], [0.7, -1.1]):
        placed = dict(checker.world_shapes(np.array(q)))
        # by hand: base -> j1 at z 0.1 rotating about y; j2 0.5 above, pitched by pi/2
        c1, s1 = np.cos(q[0]), np.sin(q[0])
        Ry1 = np.array([[c1, 0, s1], [0, 1, 0], [-s1, 0, c1]])
        p_upper = np.array([0, 0, 0.1]) + Ry1 @ [0, 0, 0.25]
        np.testing.assert_allclose(placed["upper"].pose[:3, 3], p_upper, atol=1e-12)
        a = q[1] + np.pi / 2
        Ry2 = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
        p_fore = np.array([0, 0, 0.1]) + Ry1 @ ([0, 0, 0.5] + Ry2 @ [0.2, 0, 0])
        np.testing.assert_allclose(placed["fore"].pose[:3, 3], p_fore, atol=1e-12)
    assert checker.n_pairs == 1  # base and fore (upper is adjacent to both)


WRIST = """<robot name="wrist">
  <link name="base"/>
  <link name="a"><collision><origin xyz="0 0 0.025"/><geometry>
    <cylinder radius="0.0325" length="0.05"/></geometry></collision></link>
  <link name="b"/>
  <link name="c"><collision><origin xyz="0 0 0.025"/><geometry>
    <cylinder radius="0.0325" length="0.05"/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/>
    <axis xyz="0 0 1"/><limit lower="-2" upper="2"/></joint>
  <joint name="j2" type="revolute"><parent link="a"/><child link="b"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 0 1"/><limit lower="-2" upper="2"/></joint>
  <joint name="j3" type="revolute"><parent link="b"/><child link="c"/>
    <origin xyz="0 0 0.015"/><axis xyz="0 0 1"/><limit lower="-2" upper="2"/></joint>
</robot>"""


def test_cylinders_end_to_end_are_measured_on_their_prisms():
    """A wrist's two cylinders facing each other 15 mm apart, a link without geometry
    between them (a Unitree Z1): the pair is checked and 15 mm apart in every
    configuration; their enclosing capsules alone would overlap by 50 mm in all of them."""
    robot = load_urdf(WRIST)
    model = model_from_urdf(WRIST, robot, samples=0, missing="ignore")
    checker = CollisionChecker(model=model, self_collision=True)
    assert checker.pair_names == (("a", "c"),)
    Q = robot.random_q(50, rng=np.random.default_rng(0))
    np.testing.assert_allclose(checker.min_distance(Q), 0.015, atol=1e-9)


def test_not_this_robots_urdf():
    other = load_urdf(URDF.replace('"j1"', '"k1"').replace('"j2"', '"k2"'))
    with pytest.raises(URDFError, match="has no joints"):
        model_from_urdf(URDF, other)


def test_an_unresolvable_mesh_names_link_file_and_folders(tmp_path):
    path = tmp_path / "two.urdf"
    path.write_text(URDF)
    (tmp_path / "pkgs").mkdir()  # a package folder without package x
    robot = load_urdf(path, package_dirs=[tmp_path / "pkgs"])
    with pytest.raises(GeometryError, match=r"link 'fore'.*package://x/fore\.stl.*not found.*"
                       r"pkgs/x/fore\.stl"):
        model_from_urdf(path, robot, package_dirs=[tmp_path / "pkgs"])


def test_a_body_without_geometry_is_an_error_or_an_explicit_choice():
    bare = PRIMITIVES.replace('<collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.05"/>'
                              '\n    </geometry></collision>', "")
    robot = load_urdf(bare)
    with pytest.raises(GeometryError, match=r"bodies \['fore'\] have no <collision>.*"
                       "missing='ignore'"):
        model_from_urdf(bare, robot, samples=0)
    model = model_from_urdf(bare, robot, samples=0, missing="ignore")
    assert "fore" not in model.shapes and "NOT checked: fore" in model.source
    assert model.unchecked_links == ("fore",)
    far = np.eye(4)
    far[:3, 3] = (2.0, 2.0, 2.0)
    scene = Scene({"ball": Sphere(radius=0.05, pose=far)})
    res = solve_ik(robot, robot.fk(np.array([0.3, 0.4])), scene=scene, collision=model)
    assert res.status == "solved" and res.unchecked_links == ("fore",)  # the result says so
    batch = moik.solve_ik_batch(robot, robot.fk(np.array([[0.3, 0.4]])), scene=scene,
                                collision=model)
    assert batch.unchecked_links == ("fore",)
    whole = load_urdf(PRIMITIVES)
    assert solve_ik(whole, whole.fk(np.array([0.3, 0.4])), scene=scene).unchecked_links == ()


DATA = Path(__file__).resolve().parents[1] / "data" / "urdf"
SHIPPED = Path(moik.__file__).parent / "robots" / "data"


def test_the_model_of_the_meshes_is_sound_against_coal():
    """iiwa14 as its URDF package ships it: free by the model means the meshes do not
    touch, in every pair of non-neighbouring bodies (the pairs the model allows too)."""
    from tests.coal_oracle import coal

    robot = load_urdf(SHIPPED / "lbr_iiwa_14_r820.urdf", tip_link="tool0",
                      package_dirs=[SHIPPED / "packages"])
    model = robot_model(robot)
    assert set(model.shapes) == set(model.links) and "NOT checked" not in model.source
    _, items = mesh_geometry(SHIPPED / "lbr_iiwa_14_r820.urdf", robot)
    meshes = {}
    for item in items:
        path = resolve_mesh(item["filename"], link=item["link"], urdf_dir=SHIPPED,
                            package_dirs=[SHIPPED / "packages"])
        mesh = read_mesh(path, link=item["link"], scale=item["scale"])
        bvh = coal.BVHModelOBBRSS()
        bvh.beginModel(len(mesh.faces), len(mesh.vertices))
        bvh.addVertices(mesh.vertices @ item["pose"][:3, :3].T + item["pose"][:3, 3])
        bvh.addTriangles(np.ascontiguousarray(mesh.faces))
        bvh.endModel()
        meshes[item["body"]] = bvh
    # configurations near the self-collisions of the wrist: joints 4 and 6 folded
    rng = np.random.default_rng(3)
    Q = robot.random_q(300, rng=rng)
    Q[:, 3] = np.sign(Q[:, 3]) * rng.uniform(1.6, 2.09, len(Q))
    free = CollisionChecker(model=model, self_collision=True).min_distance(Q) >= 0.0
    touching = 0
    for q, ok in zip(Q, free, strict=True):
        F = robot.frames(q)
        tf = {b: coal.Transform3s(F[b][:3, :3], F[b][:3, 3]) for b in meshes}
        touch = any(coal.collide(meshes[i], tf[i], meshes[j], tf[j], coal.CollisionRequest(),
                                 coal.CollisionResult())
                    for i in meshes for j in meshes if j > i + 1)
        touching += touch
        assert not (ok and touch)
    assert touching > 0  # the check saw touching meshes


def test_solve_ik_uses_the_urdf_geometry_without_another_step():
    robot = load_urdf(DATA / "kr16_2.urdf", tip_link="tool0", package_dirs=[DATA / "packages"])
    q = np.array([0.2, -0.9, 1.6, 0.3, 0.8, 0.1])
    T = robot.fk(q)
    free = solve_ik(robot, T, self_collision=True, seed=1)
    assert free.status == "solved" and 0.0 <= free.min_distance < np.inf
    slab = Scene({"slab": Box(size=[4.0, 4.0, 0.05], pose=np.eye(4) + _lift(0.45))})
    blocked = solve_ik(robot, T, scene=slab, self_collision=True, seed=1)
    assert blocked.status == "collides"


def _lift(z):
    T = np.zeros((4, 4))
    T[2, 3] = z
    return T


def test_nothing_to_check_is_an_error():
    """The two-link arm's only non-neighbouring pair (base, fore) never collides: the
    sampled matrix allows it, and a self-collision check would check nothing."""
    robot = load_urdf(PRIMITIVES)
    assert robot_model(robot).checked_body_pairs() == []
    with pytest.raises(GeometryError, match="nothing to check.*every pair allowed"):
        solve_ik(robot, robot.fk(np.zeros(2)), self_collision=True)


def test_the_shipped_arms_fits_ship(tmp_path, monkeypatch):
    """The fits and matrices of the catalog's URDF arms are found in moik's data (an empty
    cache stays empty); when this fails, run `python -m studies.ship_urdf_fits`."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    for name in ("panda", "ur5", "iiwa14"):
        model = robot_model(moik.get_robot(name))
        assert model.allowed and set(model.shapes) <= set(model.links)
    robot_model(moik.get_robot("panda"), joint_values={"panda_finger_joint1": 0.04})
    assert not list(tmp_path.rglob("*.json"))


def test_links_fixed_to_a_body_are_named_as_that_body():
    """A URDF link joined by a fixed joint (a mount plate under the base, a tool flange) is
    accepted wherever a link is named, as the body it is on: a scene's allowed pair naming
    it skips the same pairs as one naming the body."""
    fixed = PRIMITIVES.replace('<link name="base">', '<link name="plate"/>\n  <link name="base">'
                               ).replace('<joint name="j1"', '<joint name="mount" type="fixed">'
                                         '<parent link="plate"/><child link="base"/></joint>\n'
                                         '  <joint name="j1"')
    robot = load_urdf(fixed)
    model = model_from_urdf(fixed, robot, samples=0)
    assert model.links[0] == "plate" and model.body_name("base") == "plate"
    table = Box(size=(1.0, 1.0, 0.1), pose=np.eye(4))
    by_alias = CollisionChecker(model=model, scene=Scene({"t": table}, allowed={("t", "base")}))
    by_body = CollisionChecker(model=model, scene=Scene({"t": table}, allowed={("t", "plate")}))
    assert by_alias.pair_names == by_body.pair_names
    assert len(by_alias.pair_names) == len(CollisionChecker(
        model=model, scene=Scene({"t": table})).pair_names) - 1
    with pytest.raises(moik.exceptions.UnknownNameError, match="'base_link'.*base"):
        CollisionChecker(model=model, scene=Scene({"t": table}, allowed={("t", "base_link")}))


def test_an_allowed_link_fixed_to_a_body_skips_only_its_own_shapes():
    """Before: a scene's allowed pair naming ur10's ee_link (a 1 cm box fixed to wrist_3_link)
    skipped every shape of wrist_3_link against that obstacle, its own mesh too (a probe's
    part 7 mm into the wrist's mesh was called 1.7 mm clear)."""
    robot = load_urdf(DATA / "ur10_robot.urdf", tip_link="tool0", package_dirs=[DATA / "packages"])
    model = robot_model(robot)
    body = model.body_name("ee_link")
    assert body == "wrist_3_link" and set(model.origins[body]) == {"ee_link", "wrist_3_link"}
    part = Box(size=(0.02, 0.02, 0.02), pose=np.eye(4))

    def checked(allowed):
        names = CollisionChecker(model=model, scene=Scene({"part": part}, allowed=allowed)
                                 ).pair_names
        return sorted(a for a, b in names if b == "part" and a.startswith(body))

    everything = checked(set())
    own = [n for n, o in zip(everything, model.origins[body], strict=True) if o == "ee_link"]
    assert len(everything) == 2 and len(own) == 1
    assert checked({("part", "ee_link")}) == sorted(set(everything) - set(own))
    assert checked({("part", body)}) == []  # the body named: every shape on it
    with pytest.raises(GeometryError, match="'ee_link' is fixed to 'wrist_3_link'.*name "
                                            "'wrist_3_link' to allow the whole body"):
        model.with_allowed([("ee_link", "forearm_link")])
    assert model.with_allowed([(body, "forearm_link")]).allowed >= {
        frozenset((body, "forearm_link"))}


def test_a_mesh_in_millimetres_of_a_small_link_is_refused():
    """Before: ur10's wrist mesh at scale 1000 (90 m across, under the 100 m bound) was fitted
    as a 46 m capsule and the solve said "solved": the link practically unchecked."""
    text = (DATA / "ur10_robot.urdf").read_text()
    mesh = 'collision/wrist3.stl"/>'
    assert text.count(mesh) == 1
    robot = load_urdf(text.replace(mesh, 'collision/wrist3.stl" scale="1000 1000 1000"/>'),
                      tip_link="tool0", package_dirs=[DATA / "packages"])
    with pytest.raises(GeometryError, match=r"link 'wrist_3_link': mesh .*wrist3.stl' is 90.* m "
                                            r"across .* more than 10x the arm's reach"):
        robot_model(robot)


@pytest.mark.parametrize(("old", "new", "match"), [
    ('<box size="0.2 0.2 0.1"/>', '<box size="1e300 0.2 0.1"/>',
     r"<box> of link 'base': size must be in \(0, 100\] m"),
    ('<box size="0.2 0.2 0.1"/>', '<box size="0.2 -0.2 0.1"/>', "<box> of link 'base'"),
    ('<sphere radius="0.05"/>', '<sphere radius="nan"/>',
     "<sphere> of link 'fore' needs a finite radius="),
    ('<cylinder radius="0.04" length="0.5"/>', '<cylinder radius="0.04"/>',
     "<cylinder> of link 'upper' needs a finite length="),
])
def test_a_bad_primitive_names_its_link(old, new, match):
    """A URDF primitive of no size, a negative or absurd one (a unit mistake: the URDF's
    unit is the metre, as for meshes) is refused, naming the link, never an overflow."""
    bad = PRIMITIVES.replace(old, new)
    with pytest.raises(GeometryError, match=match):
        model_from_urdf(bad, load_urdf(bad), samples=0)


def test_a_high_poly_mesh_is_measured_soundly_and_tightly(tmp_path):
    """A link whose collision mesh is a 5,120-face ellipsoid (its pieces' hulls have more than
    128 vertices, so they become enclosing polytopes): the distance to a ball is never
    above coal's on the mesh itself, and at most 1 mm below it."""
    import trimesh
    from scipy.spatial import ConvexHull

    from moik.collision.decompose import convex_pieces
    from moik.collision.outer_hull import MAX_EXACT_VERTICES
    from tests.coal_oracle import coal

    ellipsoid = trimesh.creation.icosphere(subdivisions=4)
    ellipsoid.vertices *= [0.05, 0.06, 0.2]
    ellipsoid.vertices[:, 2] += 0.25
    ellipsoid.export(tmp_path / "fore.stl")
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(URDF.replace("package://x/fore.stl", "fore.stl").replace(
        '<collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.05"/>\n    </geometry>'
        '</collision>', ""))
    robot = load_urdf(urdf)
    (item,) = mesh_geometry(urdf, robot)[1]
    mesh = read_mesh(tmp_path / "fore.stl", link="fore", scale=np.ones(3))
    pieces = convex_pieces(mesh.vertices, mesh.faces)
    assert max(len(ConvexHull(P).vertices) for P in pieces) > MAX_EXACT_VERTICES
    rng = np.random.default_rng(5)
    balls = {f"b{k}": Sphere(radius=0.03, pose=np.block([[np.eye(3), rng.uniform(
        [-0.1, -0.3, 0.2], [0.9, 0.3, 1.0])[:, None]], [np.zeros((1, 3)), np.ones((1, 1))]]))
        for k in range(6)}
    checker = CollisionChecker(model=model_from_urdf(urdf, robot, samples=0),
                               scene=Scene(balls))
    fore = [k for k, (a, _) in enumerate(checker.pair_names) if a == "fore"]
    bvh = coal.BVHModelOBBRSS()
    bvh.beginModel(len(mesh.faces), len(mesh.vertices))
    bvh.addVertices(np.ascontiguousarray(mesh.vertices))
    bvh.addTriangles(np.ascontiguousarray(mesh.faces))
    bvh.endModel()
    gaps = []
    for q in robot.random_q(60, rng=rng):
        D = checker.distances(q)
        F = robot.frames(q)[item["body"]] @ item["pose"]
        for k in fore:
            ball = balls[checker.pair_names[k][1]]
            res = coal.DistanceResult()
            d = coal.distance(bvh, coal.Transform3s(F[:3, :3], F[:3, 3]),
                              coal.Sphere(0.03), coal.Transform3s(np.eye(3), ball.pose[:3, 3]),
                              coal.DistanceRequest(), res)
            if d > 0:
                gaps.append(d - D[k])
    assert len(gaps) > 100 and min(gaps) >= -1e-9 and max(gaps) <= 1e-3
