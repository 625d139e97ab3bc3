"""solve_ik / solve_ik_batch side by side with roboticstoolbox's C++ ``ik_LM``.

Prints every row of the solver's speed goals (docs/solver.md), measured in one
process, moik and ``ik_LM`` interleaved target by target (the machine is
shared: medians, same targets, same kinematics):

1. ``solve_ik`` on N random reachable full poses per arm (eosma7, puma560,
   sawyer7 and the iiwa14 / panda / ur5 URDFs): strict success (errors
   recomputed with moik's plain-numpy reference FK: position <= 1e-6 x reach,
   orientation <= 1e-6 rad, within the joint limits), median, p99 and worst
   time; ``ik_LM`` (``tol=1e-14``, joint limits on) from a seeded random start.
2. Unreachable targets (1.2 x reach): moik's verdict with its front vs the time
   ``ik_LM`` takes to give up.
3. ``n_solutions=8`` on UR5 poses vs a 64-start ``ik_LM`` loop: time and the
   number of distinct branches (modulo 2 pi) each finds.
4. ``solve_ik_batch`` of N poses in one call vs ``ik_LM`` one by one.

``ik_LM`` runs on an ETS built from moik's chain transforms, so both solve the
same kinematics. roboticstoolbox-python is in the ``bench`` extra.

Run: python benchmarks/solve_ik.py [--n 1000] [--robots eosma7,puma560,...] [--out FILE]
(``--out`` also writes the printed table to FILE, e.g. docs/results/solve_ik.txt, which
docs/solver.md quotes).
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _output import OUT_HELP, table_output
from scipy.spatial.transform import Rotation

from moik import get_robot, solve_ik, solve_ik_batch
from moik.problems import random_reachable_targets
from moik.robots import fk_reference

STRICT = 1e-6


def strict_ok(robot, pose: np.ndarray, q: np.ndarray) -> bool:
    """Errors by the independent reference FK: position, geodesic angle, limits."""
    T = fk_reference(robot, np.asarray(q, float)[None])[0]
    pos = np.linalg.norm(T[:3, 3] - pose[:3, 3])
    cos = np.clip((np.trace(T[:3, :3] @ pose[:3, :3].T) - 1.0) / 2.0, -1.0, 1.0)
    ori = float(np.arccos(cos))
    return bool(pos <= STRICT * robot.reach and ori <= STRICT
                and robot.within_limits(q)[0])


def rtb_robot(robot):
    """roboticstoolbox Robot with the same kinematics (an ETS of moik's transforms)."""
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


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - t0


def stats(times) -> str:
    t = 1e3 * np.asarray(times)
    return (f"median {np.median(t):7.3f} ms  p99 {np.percentile(t, 99):7.2f} ms  "
            f"worst {t.max():7.2f} ms")


def reachable(name: str, n: int, model) -> float:
    robot = get_robot(name)
    targets = random_reachable_targets(robot, n, seed=2026)
    solve_ik(robot, targets[0].pose, seed=0)  # compile / load kernels outside the timing
    rng = np.random.default_rng(0)
    mo, rt = [], []
    for i, target in enumerate(targets):
        pose = target.pose
        res, dt = timed(lambda pose=pose, i=i: solve_ik(robot, pose, seed=i))
        mo.append((strict_ok(robot, pose, res.q), dt))
        if model is not None:
            q0 = robot.random_q(1, rng=rng)[0]
            sol, dt = timed(lambda pose=pose, q0=q0: model.ik_LM(pose, q0=q0, tol=1e-14))
            rt.append((strict_ok(robot, pose, np.asarray(sol.q, float)), dt))
    print(f"{name} ({robot.dof} DOF), {n} random reachable poses")
    ok, t = zip(*mo, strict=True)
    print(f"  moik solve_ik       strict {100 * np.mean(ok):6.2f}%  {stats(t)}")
    if not rt:
        return np.nan
    ok_r, t_r = zip(*rt, strict=True)
    print(f"  rtb ik_LM 1e-14     strict {100 * np.mean(ok_r):6.2f}%  {stats(t_r)}")
    ratio = np.median(t) / np.median(t_r)
    print(f"  median ratio moik / ik_LM: {ratio:.2f}x (goal <= 1.0x)")
    return ratio


def unreachable(name: str, n: int, model) -> None:
    robot = get_robot(name)
    rng = np.random.default_rng(7)
    mo, rt, verdicts = [], [], []
    for i in range(n):
        d = rng.normal(size=3)
        pose = np.eye(4)
        pose[:3, 3] = robot.chain_origins()[0][:3, 3] + 1.2 * robot.reach * d / np.linalg.norm(d)
        pose[:3, :3] = Rotation.from_rotvec(rng.normal(size=3)).as_matrix()
        res, dt = timed(lambda pose=pose, i=i: solve_ik(robot, pose, seed=i))
        mo.append(dt)
        verdicts.append(res.status == "unreachable" and res.front is not None)
        if model is not None:
            q0 = robot.random_q(1, rng=rng)[0]
            _, dt = timed(lambda pose=pose, q0=q0: model.ik_LM(pose, q0=q0, tol=1e-14))
            rt.append(dt)
    line = (f"  unreachable (1.2x reach) {name}: moik verdict+front {100 * np.mean(verdicts):.0f}% "
            f"median {1e3 * np.median(mo):.2f} ms")
    if rt:
        line += (f"; ik_LM gives up in {1e3 * np.median(rt):.2f} ms; ratio "
                 f"{np.median(mo) / np.median(rt):.2f}x (goal <= 5x)")
    print(line)


def branches(Q: np.ndarray, robot, threshold: float = 0.1) -> int:
    """Number of distinct configurations modulo 2 pi among rows of Q."""
    kept: list[np.ndarray] = []
    for q in Q:
        if all(np.linalg.norm(np.where(robot.is_prismatic, q - k,
                                       (q - k + np.pi) % (2 * np.pi) - np.pi)) > threshold
               for k in kept):
            kept.append(q)
    return len(kept)


def many_branches(name: str, n: int, model) -> None:
    robot = get_robot(name)
    targets = random_reachable_targets(robot, n, seed=5)
    rng = np.random.default_rng(3)
    mo, rt, nb_m, nb_r = [], [], [], []
    for i, target in enumerate(targets):
        pose = target.pose
        res, dt = timed(lambda pose=pose, i=i: solve_ik(robot, pose, n_solutions=8, seed=i))
        mo.append(dt)
        nb_m.append(branches(res.solutions, robot))
        if model is not None:
            def loop(pose=pose):
                sols = []
                for q0 in robot.random_q(64, rng=rng):
                    sol = model.ik_LM(pose, q0=q0, tol=1e-14)
                    if sol.success and strict_ok(robot, pose, np.asarray(sol.q, float)):
                        sols.append(np.asarray(sol.q, float))
                return np.array(sols).reshape(-1, robot.dof)
            sols, dt = timed(loop)
            rt.append(dt)
            nb_r.append(branches(sols, robot))
    line = (f"  n_solutions=8 {name}: moik {np.mean(nb_m):.2f} branches, median "
            f"{1e3 * np.median(mo):.2f} ms")
    if rt:
        line += (f"; 64-start ik_LM {np.mean(nb_r):.2f} branches, {1e3 * np.median(rt):.2f} ms;"
                 f" ratio {np.median(mo) / np.median(rt):.2f}x (goal <= 2x)")
    print(line)


def batch(name: str, n: int, model) -> None:
    robot = get_robot(name)
    targets = random_reachable_targets(robot, n, seed=11)
    poses = np.array([t.pose for t in targets])
    solve_ik_batch(robot, poses[:2], seed=0, workers=1)  # one core, as ik_LM one by one
    res, dt = timed(lambda: solve_ik_batch(robot, poses, seed=0, workers=1))
    ok = np.mean([strict_ok(robot, p, q) for p, q in zip(poses, res.q, strict=True)])
    line = (f"  solve_ik_batch {name}: {n} poses in {1e3 * dt:.1f} ms "
            f"({n / dt:,.0f} poses/s), strict {100 * ok:.2f}%")
    if model is not None:
        rng = np.random.default_rng(1)
        q0s = robot.random_q(n, rng=rng)

        def one_by_one():
            return [model.ik_LM(p, q0=q0, tol=1e-14) for p, q0 in zip(poses, q0s, strict=True)]
        sols, dt_r = timed(one_by_one)
        ok_r = np.mean([strict_ok(robot, p, np.asarray(s.q, float))
                        for p, s in zip(poses, sols, strict=True)])
        line += (f"; ik_LM one by one {1e3 * dt_r:.1f} ms, strict {100 * ok_r:.2f}%; ratio "
                 f"{dt / dt_r:.2f}x (goal <= 1.0x)")
    print(line)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1000, help="reachable poses per robot")
    parser.add_argument("--robots", default="eosma7,puma560,sawyer7,iiwa14,panda,ur5")
    parser.add_argument("--out", help=OUT_HELP)
    args = parser.parse_args()
    with table_output(args.out):
        compare(args.n, args.robots.split(","))


def compare(n: int, names: list[str]) -> None:
    """Print every row of the goal table for the arms ``names``, ``n`` poses each."""
    try:
        import roboticstoolbox  # noqa: F401
        have_rtb = True
    except ImportError:
        have_rtb = False
        print("roboticstoolbox-python not installed (pip install -e '.[bench]'): moik only")
    models = {name: rtb_robot(get_robot(name)) if have_rtb else None for name in names}
    for name in names:
        reachable(name, n, models[name])
    for name in names:
        unreachable(name, max(n // 10, 5), models[name])
    if "ur5" in names:
        many_branches("ur5", max(n // 50, 5), models["ur5"])
    for name in names:
        batch(name, n, models[name])


if __name__ == "__main__":
    main()
