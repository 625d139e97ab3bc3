"""Solve a full pose of the EOSMA paper's 7-DOF arm and check the answer by FK."""

import numpy as np

from moik import get_robot, solve_ik
from moik.plotting import plot_robot

robot = get_robot("eosma7")  # EOSMA paper, Table 1 (lengths in cm)
target = robot.fk(np.radians([45, 0, 45, 0, 45, 0, 0]))  # a reachable (4, 4) pose
res = solve_ik(robot, target, n_solutions=3, seed=0)
print(res.status, f"{len(res.solutions)} solutions")
for q in res.solutions:
    error = np.linalg.norm(robot.fk(q)[:3, 3] - target[:3, 3])
    print(np.round(np.degrees(q), 2), "position error <= 1e-9 x reach:",
          error <= 1e-9 * robot.reach)
plot_robot(robot, res.solutions, target=target, save="solve_pose")  # solve_pose.png, .pdf
