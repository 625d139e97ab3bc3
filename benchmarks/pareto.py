"""solve_ik_pareto on random reachable poses, side by side with roboticstoolbox's ik_LM.

iiwa14 (7 DOF, the shipped URDF), N seeded random reachable full poses, the current
configuration the pose's source configuration perturbed by N(0, 0.2 rad) per joint,
criteria (joint_motion, manipulability). Per pose, checked independently of the
solver (moik's plain-numpy reference FK for the errors; roboticstoolbox's own
Jacobian for manipulability; joint motion recomputed in numpy):

- strict members: position <= 1e-9 x reach, orientation <= 1e-9 rad, within limits
  (goal: >= 10 per pose), and whether they are mutually non-dominated;
- the nearest member's joint motion against ik_LM started from q_current
  (tol 1e-14; its solution's 2 pi copy nearest q_current, which can only help it);
  goal: at least as near;
- the most manipulable member against the best strict solution of 64 random
  ik_LM starts (one search each); goal: >= 0.99x;
- the wall time of solve_ik_pareto (goal: median <= 50 ms) beside those of ik_LM.

Then the 6-DOF arms (UR5, Puma 560 URDF): every member exact and non-dominated,
and how many distinct branches solve_ik_pareto saw against solve_ik(n_solutions=16).

Run: python benchmarks/pareto.py [--n 10] [--seed 2026]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _output import OUT_HELP, table_output

from moik import get_robot, solve_ik, solve_ik_pareto
from moik.kinematics.criteria import nearest_copies
from moik.problems import random_reachable_targets
from moik.robots import fk_reference

try:
    from benchmarks.solve_ik import rtb_robot
except ImportError:  # run as a script from the repository root
    from solve_ik import rtb_robot

TOL = 1e-9


def strict_mask(robot, target, Q) -> np.ndarray:
    """Errors by the reference FK within TOL, and within the limits."""
    T = fk_reference(robot, np.atleast_2d(Q))
    pos = np.linalg.norm(T[:, :3, 3] - target.position, axis=1)
    M = np.einsum("nji,jk->nik", T[:, :3, :3], target.rotation)  # R^T R_t
    skew = np.stack([M[:, 2, 1] - M[:, 1, 2], M[:, 0, 2] - M[:, 2, 0], M[:, 1, 0] - M[:, 0, 1]])
    ori = np.arctan2(np.linalg.norm(skew, axis=0), np.trace(M, axis1=1, axis2=2) - 1)
    return (pos <= TOL * robot.reach) & (ori <= TOL) & robot.within_limits(Q)


def motion(robot, Q, q_current) -> np.ndarray:
    return np.linalg.norm(nearest_copies(robot, np.atleast_2d(Q), q_current) - q_current, axis=1)


def non_dominated(F: np.ndarray) -> bool:
    """No row dominates another (minimisation)."""
    le = np.all(F[:, None] <= F[None], axis=2) & np.any(F[:, None] < F[None], axis=2)
    return not le.any()


def iiwa(args) -> None:
    robot = get_robot("iiwa14")
    model = rtb_robot(robot)
    rng = np.random.default_rng(args.seed)
    targets = random_reachable_targets(robot, args.n, seed=args.seed)
    solve_ik_pareto(robot, targets[0], q_current=targets[0].q_source)  # compile once
    rows = []
    for i, t in enumerate(targets):
        qc = np.clip(t.q_source + rng.normal(scale=0.2, size=robot.dof), robot.lower, robot.upper)
        t0 = time.perf_counter()
        res = solve_ik_pareto(robot, t, q_current=qc, seed=i)
        wall = time.perf_counter() - t0
        ok = strict_mask(robot, t, res.X)
        F = np.column_stack([motion(robot, res.X, qc),
                             -np.array([model.manipulability(q) for q in res.X])])
        t0 = time.perf_counter()
        near = model.ik_LM(t.pose, q0=qc, tol=1e-20)
        t_near = time.perf_counter() - t0
        q_near = np.asarray(near.q, dtype=float)
        d_lm = motion(robot, q_near, qc)[0] if strict_mask(robot, t, q_near)[0] else np.inf
        best, t0 = 0.0, time.perf_counter()
        for q0 in robot.random_q(64, rng=rng):
            sol = model.ik_LM(t.pose, q0=q0, tol=1e-20, slimit=1)
            q = np.asarray(sol.q, dtype=float)
            if sol.success and strict_mask(robot, t, q)[0]:
                best = max(best, float(model.manipulability(q)))
        t_64 = time.perf_counter() - t0
        rows.append((int(ok.sum()), non_dominated(F), F[:, 0].min(), d_lm, -F[:, 1].min(), best,
                     wall, t_near, t_64))
    print(f"iiwa14 (7 DOF), {args.n} random reachable poses, q_current = source + N(0, 0.2 rad)")
    print(f"{'pose':>4} {'strict':>6} {'nondom':>6} {'nearest':>8} {'ik_LM(qc)':>9} "
          f"{'max manip':>9} {'best of 64':>10} {'ratio':>6} {'time ms':>8} {'ik_LM ms':>8} "
          f"{'64x ms':>7}")
    for i, (n, nd, d, d_lm, m, b, wall, tn, t64) in enumerate(rows):
        print(f"{i:>4} {n:>6} {'yes' if nd else 'NO':>6} {d:8.4f} {d_lm:9.4f} {m:9.5f} "
              f"{b:10.5f} {m / b if b else np.inf:6.3f} {1e3 * wall:8.1f} {1e3 * tn:8.2f} "
              f"{1e3 * t64:7.1f}")
    n, nd, d, d_lm, m, b, wall = (np.array(c) for c in list(zip(*rows, strict=True))[:7])
    print("goals:")
    print(f"  >= 10 strict solutions per pose        {'met' if n.min() >= 10 else 'NOT met'}"
          f"  (min {n.min()}, median {np.median(n):.0f})")
    print(f"  mutually non-dominated (independent)   {'met' if nd.all() else 'NOT met'}"
          f"  ({nd.sum()}/{len(nd)} poses)")
    print(f"  nearest <= ik_LM from q_current        {'met' if np.all(d <= d_lm) else 'NOT met'}"
          f"  ({np.sum(d <= d_lm)}/{len(d)}; median ratio {np.median(d / d_lm):.4f}, "
          f"smallest margin {np.min(d_lm - d):.2e} rad)")
    ratio = m / b
    print(f"  most manipulable >= 0.99x best of 64   {'met' if ratio.min() >= 0.99 else 'NOT met'}"
          f"  (min ratio {ratio.min():.3f}, median {np.median(ratio):.3f})")
    fast = np.median(wall) <= 0.05
    print(f"  median time <= 50 ms                   {'met' if fast else 'NOT met'}"
          f"  (median {1e3 * np.median(wall):.1f} ms, max {1e3 * wall.max():.1f} ms)")


def six_dof(args) -> None:
    print("6-DOF arms: branches (pose targets; q_current = source + N(0, 0.2 rad))")
    rng = np.random.default_rng(args.seed)
    for name in ("ur5", "puma560-urdf"):
        robot = get_robot(name)
        targets = random_reachable_targets(robot, args.n, seed=args.seed)
        exact = nondom = 0
        found, seen, ref, times = [], [], [], []
        for i, t in enumerate(targets):
            qc = np.clip(t.q_source + rng.normal(scale=0.2, size=robot.dof), robot.lower,
                         robot.upper)
            t0 = time.perf_counter()
            res = solve_ik_pareto(robot, t, q_current=qc, objectives=(
                "joint_motion", "manipulability", "limit_margin"), seed=i)
            times.append(time.perf_counter() - t0)
            exact += int(strict_mask(robot, t, res.X).all())
            nondom += int(non_dominated(res.F_min))
            seen.append(len(res.X))
            found.append(res.n_exact)
            ref.append(len(solve_ik(robot, t.pose, n_solutions=16, seed=i).solutions))
        print(f"  {name:<13} all members exact on {exact}/{len(targets)} poses, non-dominated on "
              f"{nondom}/{len(targets)}; branches per pose: found {np.median(found):.0f} "
              f"(solve_ik n_solutions=16: {np.median(ref):.0f}), returned (non-dominated) "
              f"{np.median(seen):.0f}; median {1e3 * np.median(times):.1f} ms")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10, help="poses per arm")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--out", help=OUT_HELP)
    args = parser.parse_args()
    with table_output(args.out):
        iiwa(args)
        six_dof(args)


if __name__ == "__main__":
    main()
