"""The exact solutions of a redundant arm's pose that are Pareto-optimal in joint motion
and manipulability, written as an interactive page (needs the ``explorer`` extra)."""

import numpy as np

from moik import get_robot, solve_ik_pareto
from moik.plotting import pareto_explorer

robot = get_robot("panda")
q_current = np.array([0.0, -0.3, 0.0, -2.0, 0.0, 1.8, 0.8])
pose = robot.fk(q_current + 0.2)
res = solve_ik_pareto(robot, pose, q_current=q_current, n_solutions=12, seed=1)
i = res.compromise_index()
print(f"{len(res.X)} exact solutions; compromise: joint motion {res.F[i, 0]:.3f} rad, "
      f"manipulability {res.F[i, 1]:.4f}")
print("wrote", pareto_explorer(res, robot, "pareto_explorer.html", target=pose))
