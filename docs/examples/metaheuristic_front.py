"""A metaheuristic on a pymoo problem: MOEOSMA's front of (position, orientation) errors at
the EOSMA paper's pose P2, its hypervolume (Table 8's reference point) and compromise."""

from pymoo.optimize import minimize

from moik import get_robot
from moik.algorithms import get_algorithm
from moik.metrics import compromise, hypervolume
from moik.plotting import plot_pareto_fronts
from moik.problems import BiObjectiveIK, Target

robot = get_robot("eosma7-m")
target = Target.from_euler([0.5, -0.25, 0.75], [0, 0, 0], convention="eosma-euler")
problem = BiObjectiveIK(robot, target, orientation="eosma-euler")
res = minimize(problem, get_algorithm("moeosma"), ("n_gen", 60), seed=1)
print(f"front of {len(res.F)} members, HV {hypervolume(res.F, ref_point=[1.695669, 2.524178]):.4f}")
x, f = compromise(res)
print("compromise errors:", f)
plot_pareto_fronts({"MOEOSMA": res.F}, compromise=f, save="metaheuristic_front")
