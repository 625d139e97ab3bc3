"""Build the capsule models shipped in moik/collision/data (run: python -m studies.fit_capsules).

Three sources (moik/collision/data/README.md records which one each file uses):

* ``panda``: Franka Emika's own self-collision capsules, published in franka_ros
  (``franka_description/robots/arm.xacro`` and ``common/franka_hand.xacro``, Apache-2.0):
  each link's ``<self_collision_geometries>`` is a cylinder with a sphere of the same
  radius on each end, i.e. a capsule, given in the URDF link frames; they are placed on
  moik's bodies with :func:`moik.robots.urdf_geometry.link_placements`.
* ``iiwa14``, ``ur5``, ``puma560-urdf``, when their mesh folders are given
  (``--iiwa14-meshes DIR``, ``--ur5-meshes DIR``, ``--puma560-urdf-meshes DIR``; trimesh
  needed, ``pip install 'moik[fit]'``): one enclosing capsule per URDF link, fitted to the
  vertices of the meshes the catalog URDF names (:func:`moik.collision.fit.fit_urdf`:
  the element's ``<origin>`` and ``scale`` applied, on moik's bodies by
  :func:`~moik.robots.urdf_geometry.link_placements`). iiwa14 and ur5 use their
  ``<collision>`` meshes (rtb-data 2.0.0's ``kuka_lbr_iiwa/meshes/lbr_iiwa_14_r820/
  collision``; example-robot-data 6.0.0's ``ur_description/meshes/ur5/collision``).
  ``puma560_robot.urdf`` has no ``<collision>`` element: its ``<visual>`` meshes
  (``puma_link*.stl``, scale 0.0254) are fitted instead (rtb-data's
  ``puma560_collision*.dae`` belong to its xacro, another kinematic description:
  shoulder height 0.54864 instead of 0.6718, joint 3 turned the other way). For each
  link the script prints the capsule's radius and length, the largest distance of a
  vertex outside it (0 up to rounding) and its volume over the mesh's convex hull's.
  Without a folder (or without trimesh) the arm gets the link drawing below.
* every other catalog arm: the link drawing of its kinematic chain. Body ``j`` gets a
  capsule along the polyline from joint ``j``'s axis point, along that axis to the foot
  of the common normal with joint ``j + 1``'s axis, to joint ``j + 1``'s axis point (the
  tool point after the last joint); the base a capsule from the base origin to joint 1's
  axis point. Radius: 5 % of the arm's reach (``Robot.reach``), 3.75 % on the last two
  bodies (the wrist). These are **not** fitted to meshes (none are shipped with the
  catalog's DH models); they are the DH link drawings with an assumed link thickness.

The allowed-collision matrix is then sampled (:func:`moik.collision.acm.sample_allowed`,
10,000 configurations, seed 0). Meshes are read only here, at build time; nothing is
downloaded.

The shipped ur5.json is built without ``--ur5-meshes``: one capsule per link leaves 3.9 %
of random UR5 configurations free of self-collision (q = 0 in collision), see
moik/collision/data/README.md.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

import numpy as np

from moik import get_robot
from moik.collision.acm import sample_allowed
from moik.collision.fit import capsule_excess, capsule_volume, fit_urdf
from moik.collision.io import model_to_dict
from moik.collision.kernels import world_frames
from moik.collision.model import CollisionChecker, CollisionModel, default_links
from moik.collision.shapes import Capsule, Shape, Sphere
from moik.robots.catalog import DATA
from moik.robots.urdf_geometry import link_placements

OUT = Path(__file__).resolve().parents[1] / "moik" / "collision" / "data"
FRANKA = "franka_ros franka_description/robots/arm.xacro + common/franka_hand.xacro (Apache-2.0)"
# (link, end a, end b, radius) in the URDF link frames, from FRANKA
PANDA = [
    ("panda_link0", (-0.09, 0, 0.06), (-0.06, 0, 0.06), 0.06),
    ("panda_link1", (0, 0, -0.333), (0, 0, -0.05), 0.06),
    ("panda_link2", (0, 0, -0.06), (0, 0, 0.06), 0.06),
    ("panda_link3", (0, 0, -0.22), (0, 0, -0.07), 0.06),
    ("panda_link4", (0, 0, -0.06), (0, 0, 0.06), 0.06),
    ("panda_link5", (0, 0, -0.31), (0, 0, -0.21), 0.06),
    ("panda_link5", (0, 0.08, -0.20), (0, 0.08, -0.06), 0.025),
    ("panda_link6", (0, 0, -0.07), (0, 0, 0.01), 0.05),
    ("panda_link7", (0, 0, -0.06), (0, 0, 0.08), 0.04),
    ("panda_link8", (0.0424, 0.0424, -0.03), (0.0424, 0.0424, -0.02), 0.03),
    ("panda_hand", (0, -0.05, 0.04), (0, 0.05, 0.04), 0.04),
    ("panda_hand", (0, -0.05, 0.10), (0, 0.05, 0.10), 0.02),
]
# arm: (catalog URDF, URDF element whose meshes are fitted, the meshes' source)
MESHES = {
    "iiwa14": ("lbr_iiwa_14_r820.urdf", "collision",
               "rtb-data 2.0.0 rtbdata/xacro/kuka_description/kuka_lbr_iiwa/meshes/"
               "lbr_iiwa_14_r820/collision/*.stl (ROS-Industrial kuka_experimental, "
               "Apache-2.0; rtb-data MIT)"),
    "ur5": ("ur5_robot.urdf", "collision",
            "example-robot-data 6.0.0 robots/ur_description/meshes/ur5/collision/*.stl "
            "(ROS-Industrial universal_robot ur_description, BSD)"),
    "puma560-urdf": ("puma560_robot.urdf", "visual",
                     "rtb-data 2.0.0 rtbdata/xacro/unimation_puma560_description/meshes/"
                     "puma_link*.stl, scale 0.0254 (the URDF's <visual> meshes: it has no "
                     "<collision>; MIT)"),
}
DRAWN = ["ur5", "iiwa14", "puma560", "puma560-kalra", "puma560-urdf", "eosma7", "eosma7-m",
         "rokbani5", "anthropomorphic3", "youbot5", "sawyer7", "irb2600", "scara4", "planar2"]


def panda_model() -> CollisionModel:
    robot = get_robot("panda")
    names, placed = link_placements(DATA / "panda.urdf", robot)
    shapes: dict[str, list[Shape]] = {}
    for link, a, b, r in PANDA:
        body, offset = placed[link]
        pa, pb = (offset @ np.r_[a, 1.0])[:3], (offset @ np.r_[b, 1.0])[:3]
        shapes.setdefault(names[body], []).append(Capsule.between(pa, pb, r))
    return CollisionModel(robot=robot, shapes=shapes, links=tuple(names), source=FRANKA)


def _foot(o1, z1, o2, z2):
    """The point of the line ``o1 + t z1`` closest to the line ``o2 + s z2``."""
    b = z1 @ z2
    denom = 1.0 - b * b
    if denom < 1e-12:
        return o1
    w = o1 - o2
    t = (b * (z2 @ w) - z1 @ w) / denom
    return o1 + t * z1


def drawn_model(name: str) -> CollisionModel:
    robot = get_robot(name)
    q = (robot.lower + robot.upper) / 2
    frames, axes = np.empty((robot.dof + 1, 4, 4)), np.empty((robot.dof, 6))
    world_frames(robot.chain_model, q, frames, axes)
    radius = 0.05 * robot.reach
    points = [axes[j, :3] for j in range(robot.dof)] + [frames[-1][:3, 3]]
    shapes: dict[str, list[Shape]] = {}
    links = default_links(robot)

    def add(body: int, pts: list[np.ndarray], r: float) -> None:
        inv = np.linalg.inv(frames[body])
        local = [(inv @ np.r_[p, 1.0])[:3] for p in pts]
        segs = [(a, b) for a, b in zip(local, local[1:], strict=False)
                if np.linalg.norm(b - a) > 1e-9 * robot.reach]
        items: list[Shape] = [Capsule.between(a, b, r) for a, b in segs]
        shapes[links[body]] = items or [Sphere(radius=r, pose=_at(local[0]))]

    add(0, [frames[0][:3, 3], points[0]], radius)
    for j in range(1, robot.dof + 1):
        o1, z1 = axes[j - 1, :3], axes[j - 1, 3:]
        nxt = points[j]
        foot = nxt if j == robot.dof else _foot(o1, z1, axes[j, :3], axes[j, 3:])
        r = radius * (0.75 if j >= robot.dof - 1 else 1.0)
        add(j, [points[j - 1], foot, nxt], r)
    return CollisionModel(robot=robot, shapes=shapes, links=links,
                          source=f"link drawing of {robot.source}; radius 5 % of the reach "
                                 "(3.75 % on the wrist), assumed, not fitted to meshes")


def _at(p: np.ndarray) -> np.ndarray:
    T = np.eye(4)
    T[:3, 3] = p
    return T


def fitted_model(name: str, mesh_dir: Path) -> tuple[CollisionModel, list[dict[str, Any]]]:
    """The mesh-fitted model of ``name`` and one table row per link."""
    from scipy.spatial import ConvexHull

    urdf, element, source = MESHES[name]
    robot = get_robot(name)
    names, fits = fit_urdf(DATA / urdf, robot, mesh_dir, element)
    shapes: dict[str, list[Shape]] = {}
    rows = []
    for fit in fits:
        capsule = Capsule.between(fit["a"], fit["b"], fit["radius"])
        shapes.setdefault(names[fit["body"]], []).append(capsule)
        a, b = capsule.ends
        rows.append({"link": fit["link"], "body": names[fit["body"]],
                     "radius": capsule.radius, "length": capsule.length,
                     "outside": capsule_excess(fit["points"], a, b, capsule.radius),
                     "ratio": capsule_volume(capsule.radius, capsule.length)
                     / ConvexHull(fit["points"]).volume})
    model = CollisionModel(robot=robot, shapes=shapes, links=tuple(names),
                           source=f"enclosing capsules (one per URDF link, moik.collision.fit) "
                                  f"fitted to the <{element}> meshes of URDF {urdf}: {source}")
    return model, rows


def _table(name: str, rows: list[dict[str, Any]]) -> str:
    lines = [f"{name}:", "", "| link (body) | radius (m) | length (m) | max vertex outside (m) "
             "| capsule / hull volume |", "|---|---|---|---|---|"]
    for r in rows:
        body = "" if r["body"] == r["link"] else f" ({r['body']})"
        lines.append(f"| {r['link']}{body} | {r['radius']:.4f} | {r['length']:.4f} | "
                     f"{r['outside']:.1e} | {r['ratio']:.2f} |")
    return "\n".join(lines)


def _arguments() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for name in MESHES:
        parser.add_argument(f"--{name}-meshes", type=Path, metavar="DIR",
                            help=f"folder of {name}'s meshes ({MESHES[name][2]})")
    return parser.parse_args()


def main() -> None:
    args = _arguments()
    try:
        import trimesh  # noqa: F401  (only to know whether meshes can be read)
        have_trimesh = True
    except ImportError:
        have_trimesh = False
    OUT.mkdir(exist_ok=True)
    models = {"panda": panda_model()} | {n: drawn_model(n) for n in DRAWN}
    tables = []
    for name in MESHES:
        folder = getattr(args, f"{name.replace('-', '_')}_meshes")
        if folder is None or not have_trimesh:
            why = f"no --{name}-meshes" if folder is None else "trimesh is not installed"
            print(f"{name}: link drawing ({why})")
            continue
        if not folder.is_dir():
            raise SystemExit(f"--{name}-meshes {folder}: not a folder")
        models[name], rows = fitted_model(name, folder)
        tables.append(_table(name, rows))
        worst = max(r["outside"] for r in rows)
        if worst > 1e-9:
            raise SystemExit(f"{name}: a vertex lies {worst:.3g} m outside its capsule")
    for name, model in models.items():
        model = sample_allowed(model, rng=np.random.default_rng(0))
        data = model_to_dict(model)
        data["acm"] = "sampled: 10,000 configurations, seed 0 (moik.collision.acm)"
        (OUT / f"{name}.json").write_text(json.dumps(data, indent=1) + "\n")
        n_shapes = sum(len(v) for v in model.shapes.values())
        Q = model.robot.random_q(10_000, rng=np.random.default_rng(0))  # sample_allowed's
        checker = CollisionChecker(model=model, self_collision=True)
        free = float((checker.min_distance(Q) >= 0.0).mean())
        print(f"{name:18s} {n_shapes:3d} shapes, {len(model.checked_body_pairs()):3d} checked "
              f"body pairs, {len(model.allowed):3d} allowed, {100 * free:5.1f} % of the "
              f"samples free of self-collision")
    for table in tables:
        print()
        print(table)


if __name__ == "__main__":
    main()
