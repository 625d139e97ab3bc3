"""Collision-constrained bi-objective IK: the registered MO algorithms beside a shelf and table.

Not a paper's table: the Panda (Franka Emika's capsule model, moik/collision/data) on a
table with a shelf board and a side wall in front of it; objectives (position error,
geodesic orientation error), one constraint ``G = clearance - d_min(q) <= 0`` over the
arm's self pairs and every link-obstacle pair (the table is not checked against the
two base links that stand on it). Two targets: ``above-shelf``, the FK pose of a
collision-free configuration (clearance 0.022 m, so a collision-free exact solution
exists) and ``beyond-reach``, 1.1 m in front of the base (unreachable: the front is
a trade-off). The trials record how many returned members are collision-free (the
``collision`` table) and the HV of those only (reference point (1.5, pi)).
"""

_MO = ["moeosma", "mo-m-pso", "mssa", "moalo", "moda", "momvo", "mogwo", "mosma", "mopso",
       "mompa", "mo-pso", "mo-jaya", "mo-csa", "nsga2", "moead", "sms-emoa", "mopso-cd"]
_SCENE = {"obstacles": [
    {"name": "table", "type": "halfspace", "normal": [0, 0, 1], "offset": 0.0},
    {"name": "shelf", "type": "box", "size": [0.3, 0.7, 0.02], "xyz": [0.55, 0, 0.35]},
    {"name": "side-wall", "type": "box", "size": [0.3, 0.02, 0.7], "xyz": [0.55, 0.36, 0.35]}],
    "allowed": [["table", "panda_link0"], ["table", "panda_link1"]]}

EXPERIMENT = {
    "name": "collision-front",
    "title": "MO algorithms on collision-constrained bi-objective IK (Panda, shelf and table)",
    "source": "moik: Panda capsules from franka_ros (Apache-2.0); scene and targets of this file",
    "robot": "panda",
    "problem": {"kind": "bi-objective", "orientation": "geodesic", "scene": _SCENE,
                "clearance": 0.0, "self_collision": True, "collision_groups": "min"},
    "targets": {"kind": "fixed", "points": [
        {"name": "above-shelf", "fk_q_deg": [-119.7, 27.9, 136.1, -130.7, -41.8, 137.5, -66.4],
         "hv_ref_point": [1.5, 3.141593]},
        {"name": "beyond-reach", "position": [1.1, 0.0, 0.4], "euler_deg": [180, 0, 0],
         "hv_ref_point": [1.5, 3.141593]},
    ]},
    "algorithms": [{"name": n} for n in _MO],
    "pop_size": 100,
    "archive_size": 100,
    "iterations": 300,
    "runs": 10,
    "seed": 2323,
    "analyses": ["friedman-hv", "collision"],
    "proposed": "nsga2",
    "quick": {"pop_size": 20, "iterations": 10, "runs": 2},
}
