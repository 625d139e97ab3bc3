"""solve_ik on random reachable full poses, side by side with roboticstoolbox's ik_LM.

For each robot (``eosma7``, ``puma560``, ``sawyer7`` and the KUKA iiwa 14
URDF from ``shared/data/urdf``) and N seeded random reachable poses, prints:
strict success rate (errors recomputed with moik's reference FK: position
<= 1e-9 x the robot's reach, orientation <= 1e-9 rad), the share of answers
inside the joint limits, and the median / 95th-percentile time per solve.

If roboticstoolbox-python is importable (``pip install roboticstoolbox-python``,
benchmark only) its ``ik_LM`` runs on the same targets, on the same kinematics
(an ETS built from moik's chain transforms), with its default tolerance and
with ``tol=1e-14``, from the same seeded start configurations.

With ``--search-only`` it also times ``solve_ik(..., starts=0)`` (the
metaheuristic search and least-squares polish without the batched
Levenberg-Marquardt first attempt) on the same targets.

Run: python benchmarks/solve_ik.py [--n 1000] [--robots eosma7,puma560,...] [--search-only]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from moik import get_robot, load_urdf, solve_ik
from moik.problems import random_reachable_targets
from moik.solver.session import pose_errors

URDF = Path(__file__).resolve().parents[2] / "shared" / "data" / "urdf" / "lbr_iiwa_14_r820.urdf"


def load(name: str):
    return load_urdf(URDF, name="iiwa14") if name == "iiwa14" else get_robot(name)


def strict(robot, target, q) -> tuple[bool, bool]:
    pos, ori = pose_errors(robot, target, q)
    ok = pos[0] <= 1e-9 * robot.reach and ori[0] <= 1e-9
    return bool(ok), bool(robot.within_limits(q)[0])


def summarize(label: str, rows: list[tuple[bool, bool, float]]) -> str:
    ok, inside, times = (np.array(c) for c in zip(*rows, strict=True))
    return (f"  {label:<22} success {100 * ok.mean():6.1f}%   within limits "
            f"{100 * inside.mean():6.1f}%   median {1e3 * np.median(times):7.2f} ms   "
            f"p95 {1e3 * np.percentile(times, 95):7.2f} ms")


def run_moik(robot, targets, **options) -> list[tuple[bool, bool, float]]:
    rows = []
    for i, target in enumerate(targets):
        t0 = time.perf_counter()
        res = solve_ik(robot, target.pose, seed=i, **options)
        elapsed = time.perf_counter() - t0
        rows.append((*strict(robot, target, res.q), elapsed))
    return rows


def rtb_robot(robot):
    """roboticstoolbox Robot with the same kinematics (ETS of moik's transforms)."""
    import roboticstoolbox as rtb
    from roboticstoolbox import ET
    from spatialmath import SE3

    origins = robot.chain_origins()
    ets = ET.SE3(SE3(origins[0], check=False))
    for j in range(robot.dof):
        qlim = [robot.lower[j], robot.upper[j]]
        ets = ets * (ET.tz(qlim=qlim) if robot.is_prismatic[j] else ET.Rz(qlim=qlim))
        ets = ets * ET.SE3(SE3(origins[j + 1], check=False))
    return rtb.Robot(ets)


def run_rtb(robot, targets, tol: float | None) -> list[tuple[bool, bool, float]]:
    model = rtb_robot(robot)
    rng = np.random.default_rng(0)
    rows = []
    for target in targets:
        q0 = robot.random_q(1, rng=rng)[0]
        kwargs = {} if tol is None else {"tol": tol}
        t0 = time.perf_counter()
        sol = model.ik_LM(target.pose, q0=q0, **kwargs)
        elapsed = time.perf_counter() - t0
        rows.append((*strict(robot, target, np.asarray(sol[0], dtype=float)), elapsed))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1000, help="targets per robot")
    parser.add_argument("--robots", default="eosma7,puma560,sawyer7,iiwa14")
    parser.add_argument("--search-only", action="store_true",
                        help="also time solve_ik with starts=0 (no local multi-start attempt: "
                             "the metaheuristic search and least-squares polish alone)")
    args = parser.parse_args()
    try:
        import roboticstoolbox  # noqa: F401
        have_rtb = True
    except ImportError:
        have_rtb = False
        print("roboticstoolbox-python not installed: moik only "
              "(pip install roboticstoolbox-python for the side-by-side)")
    for name in args.robots.split(","):
        robot = load(name)
        targets = random_reachable_targets(robot, args.n, seed=2026)
        print(f"{name} ({robot.dof} DOF, reach {robot.reach:.4g} {robot.unit}), "
              f"{args.n} random reachable poses")
        moik_rows = run_moik(robot, targets)
        print(summarize("moik solve_ik", moik_rows))
        if args.search_only:
            search_rows = run_moik(robot, targets, starts=0)
            print(summarize("moik starts=0", search_rows))
            ratio = np.median([r[2] for r in search_rows]) / np.median([r[2] for r in moik_rows])
            print(f"  median time ratio starts=0 / default: {ratio:.1f}x")
        if have_rtb:
            default = run_rtb(robot, targets, None)
            tight = run_rtb(robot, targets, 1e-14)
            print(summarize("rtb ik_LM (default)", default))
            print(summarize("rtb ik_LM (tol=1e-14)", tight))
            ratio = np.median([r[2] for r in moik_rows]) / np.median([r[2] for r in tight])
            print(f"  median time ratio moik / ik_LM(tol=1e-14): {ratio:.1f}x")


if __name__ == "__main__":
    main()
