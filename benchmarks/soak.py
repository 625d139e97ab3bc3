"""Soak test of the public solvers: many solves, verdicts against recomputed errors, memory.

Runs ``--n`` solves (default 200,000) round-robin over the catalog arms
(:func:`moik.available_robots`, or ``--robots``) on random reachable full poses
(:func:`moik.problems.random_reachable_targets`, a new seeded batch per round):
most through :func:`moik.solve_ik_batch` in batches of ``--batch``, every
``--single-every``-th batch through :func:`moik.solve_ik` one pose at a time.

Every answer is checked against errors recomputed independently, with the
plain-numpy oracle :func:`moik.robots.fk_reference` (position distance; geodesic
angle of ``R(q) R_target^T``), at the solver's tolerance (``tol=1e-9``: position
``1e-9 x reach``, orientation ``1e-9`` rad). A *disagreement* is

- ``solved`` (or ``success``) while a recomputed error is above the tolerance,
- a verdict other than ``solved`` while both recomputed errors are within it,
- ``success`` different from ``status == "solved"``, or ``q`` outside the limits,
- a reported error farther than ``1e-12 x reach`` (position) or ``1e-12`` rad
  from the recomputed one.

The two FKs agree to about 1e-15 relative, so an error within ``1e-12`` (relative)
of the tolerance is *borderline*: counted apart, and not a disagreement.
The resident memory (RSS, ``/proc/self/statm``) is printed at ``--intervals``
points: flat memory means no leak across solves.

Run: python benchmarks/soak.py [--n 200000] [--batch 50] [--robots eosma7,ur5]
[--single-every 10] [--intervals 10] [--seed 0] [--out FILE]
"""

from __future__ import annotations

import argparse
import os
import resource
import time
from collections import Counter

import numpy as np
from _output import OUT_HELP, table_output

from moik import available_robots, get_robot, solve_ik, solve_ik_batch
from moik.problems import random_reachable_targets
from moik.robots import fk_reference

TOL = 1e-9
REPORT_ATOL = 1e-12  # reported vs recomputed error (relative to reach for positions)
BORDER = 1e-12  # relative band around the tolerance where the two FKs may disagree


