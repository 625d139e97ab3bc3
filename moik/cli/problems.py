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
    print(f"{'name':<24}{'robot':<11}{'obj':>4}  {'orientation':<14}{'front':>6}  reachable")
    for r in rows:
        front = "-" if r["front_points"] is None else str(r["front_points"])
        reach = "-" if r["reachable"] is None else ("yes" if r["reachable"] else "no")
        print(f"{r['name']:<24}{r['robot']:<11}{r['n_obj']:>4}  {r['orientation'] or '-':<14}"
              f"{front:>6}  {reach}")
    return 0
