"""Your own arm: a URDF package with collision meshes, a scene file, collision-free IK."""

import json
from pathlib import Path

import numpy as np

import moik
from moik import load_urdf, solve_ik

# A URDF whose <collision> meshes are package://example-robot-data/... references, and a
# folder holding that package (here the copy moik ships; yours: your workspace's src/).
shipped = Path(moik.__file__).parent / "robots" / "data"
robot = load_urdf(shipped / "panda.urdf", tip_link="panda_hand_tcp",
                  package_dirs=[shipped / "packages"])

scene = Path("scene.json")  # obstacles in the robot's base frame, metres
scene.write_text(json.dumps({
    "obstacles": [
        {"name": "table", "type": "halfspace", "normal": [0, 0, 1], "offset": 0.0},
        {"name": "shelf", "type": "box", "size": [0.3, 0.7, 0.02], "xyz": [0.6, 0.0, 0.3]}],
    "allowed": [["table", "panda_link0"]]}))  # the table the arm stands on

target = robot.fk(np.array([0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8]))
res = solve_ik(robot, target, scene=str(scene), self_collision=True, clearance=0.01, seed=0)
print(res.status, f"smallest distance {res.min_distance:.3f} m")