def rss_mib() -> float:
    """Resident memory of this process in MiB (Linux /proc; else the peak from getrusage)."""
    try:
        with open("/proc/self/statm") as fh:
            pages = int(fh.read().split()[1])
        return pages * os.sysconf("SC_PAGE_SIZE") / 2**20
    except (OSError, ValueError):
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def recomputed(robot, poses: np.ndarray, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Position and geodesic orientation errors by the reference FK."""
    T = fk_reference(robot, Q)
    pos = np.linalg.norm(T[:, :3, 3] - poses[:, :3, 3], axis=1)
    R = np.einsum("nij,nkj->nik", T[:, :3, :3], poses[:, :3, :3])
    # the angle of R by atan2(sin, cos): arccos of the trace alone loses half the digits
    # near 0 (an angle below 2e-8 reads as 0 or 2.1e-8)
    vee = np.stack([R[:, 2, 1] - R[:, 1, 2], R[:, 0, 2] - R[:, 2, 0], R[:, 1, 0] - R[:, 0, 1]], 1)
    sin = np.linalg.norm(vee, axis=1) / 2.0
    cos = (np.trace(R, axis1=1, axis2=2) - 1.0) / 2.0
    return pos, np.arctan2(sin, cos)


def check(robot, poses, Q, status, success, pos_rep, ori_rep, counts: Counter,
          where: str) -> list[str]:
    """Counts the verdicts and disagreements of one batch; returns the disagreements
    (``where`` says how to reproduce the batch)."""
    pos, ori = recomputed(robot, poses, Q)
    tp, to = TOL * robot.reach, TOL
    within = (pos <= tp) & (ori <= to)
    border = ((np.abs(pos - tp) <= BORDER * tp) | (np.abs(ori - to) <= BORDER * to))
    solved = status == "solved"
    bad = {
        "solved above tolerance": solved & ~within & ~border,
        "unsolved within tolerance": ~solved & within & ~border,
        "success != solved": success != solved,
        "q outside limits": ~robot.within_limits(Q),
        "reported error off": ((np.abs(pos_rep - pos) > REPORT_ATOL * robot.reach)
                               | (np.abs(ori_rep - ori) > REPORT_ATOL)),
    }
    counts.update(str(s) for s in status)
    counts["borderline"] += int(np.sum(border))
    found = []
    for kind, mask in bad.items():
        counts[kind] += int(np.sum(mask))
        found += [f"{where}[{i}]: {kind} (status {status[i]}, position {pos[i]:.3e} "
                  f"(reported {pos_rep[i]:.3e}), orientation {ori[i]:.3e} (reported "
                  f"{ori_rep[i]:.3e}))"
                  for i in np.flatnonzero(mask)]
    return found


def solve(robot, poses: np.ndarray, seed: int, single: bool):
    if not single:
        res = solve_ik_batch(robot, poses, seed=seed, tol=TOL)
        return res.q, res.status, res.success, res.position_error, res.orientation_error
    out = [solve_ik(robot, pose, seed=seed + i, tol=TOL) for i, pose in enumerate(poses)]
    return (np.array([r.q for r in out]), np.array([r.status for r in out]),
            np.array([r.success for r in out]), np.array([r.position_error for r in out]),
            np.array([r.orientation_error for r in out]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=200_000, help="solves in all")
    parser.add_argument("--batch", type=int, default=50, help="poses per solve_ik_batch call")
    parser.add_argument("--robots", default=None, help="comma-separated (default: the catalog)")
    parser.add_argument("--single-every", type=int, default=10,
                        help="every k-th batch goes through solve_ik pose by pose")
    parser.add_argument("--intervals", type=int, default=10, help="memory readings")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", help=OUT_HELP)
    args = parser.parse_args()
    names = args.robots.split(",") if args.robots else available_robots()
    robots = [get_robot(n) for n in names]
    with table_output(args.out):
        for robot in robots:  # compile / load the kernels before the first reading
            pose = random_reachable_targets(robot, 1, seed=0)[0].pose
            solve(robot, pose[None], 0, single=False)
            solve(robot, pose[None], 0, single=True)
        counts: Counter = Counter()
        found: list[str] = []
        every = max(1, args.n // max(1, args.intervals))
        done, k, next_mark, t0 = 0, 0, 0, time.perf_counter()
        print(f"soak: {args.n} solves over {len(robots)} arms ({', '.join(names)}), "
              f"batches of {args.batch}, every {args.single_every}th through solve_ik; "
              f"tol {TOL:g}")
        print(f"{'solves':>9} {'elapsed s':>10} {'RSS MiB':>9} {'disagree':>9}")
        rss0 = rss_mib()
        rss = [rss0]
        print(f"{0:>9} {0.0:>10.1f} {rss0:>9.1f} {0:>9}")
        next_mark = every
        while done < args.n:
            robot = robots[k % len(robots)]
            n = min(args.batch, args.n - done)
            single = args.single_every > 0 and k % args.single_every == args.single_every - 1
            seed = args.seed * 1_000_003 + k
            poses = np.array([t.pose for t in random_reachable_targets(robot, n, seed=seed)])
            Q, status, success, pos_rep, ori_rep = solve(robot, poses, seed, single)
            where = (f"{robot.name}: random_reachable_targets(robot, {n}, seed={seed}), "
                     + (f"solve_ik(seed={seed} + i, tol={TOL:g})" if single else
                        f"solve_ik_batch(seed={seed}, tol={TOL:g}) target i"))
            found += check(robot, poses, Q, status, success, pos_rep, ori_rep, counts, where)
            done += n
            k += 1
            if done >= next_mark or done == args.n:
                rss.append(rss_mib())
                bad = sum(counts[key] for key in ("solved above tolerance",
                                                  "unsolved within tolerance",
                                                  "success != solved", "q outside limits",
                                                  "reported error off"))
                print(f"{done:>9} {time.perf_counter() - t0:>10.1f} {rss[-1]:>9.1f} {bad:>9}")
                next_mark += every
        print()
        print("verdicts: " + ", ".join(f"{s} {counts[s]}" for s in
                                       ("solved", "not-converged", "unreachable")))
        for key in ("solved above tolerance", "unsolved within tolerance", "success != solved",
                    "q outside limits", "reported error off", "borderline"):
            print(f"  {key:<27} {counts[key]}")
        half = len(rss) // 2
        print(f"RSS: first reading {rss[0]:.1f} MiB, after the warm-up half "
              f"{rss[half]:.1f} MiB, last {rss[-1]:.1f} MiB (growth over the second half "
              f"{rss[-1] - rss[half]:+.1f} MiB)")
        for line in found[:20]:  # the first disagreements, to reproduce
            print("  " + line)


if __name__ == "__main__":
    main()
