"""Collision distances and collision-blind IK answers, printed side by side in one run.

1. Correctness: N random configurations of panda, ur5 and iiwa14 (their shipped capsule
   models, moik/collision/data) in 3 scenes (a table; the collision-front shelf and table;
   a table with 6 random boxes and spheres, seeded): every evaluated pair's compiled
   signed distance against coal's (the test oracle): the largest difference over the
   separated pairs and over the penetrating ones, and sign disagreements.
2. Speed of the distance query: the compiled minimum distance of a batch of N
   configurations per configuration, beside coal's per configuration (coal called pair by
   pair from Python on N/10 of them, the baseline a user would write today; shapes and
   transforms built per configuration); medians of 5 interleaved repeats, ratio printed.
3. How often today's collision-blind ``solve_ik`` answers collide (the reason for
   collision-aware IK): targets are the FK poses of random collision-free configurations
   (so a collision-free exact solution exists); ``solve_ik`` (defaults, seed 0) solves
   each without geometry; the share of solved answers in collision, split by cause (self
   pair, scene pair), per arm and scene.
4. Collision-aware IK (success and speed): ``--success`` targets per arm,
   the FK poses of random collision-free configurations (self and scene) in the
   table + 6 boxes and spheres scene; ``solve_ik_batch(..., collision=checker)`` (self
   pairs and scene) in one call: the share solved collision-free (checked by coal, the
   limits and the pose tolerance by the reference FK), the rest by status, and
   collision-free solutions/s (median of 3 calls, interleaved with the collision-blind
   batch, whose solutions/s are printed beside); single ``solve_ik`` with the scene,
   median per target, beside the collision-blind solve (each first every other target) and the
   baseline a user would write today: roboticstoolbox's ``ik_LM`` (tol 1e-14) from random
   starts until coal says the answer is collision-free (at most 50 starts), ratio printed.
   Three passes over the targets alternate with three passes of the baseline (so both share
   the machine's noise). The solves are timed a second way too, each right after the
   baseline's calls for its target ("after LM"): measured, that doubles moik's time (the
   baseline's Python and coal code evicts moik's from the caches), so both are printed.
   ``solve_ik_pareto`` with the scene on the first 20 targets: every member checked by
   coal, the limits and the pose tolerance.

Run: python benchmarks/collision_ik.py [--n 1000] [--targets 100] [--success 200] [--out FILE]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _output import OUT_HELP, table_output
from solve_ik import rtb_robot

from moik import solve_ik
from moik.collision import Box, CollisionChecker, HalfSpace, Scene, Sphere
from moik.collision.catalog import collision_model
from moik.collision.io import rpy_pose
from moik.kinematics.orientation import orientation_error
from moik.robots import fk_reference
from moik.solver import solve_ik_batch, solve_ik_pareto

BASELINE_STARTS = 50  # ik_LM starts before the baseline gives a target up
PARETO_TARGETS = 20  # targets per arm whose solve_ik_pareto members are checked by coal

ARMS = ("panda", "ur5", "iiwa14")


def scenes(model, *, rng: np.random.Generator) -> dict[str, Scene]:
    """The three scenes, the table allowed against the two base bodies."""
    base = [("table", model.links[0]), ("table", model.links[1])]
    table = HalfSpace.plane([0, 0, 1], 0.0)
    shelf = {"table": table, "shelf": Box(size=(0.3, 0.7, 0.02), pose=rpy_pose([0.55, 0, 0.35])),
             "side-wall": Box(size=(0.3, 0.02, 0.7), pose=rpy_pose([0.55, 0.36, 0.35]))}
    clutter: dict = {"table": table}
    for k in range(6):
        c = rng.uniform([-0.8, -0.8, 0.05], [0.8, 0.8, 0.9])
        while np.linalg.norm(c[:2]) < 0.25:  # not through the base
            c = rng.uniform([-0.8, -0.8, 0.05], [0.8, 0.8, 0.9])
        if k % 2:
            clutter[f"ball{k}"] = Sphere(radius=rng.uniform(0.04, 0.12), pose=rpy_pose(c))
        else:
            clutter[f"box{k}"] = Box(size=rng.uniform(0.05, 0.25, 3),
                                     pose=rpy_pose(c, rng.uniform(-np.pi, np.pi, 3)))
    return {"table": Scene({"table": table}, allowed=frozenset(base[:2])),
            "shelf+table": Scene(shelf, allowed=frozenset(base)),
            "table+6": Scene(clutter, allowed=frozenset(base))}


def coal_distances(checker: CollisionChecker, q: np.ndarray) -> np.ndarray:
    """Every pair's distance by coal, pair by pair."""
    import coal

    placed = dict(checker.world_shapes(q))
    req = coal.DistanceRequest()
    req.enable_signed_distance = True
    req.gjk_tolerance = req.epa_tolerance = 1e-14
    cache: dict = {}

    def geom(name):
        if name not in cache:
            s = placed[name]
            r, h, _ = s.sizes
            g = (coal.Sphere(r) if isinstance(s, Sphere) else coal.Box(*s.size)
                 if isinstance(s, Box) else coal.Halfspace(np.array([0.0, 0, 1]), 0.0)
                 if isinstance(s, HalfSpace) else coal.Capsule(r, 2 * h))
            cache[name] = (g, coal.Transform3s(s.pose[:3, :3], s.pose[:3, 3]))
        return cache[name]

    out = np.empty(checker.n_pairs)
    for k, (a, b) in enumerate(checker.pair_names):
        (ga, ta), (gb, tb) = geom(a), geom(b)
        out[k] = coal.distance(ga, ta, gb, tb, req, coal.DistanceResult())
    return out


