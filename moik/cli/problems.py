"""``moik problems``: the registered IK benchmark problems (:func:`moik.problems.available`)
with their robot, objectives, orientation metric and reference front."""

from __future__ import annotations

import argparse

from moik.cli import output
from moik.exceptions import MoikError
from moik.problems import BiObjectiveIK, available, get_problem


def _row(name: str) -> dict:
    problem = get_problem(name)
    row = {"name": name, "robot": problem.robot.name, "n_obj": int(problem.n_obj),
           "n_var": int(problem.n_var), "orientation": getattr(problem, "orientation", None),
           "front_points": None, "reachable": None}
    if isinstance(problem, BiObjectiveIK) and problem.n_obj == 2:
        try:
            front = problem.reference_front()
        except MoikError:
            return row
        row.update(front_points=len(front.F), reachable=bool(front.reachable))
    return row


def cmd_problems(args: argparse.Namespace) -> int:
    """Print the registry: name, robot, objectives, metric and reference-front size."""
    rows = [_row(name) for name in available()]
    if args.json:
        output.print_json({"problems": rows})
        return 0
    cells = []
    for r in rows:
        front = "-" if r["front_points"] is None else str(r["front_points"])
        reach = "-" if r["reachable"] is None else ("yes" if r["reachable"] else "no")
        cells.append([r["name"], r["robot"], str(r["n_obj"]), r["orientation"] or "-", front,
                      reach])
    print(output.table(["name", "robot", "obj", "orientation", "front", "reachable"], cells,
                       right={2, 4}))
    return 0
