"""Speed of moik's algorithms, printed side by side.

Run: ``.venv/bin/python benchmarks/algorithms.py [--quick] [a] [b] [c] [d] [--out FILE]``
(the letters pick sections, all by default; ``--out`` also writes the printed table to
FILE, e.g. docs/results/algorithms.txt, which docs/performance.md links to)

(a) Per-generation cost of each algorithm run through ``pymoo.optimize.minimize``
    against a plain numpy loop of the same update rule (the same kernel
    functions, a raw vectorized sphere, no pymoo), N=100, dim=7. Goal: ratio <= 1.3.
(b) One EOSMA run of the paper's scenario 1 (position, N=50, T=500, Table 5) and
    scenario 2 (pose with the Eq. 26 Euler error, N=100, T=1000, Table 7) on the
    ``eosma7-m`` arm, against forward kinematics of as many poses as the run
    evaluates (its n_eval, in batches of N): moik's compiled FK (``robot.fk_position``
    / ``robot.fk``) and the plain batched numpy DH chain (``moik.robots.fk_reference``).
    Interleaved repeats, medians. Goal: run / numpy FK <= 0.8 (the whole run, update
    rule and bookkeeping included, costs less than numpy FK of its poses alone). The
    paper's MATLAB times (i7-9700): 0.0567 s and 0.3608 s.
(c) Seconds per IK solve with the paper's re-solve protocol: scenario 1 and
    scenario 2, the latter both with the catalog arm (cm) and with Table 1's lengths
    in metres (the unit that reproduces Table 7, see tests/algorithms/soo/test_eosma.py).
(d) moik EO/SMA/PSO against mealpy 3.0.3 OriginalEO/OriginalSMA/OriginalPSO,
    N=100, 1000 iterations, on the 7-D sphere and on eosma7 position IK
    (``pip install mealpy==3.0.3``, the ``bench-mealpy`` extra).
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import numpy as np
from _output import OUT_HELP, table_output
from pymoo.core.problem import Problem
from pymoo.optimize import minimize

from moik.algorithms import EO, EOSMA, MPSO, PSO, SMA
from moik.algorithms.mechanics import (
    best_index,
    clip_to_bounds,
    greedy_memory,
    is_better,
    midpoint_repair,
    uniform_population,
)
from moik.algorithms.soo.eo import concentration_update, eo_schedule, update_pool, with_mean
from moik.algorithms.soo.eosma import (
    eosma_update,
    random_difference_mutation,
    update_distinct_pool,
)
from moik.algorithms.soo.modified_pso import mpso_velocity
from moik.algorithms.soo.pso import clamp_velocity, pso_velocity
from moik.algorithms.soo.sma import sma_schedule, sma_update, sma_weights
from moik.experiments.protocol import solve_until_success
from moik.problems import PoseIK, PositionIK, random_reachable_targets
from moik.robots import fk_reference, get_robot

N, D, LO, HI = 100, 7, -10.0, 10.0
SECTIONS = ("a", "b", "c", "d")


def sphere(X: np.ndarray) -> np.ndarray:
    return np.einsum("ij,ij->i", X, X)


class Sphere(Problem):
    def __init__(self, n_var: int = D):
        super().__init__(n_var=n_var, n_obj=1, xl=LO, xu=HI, vtype=float)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = sphere(X)[:, None]


def loop_eo(T, rng, xl, xu):
    X = uniform_population(N, xl, xu, rng=rng)
    F = sphere(X)
    P = update_pool(np.empty((0, D)), np.empty(0), None, X, F, None)
    for t in range(1, T):
        Xn = clip_to_bounds(concentration_update(X, with_mean(P[0]), eo_schedule(t, T, 1.0),
                                                 a1=2.0, GP=0.5, V=1.0, rng=rng), xl, xu)
        Fn = sphere(Xn)
        P = update_pool(P[0], P[1], None, Xn, Fn, None)
        X, F, _ = greedy_memory(Xn, Fn, None, X, F, None)
    return F.min()


def loop_sma(T, rng, xl, xu):
    X = uniform_population(N, xl, xu, rng=rng)
    F = sphere(X)
    i = best_index(F, None)
    bx, bf = X[i].copy(), F[i]
    for t in range(1, T):
        a, b = sma_schedule(t, T)
        W = sma_weights(F, D, rng=rng)
        X = clip_to_bounds(sma_update(X, W, bx, F, bf, a, b, z=0.03, xl=xl, xu=xu, rng=rng),
                           xl, xu)
        F = sphere(X)
        i = best_index(F, None)
        if F[i] < bf:
            bx, bf = X[i].copy(), F[i]
    return bf


def loop_eosma(T, rng, xl, xu, q=1.0, a1=2.0):
    X = uniform_population(N, xl, xu, rng=rng)
    F = sphere(X)
    PX, PF = X, F
    P = update_distinct_pool(np.empty((0, D)), np.empty(0), None, X, F, None)
    for t in range(1, T):
        W = sma_weights(PF, D, rng=rng)
        g = PX[best_index(PF, None)]
        Xn = eosma_update(PX, g, with_mean(P[0]), W, eo_schedule(t, T, 2.0), sma_schedule(t, T)[0],
                          z=0.5, a1=a1, GP=0.5, V=1.0, rng=rng)
        X = midpoint_repair(Xn, PX, xl, xu)
        F = sphere(X)
        PX, PF, _ = greedy_memory(X, F, None, PX, PF, None)
        P = update_distinct_pool(P[0], P[1], None, X, F, None)
        if rng.random() < q:
            X = midpoint_repair(random_difference_mutation(PX, rng=rng), PX, xl, xu)
            F = sphere(X)
            PX, PF, _ = greedy_memory(X, F, None, PX, PF, None)
            P = update_distinct_pool(P[0], P[1], None, X, F, None)
    return PF.min()


def loop_pso(T, rng, xl, xu, modified=False):
    X = uniform_population(N, xl, xu, rng=rng)
    F = sphere(X)
    V, vmax = np.zeros_like(X), 0.2 * (xu - xl)
    PX, PF = X, F
    for _ in range(1, T):
        g = PX[best_index(PF, None)]
        if modified:
            f_mean = sphere(PX.sum(axis=0, keepdims=True) / N)
            V = mpso_velocity(V, X, PX, g, is_better(f_mean, None, F, None), w=0.8, c1=1.493,
                              c2=1.493, rng=rng)
        else:
            V = pso_velocity(V, X, PX, g, w=0.8, c1=1.493, c2=1.493, rng=rng)
        V = clamp_velocity(V, vmax)
        X = clip_to_bounds(X + V, xl, xu)
        F = sphere(X)
        PX, PF, _ = greedy_memory(X, F, None, PX, PF, None)
    return PF.min()


def best_time(fn, repeats: int) -> float:
    times = []
    for r in range(repeats):
        t0 = time.perf_counter()
        fn(r)
        times.append(time.perf_counter() - t0)
    return min(times)


def per_generation(run, T: int, repeats: int) -> tuple[float, float]:
    """Marginal seconds per generation and the one-time cost, from runs of T and 1 gens."""
    t_long = best_time(lambda r: run(T, r), repeats)
    t_one = best_time(lambda r: run(1, r), repeats)
    return (t_long - t_one) / (T - 1), t_one


def section_a(T: int, repeats: int) -> None:
    print(f"(a) per-generation cost, N={N}, dim={D}, {T} generations, best of {repeats}; the loop "
          "calls the same kernels and a raw numpy sphere (no pymoo)")
    print(f"{'algorithm':<12}{'moik us/gen':>13}{'loop us/gen':>13}{'ratio':>8}"
          f"{'moik setup ms':>15}")
    xl, xu, problem = np.full(D, LO), np.full(D, HI), Sphere()
    cases = [
        ("EOSMA q=1", lambda: EOSMA(pop_size=N, q=1.0), lambda T, rng: loop_eosma(T, rng, xl, xu)),
        ("EOSMA q=0", lambda: EOSMA(pop_size=N, q=0.0, a1=1.0),
         lambda T, rng: loop_eosma(T, rng, xl, xu, q=0.0, a1=1.0)),
        ("EO", lambda: EO(pop_size=N), lambda T, rng: loop_eo(T, rng, xl, xu)),
        ("SMA", lambda: SMA(pop_size=N), lambda T, rng: loop_sma(T, rng, xl, xu)),
        ("PSO", lambda: PSO(pop_size=N), lambda T, rng: loop_pso(T, rng, xl, xu)),
        ("m-PSO", lambda: MPSO(pop_size=N), lambda T, rng: loop_pso(T, rng, xl, xu, True)),
    ]
    for name, make, loop in cases:
        g_moik, setup = per_generation(
            lambda T, r, m=make: minimize(problem, m(), ("n_gen", T), seed=r), T, repeats)
        g_loop, _ = per_generation(
            lambda T, r, lp=loop: lp(T, np.random.default_rng(r)), T, repeats)
        print(f"{name:<12}{g_moik * 1e6:13.1f}{g_loop * 1e6:13.1f}{g_moik / g_loop:8.2f}"
              f"{setup * 1e3:15.2f}")


def section_b(repeats: int, n_targets: int = 5) -> None:
    robot = get_robot("eosma7-m")
    targets = random_reachable_targets(robot, n_targets, seed=2022)
    cases = [  # label, scenario, T, problem, compiled FK, paper s
        ("1 position", 1, 500, lambda t: PositionIK(robot, t.position), robot.fk_position,
         0.0567),
        ("2 pose Eq. 26", 2, 1000,
         lambda t: PoseIK(robot, t, weights=(0.5, 0.5), orientation="eosma-euler"), robot.fk,
         0.3608),
    ]
    print(f"\n(b) one EOSMA run vs FK of the run's poses, eosma7-m, {n_targets} random targets, "
          f"{repeats} interleaved repeats, medians")
    print(f"{'scenario':<16}{'N':>5}{'T':>6}{'poses':>8}{'run s':>9}{'moik FK s':>11}"
          f"{'numpy FK s':>12}{'run/numpy':>11}{'goal':>6}{'per N*T':>9}{'paper s':>9}")
    for label, number, T, make, fk, paper in cases:
        problems = [make(t) for t in targets]
        N = EOSMA.scenario(number).pop_size
        res = minimize(problems[0], EOSMA.scenario(number), ("n_gen", T + 1), seed=0)
        n_eval, n_batches = res.algorithm.evaluator.n_eval, -(-res.algorithm.evaluator.n_eval // N)
        Q = robot.random_q(N, rng=np.random.default_rng(0))
        times = {"run": [], "fk": [], "numpy": []}
        for r in range(repeats):
            t0 = time.perf_counter()
            minimize(problems[r % n_targets], EOSMA.scenario(number), ("n_gen", T + 1),
                     seed=r)
            times["run"].append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            for _ in range(n_batches):
                fk(Q)
            times["fk"].append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            for _ in range(n_batches):
                fk_reference(robot, Q)
            times["numpy"].append(time.perf_counter() - t0)
        run, t_fk, t_np = (float(np.median(times[k])) for k in ("run", "fk", "numpy"))
        per_nt = run / (t_np * N * T / (n_batches * N))
        print(f"{label:<16}{N:5d}{T:6d}{n_eval:8d}{run:9.4f}{t_fk:11.4f}{t_np:12.4f}"
              f"{run / t_np:11.2f}{0.8:6.1f}{per_nt:9.2f}{paper:9.4f}")
    print("    'poses': the run's evaluations (scenario 2's mutation doubles them: 2 N per "
          "iteration);\n    'per N*T': run / numpy FK of N*T poses instead.")


def section_c(n_targets: int) -> None:
    print(f"\n(c) seconds per IK solve, EOSMA on eosma7, {n_targets} random reachable targets; "
          "'s/run': one run; 's/solve': the paper's protocol (re-run until f < 1e-6, at most "
          "10 runs)")
    cm = get_robot("eosma7")
    m = get_robot("eosma7-m")  # Table 1 as printed (m): the unit of Tables 5 and 7
    print(f"{'scenario':<30}{'s/run':>8}{'s/solve':>9}{'paper s':>9}{'goal s':>8}{'eval ms':>9}"
          f"{'1 run ok':>9}{'solved':>8}{'worst f':>10}")
    for label, number, robot, T, paper, goal, make in [
        ("1 position, cm, T=500", 1, cm, 500, 0.0567, 0.015,
         lambda r, t: PositionIK(r, t.position)),
        ("2 pose Eq.26, cm, T=1000", 2, cm, 1000, 0.3608, 0.08,
         lambda r, t: PoseIK(r, t, weights=(0.5, 0.5), orientation="eosma-euler")),
        ("2 pose Eq.26, m, T=1000", 2, m, 1000, 0.3608, 0.08,
         lambda r, t: PoseIK(r, t, weights=(0.5, 0.5), orientation="eosma-euler")),
    ]:
        targets = random_reachable_targets(robot, n_targets, seed=2022)
        minimize(make(robot, targets[0]), EOSMA.scenario(number), ("n_gen", 5), seed=0)  # warm
        run_t, solve_t, first, final = [], [], [], []
        for i, target in enumerate(targets):
            problem = make(robot, target)
            t0 = time.perf_counter()
            res = minimize(problem, EOSMA.scenario(number), ("n_gen", T + 1), seed=i)
            run_t.append(time.perf_counter() - t0)
            first.append(res.F[0])
            out = solve_until_success(problem, lambda n=number: EOSMA.scenario(n),
                                      ("n_gen", T + 1),
                                      seed=i)
            solve_t.append(out.total_time)
            final.append(out.best_f)
        X = robot.random_q(EOSMA.scenario(number).pop_size, rng=np.random.default_rng(0))
        t_eval = best_time(lambda r, p=problem, X=X: p.evaluate(X), 200) * 1e3
        first, final = np.array(first), np.array(final)
        print(f"{label:<30}{np.mean(run_t):8.4f}{np.mean(solve_t):9.4f}{paper:9.4f}{goal:8.3f}"
              f"{t_eval:9.3f}{np.mean(first < 1e-6):9.0%}{np.mean(final < 1e-6):8.0%}"
              f"{final.max():10.2e}")


def _mealpy_run(name: str, f, lb, ub, epochs: int, seed: int) -> float:
    import mealpy

    model = {"EO": lambda: mealpy.EO.OriginalEO(epoch=epochs, pop_size=N),
             "SMA": lambda: mealpy.SMA.OriginalSMA(epoch=epochs, pop_size=N, p_t=0.03),
             "PSO": lambda: mealpy.PSO.OriginalPSO(epoch=epochs, pop_size=N, c1=1.493,
                                                   c2=1.493, w=0.8)}[name]()
    problem = {"obj_func": f, "bounds": mealpy.FloatVar(lb=lb, ub=ub), "minmax": "min",
               "log_to": None}
    t0 = time.perf_counter()
    model.solve(problem, seed=seed)
    return time.perf_counter() - t0


def section_d(epochs: int) -> None:
    print(f"\n(d) moik vs mealpy 3.0.3, N={N}, {epochs} iterations, one run each")
    try:
        import mealpy  # noqa: F401
    except ImportError:
        print("    skipped: mealpy is not installed; pip install mealpy==3.0.3 "
              "(extra 'bench-mealpy')")
        return
    robot = get_robot("eosma7")
    problems = [("sphere 7-D", Sphere()),
                ("eosma7 position IK",
                 PositionIK(robot, random_reachable_targets(robot, 1, seed=5)[0].position))]
    print(f"{'problem':<20}{'algorithm':<10}{'moik s':>9}{'mealpy s':>10}{'speed-up':>10}")
    for label, problem in problems:
        def f(x, p=problem):
            return float(p.evaluate(np.asarray(x)[None])[0, 0])

        for name, algo in [("EO", EO), ("SMA", SMA), ("PSO", PSO)]:
            t0 = time.perf_counter()
            minimize(problem, algo(pop_size=N), ("n_gen", epochs), seed=1)
            t_moik = time.perf_counter() - t0
            t_mealpy = _mealpy_run(name, f, problem.xl, problem.xu, epochs, seed=1)
            print(f"{label:<20}{name:<10}{t_moik:9.3f}{t_mealpy:10.2f}{t_mealpy / t_moik:9.0f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sections", nargs="*", metavar="SECTION",
                        help="sections to run, of a b c d (all by default)")
    parser.add_argument("--quick", action="store_true", help="a short smoke run")
    parser.add_argument("--out", help=OUT_HELP)
    args = parser.parse_args()
    quick, only = args.quick, args.sections
    unknown = sorted(set(only) - set(SECTIONS))
    if unknown:
        parser.error(f"sections are {', '.join(SECTIONS)}; got {', '.join(unknown)}")
    with table_output(args.out):
        load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
        print(f"numpy {np.__version__}, {platform.processor() or platform.machine()}, "
              f"{os.cpu_count()} CPUs, load average {load:.2f}, {time.strftime('%Y-%m-%d %H:%M')}")
        if not only or "a" in only:
            section_a(T=300 if quick else 1000, repeats=3 if quick else 7)
        if not only or "b" in only:
            section_b(repeats=5 if quick else 21)
        if not only or "c" in only:
            section_c(n_targets=5 if quick else 20)
        if not only or "d" in only:
            section_d(epochs=100 if quick else 1000)


if __name__ == "__main__":
    main()
