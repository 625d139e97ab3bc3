"""Build the capsule models shipped in moik/collision/data (run: python -m studies.fit_capsules).

Two sources (moik/collision/data/README.md records which one each file uses):

* ``panda``: Franka Emika's own self-collision capsules, published in franka_ros
  (``franka_description/robots/arm.xacro`` and ``common/franka_hand.xacro``, Apache-2.0):
  each link's ``<self_collision_geometries>`` is a cylinder with a sphere of the same
  radius on each end, i.e. a capsule, given in the URDF link frames; they are placed on
  moik's bodies with :func:`moik.robots.urdf_geometry.link_placements`.
* every other catalog arm: the link drawing of its kinematic chain. Body ``j`` gets a
  capsule along the polyline from joint ``j``'s axis point, along that axis to the foot
  of the common normal with joint ``j + 1``'s axis, to joint ``j + 1``'s axis point (the
  tool point after the last joint); the base a capsule from the base origin to joint 1's
  axis point. Radius: 5 % of the arm's reach (``Robot.reach``), 3.75 % on the last two
  bodies (the wrist). These are **not** fitted to the manufacturers' meshes (the meshes
  are not shipped and were not fetched for this build); they are the DH link drawings
  with an assumed link thickness.

The allowed-collision matrix is then sampled (:func:`moik.collision.acm.sample_allowed`,
10,000 configurations, seed 0). trimesh is not needed for either source.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from moik import get_robot
from moik.collision.acm import sample_allowed
from moik.collision.io import model_to_dict
from moik.collision.kernels import world_frames
from moik.collision.model import CollisionModel, default_links
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
    chain = robot.kinematic_chain
    q = (robot.lower + robot.upper) / 2
    frames, axes = np.empty((robot.dof + 1, 4, 4)), np.empty((robot.dof, 6))
    world_frames(chain.origins, chain.link_frames, np.array(robot.base), chain.joint_types, q,
                 frames, axes)
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


def main() -> None:
    OUT.mkdir(exist_ok=True)
    models = {"panda": panda_model()} | {n: drawn_model(n) for n in DRAWN}
    for name, model in models.items():
        model = sample_allowed(model, rng=np.random.default_rng(0))
        data = model_to_dict(model)
        data["acm"] = "sampled: 10,000 configurations, seed 0 (moik.collision.acm)"
        (OUT / f"{name}.json").write_text(json.dumps(data, indent=1) + "\n")
        n_shapes = sum(len(v) for v in model.shapes.values())
        print(f"{name:18s} {n_shapes:3d} shapes, {len(model.checked_body_pairs()):3d} checked "
              f"body pairs, {len(model.allowed):3d} allowed")


if __name__ == "__main__":
    main()
