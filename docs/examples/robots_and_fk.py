"""The catalog's arms, their units and limits, and forward kinematics of a batch."""

import numpy as np

from moik import available_robots, get_robot

print(available_robots())
robot = get_robot("ur5")
print(robot, "reach", round(robot.reach, 3), robot.unit)
Q = robot.random_q(4, rng=np.random.default_rng(0))
T = robot.fk(Q)  # (4, 4, 4): one pose per joint vector
print(np.round(T[:, :3, 3], 4))