def strict_ok(robot, pose: np.ndarray, q: np.ndarray, tol: float = 1e-9) -> bool:
    """Within the limits and the pose tolerance by the reference FK (geodesic angle, the
    library's accurate form: an arccos of the trace is only good to ~1e-8 rad)."""
    T = fk_reference(robot, np.asarray(q, float)[None])[0]
    pos = np.linalg.norm(T[:3, 3] - pose[:3, 3])
    ori = float(np.ravel(orientation_error(T[:3, :3], pose[:3, :3], "geodesic"))[0])
    return bool(pos <= tol * robot.reach and ori <= tol and robot.within_limits(q)[0])


def baseline(lm, checker: CollisionChecker, pose: np.ndarray, rng: np.random.Generator
             ) -> tuple[bool, float]:
    """The IK a user would write today: ``ik_LM`` from random starts until coal says the
    answer is collision-free (at most BASELINE_STARTS); (solved, seconds)."""
    robot = checker.robot
    t0 = time.perf_counter()
    for q0 in robot.random_q(BASELINE_STARTS, rng=rng):
        q = np.asarray(lm.ik_LM(pose, q0=q0, tol=1e-14).q, float)
        if strict_ok(robot, pose, q) and coal_distances(checker, q).min() >= 0:
            return True, time.perf_counter() - t0
    return False, time.perf_counter() - t0


def collision_aware(checker: CollisionChecker, n: int, *, rng: np.random.Generator) -> dict:
    """Section 4 for one arm: the batch, single solves and the ik_LM + coal baseline."""
    robot = checker.robot
    Q = robot.random_q(20 * n, rng=rng)
    free = Q[checker.min_distance(Q) >= 0.0][:n]
    T = robot.fk(free)
    solve_ik(robot, T[0], seed=0, collision=checker)  # compiled outside the timing
    solve_ik_batch(robot, T[:2], seed=0, collision=checker)
    solve_ik_batch(robot, T[:2], seed=0)
    t_aware, t_blind_batch = [], []
    for _ in range(3):  # interleaved with the collision-blind batch; medians
        t0 = time.perf_counter()
        batch = solve_ik_batch(robot, T, seed=0, collision=checker)
        t_aware.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        blind_batch = solve_ik_batch(robot, T, seed=0)
        t_blind_batch.append(time.perf_counter() - t0)
    t_batch = float(np.median(t_aware))
    out = {"n": len(T), "ok": 0, "collides": int(np.sum(batch.status == "collides")),
           "other": int(np.sum(~batch.success & (batch.status != "collides"))), "bad": 0}
    for i in np.flatnonzero(batch.success):
        good = strict_ok(robot, T[i], batch.q[i]) and coal_distances(checker, batch.q[i]).min() >= 0
        out["ok"] += good
        out["bad"] += not good  # a "solved" answer the independent checks refuse
    out["rate"] = out["ok"] / t_batch
    out["blind_rate"] = int(blind_batch.success.sum()) / float(np.median(t_blind_batch))
    lm = rtb_robot(robot)
    t_moik, t_blind, t_mixed, t_mixed_blind, t_base = [], [], [], [], []
    base_ok = 0
    for rep in range(3):  # passes alternate (moik's, the baseline's): they share the noise
        for i, pose in enumerate(T):  # aware and blind interleaved, each first every other
            for aware in ((True, False) if i % 2 else (False, True)):  # time (the first is
                t0 = time.perf_counter()  # colder)
                res = solve_ik(robot, pose, seed=i, collision=checker if aware else None)
                (t_moik if aware else t_blind).append(time.perf_counter() - t0)
                if aware and rep == 0:
                    out["bad"] += res.success and not (
                        strict_ok(robot, pose, res.q) and coal_distances(checker, res.q).min() >= 0)
        for i, pose in enumerate(T):
            ok, dt = baseline(lm, checker, pose, rng)
            t_base.append(dt)
            base_ok += ok and rep == 0
            if rep == 0:  # moik right after the baseline's Python and coal calls (cold caches)
                for aware in (True, False):
                    t0 = time.perf_counter()
                    solve_ik(robot, pose, seed=i, collision=checker if aware else None)
                    (t_mixed if aware else t_mixed_blind).append(time.perf_counter() - t0)
    members = pareto_bad = 0
    for i, pose in enumerate(T[:PARETO_TARGETS]):  # every member checked independently
        front = solve_ik_pareto(robot, pose, objectives=("manipulability", "limit_margin"),
                                collision=checker, seed=i, n_solutions=10)
        members += len(front.X)
        pareto_bad += sum(not (strict_ok(robot, pose, q) and coal_distances(checker, q).min()
                               >= 0) for q in front.X)
    out.update(pareto_targets=min(len(T), PARETO_TARGETS), pareto_members=members,
               pareto_bad=pareto_bad)
    out.update(moik=1e3 * float(np.median(t_moik)), blind=1e3 * float(np.median(t_blind)),
               mixed=1e3 * float(np.median(t_mixed)),
               mixed_blind=1e3 * float(np.median(t_mixed_blind)),
               base=1e3 * float(np.median(t_base)), base_ok=base_ok)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=1000, help="configurations per arm and scene")
    ap.add_argument("--targets", type=int, default=100, help="IK targets per arm and scene")
    ap.add_argument("--success", type=int, default=200,
                    help="collision-aware IK targets per arm (section 4)")
    ap.add_argument("--out", help=OUT_HELP)
    args = ap.parse_args()
    rng = np.random.default_rng(2323)
    rows1, rows3, rows4 = [], [], []
    for arm in ARMS:
        model = collision_model(arm)
        robot = model.robot
        for sname, scene in scenes(model, rng=rng).items():
            checker = CollisionChecker(model=model, scene=scene, self_collision=True)
            Q = robot.random_q(args.n, rng=rng)
            D = checker.distances(Q)
            dmin = checker.min_distance(Q)  # compiled before timing
            coal_distances(checker, Q[0])
            t_m, t_c = [], []
            for _ in range(5):  # interleaved, medians (the machine is shared)
                t0 = time.perf_counter()
                checker.min_distance(Q)
                t_m.append((time.perf_counter() - t0) / args.n)
                t0 = time.perf_counter()
                C = np.array([coal_distances(checker, q) for q in Q[: max(args.n // 10, 1)]])
                t_c.append((time.perf_counter() - t0) / len(C))
            t_moik, t_coal = float(np.median(t_m)), float(np.median(t_c))
            C = np.array([coal_distances(checker, q) for q in Q])
            sep, pen = C >= 0, C < 0
            err_sep = float(np.abs(D - C)[sep].max()) if sep.any() else 0.0
            err_pen = float(np.abs(D - C)[pen].max()) if pen.any() else 0.0
            signs = int(np.sum((D < 0) != (C < 0)))
            rows1.append((arm, sname, checker.n_pairs, err_sep, err_pen, signs,
                          float((dmin >= 0).mean()), t_moik * 1e6, t_coal * 1e6))
            free = Q[dmin >= 0][: args.targets]
            blind = {"solved": 0, "colliding": 0, "self": 0, "scene": 0}
            self_only = CollisionChecker(model=model, self_collision=True)
            scene_only = CollisionChecker(model=model, scene=scene, self_collision=False)
            for q in free:
                res = solve_ik(robot, robot.fk(q), seed=0)
                if not res.success:
                    continue
                blind["solved"] += 1
                hit_self = self_only.min_distance(res.q) < 0
                hit_scene = scene_only.min_distance(res.q) < 0
                blind["colliding"] += bool(hit_self or hit_scene)
                blind["self"] += bool(hit_self)
                blind["scene"] += bool(hit_scene)
            rows3.append((arm, sname, len(free), blind))
            if sname == "table+6" and args.success:
                rows4.append((arm, collision_aware(checker, args.success, rng=rng)))
    lines = ["1-2. compiled distances vs coal (every evaluated pair), and the query time",
             f"{'arm':7s} {'scene':12s} {'pairs':>5s} {'max|d-coal| sep':>16s} "
             f"{'max|d-coal| pen':>16s} {'sign diff':>9s} {'free q':>7s} "
             f"{'moik us/q':>10s} {'coal us/q':>10s} {'coal/moik':>9s}"]
    for arm, sname, npairs, es, ep, sg, free, tm, tc in rows1:
        lines.append(f"{arm:7s} {sname:12s} {npairs:5d} {es:16.2e} {ep:16.2e} {sg:9d} "
                     f"{100 * free:6.1f}% {tm:10.2f} {tc:10.1f} {tc / tm:9.0f}")
    lines += ["", "3. collision-blind solve_ik answers at targets with a collision-free "
              "solution", f"{'arm':7s} {'scene':12s} {'targets':>7s} {'solved':>6s} "
              f"{'colliding':>10s} {'self':>5s} {'scene':>6s}"]
    for arm, sname, n, b in rows3:
        share = 100 * b["colliding"] / max(b["solved"], 1)
        lines.append(f"{arm:7s} {sname:12s} {n:7d} {b['solved']:6d} {share:9.1f}% "
                     f"{b['self']:5d} {b['scene']:6d}")
    lines += ["", "4. collision-aware IK (self pairs + table+6), targets from collision-free "
              "configurations", f"{'arm':7s} {'targets':>7s} {'free ok':>8s} {'collides':>8s} "
              f"{'other':>5s} {'bad':>4s} {'batch sol/s':>11s} {'blind sol/s':>11s} "
              f"{'moik ms':>8s} {'blind ms':>8s} {'after LM':>8s} {'blind':>6s} "
              f"{'LM+coal ok':>10s} {'LM+coal ms':>10s} {'ratio':>6s}"]
    for arm, r in rows4:
        lines.append(f"{arm:7s} {r['n']:7d} {100 * r['ok'] / r['n']:7.1f}% {r['collides']:8d} "
                     f"{r['other']:5d} {r['bad']:4d} {r['rate']:11.0f} {r['blind_rate']:11.0f} "
                     f"{r['moik']:8.3f} {r['blind']:8.3f} {r['mixed']:8.3f} "
                     f"{r['mixed_blind']:6.3f} {100 * r['base_ok'] / r['n']:9.1f}% "
                     f"{r['base']:10.3f} {r['moik'] / r['base']:6.3f}")
    lines += ["", "solve_ik_pareto with the scene (manipulability, limit margin; 10 members "
              "asked), every member checked by coal, the limits and the pose tolerance",
              f"{'arm':7s} {'targets':>7s} {'members':>7s} {'bad':>4s}"]
    for arm, r in rows4:
        lines.append(f"{arm:7s} {r['pareto_targets']:7d} {r['pareto_members']:7d} "
                     f"{r['pareto_bad']:4d}")
    lines += ["moik ms / blind ms: medians of single solve_ik calls with the scene / without,",
              "  one target after another (3 passes, alternating with the baseline's pass);",
              "after LM / blind: the same solves each made right after the baseline's ik_LM",
              "  and coal calls for that target (one pass): colder caches, so slower; the ratio",
              "  is moik ms / LM+coal ms"]
    with table_output(args.out):
        print("\n".join(lines))


if __name__ == "__main__":
    main()
