"""Speed of moik's algorithms, printed side by side.

Run: ``.venv/bin/python benchmarks/algorithms.py [--quick]``

(a) Per-generation cost of each algorithm run through ``pymoo.optimize.minimize``
    against a plain numpy loop of the same update rule (the same kernel
    functions, a raw vectorized sphere, no pymoo), N=100, dim=7. Goal: ratio <= 1.3.
(b) Seconds per IK solve with EOSMA on the ``eosma7`` arm: scenario 1 (position,
    N=50, T=500) and scenario 2 (pose with the Eq. 26 Euler error, N=100,
    T=1000), one run and with the paper's re-solve protocol; scenario 2 both
    with the catalog arm (cm) and with Table 1's lengths in metres (the unit
    that reproduces Table 7, see tests/algorithms/soo/test_eosma.py). The
    paper's MATLAB figures: 0.0567 s and 0.3608 s; goals 0.015 s and 0.08 s.
(c) moik EO/SMA/PSO against mealpy 3.0.3 OriginalEO/OriginalSMA/OriginalPSO,
    N=100, 1000 iterations, on the 7-D sphere and on eosma7 position IK
    (``pip install mealpy==3.0.3``, the ``bench`` extra).
"""

from __future__ import annotations

import sys
import time

import numpy as np
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

N, D, LO, HI = 100, 7, -10.0, 10.0


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


def section_b(n_targets: int) -> None:
    print(f"\n(b) seconds per IK solve, EOSMA on eosma7, {n_targets} random reachable targets; "
          "'s/run': one run; 's/solve': the paper's protocol (re-run until f < 1e-6, at most "
          "10 runs)")
    try:
        from moik.experiments.protocol import solve_until_success
        from moik.problems import PoseIK, PositionIK, random_reachable_targets
        from moik.robots import get_robot
    except ImportError as exc:  # robots/problems not installed in this checkout
        print(f"    skipped: {exc}")
        return
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
        run_t, solve_t, first, final = [], [], [], []
        for i, target in enumerate(targets):
            problem = make(robot, target)
            t0 = time.perf_counter()
            res = minimize(problem, EOSMA.scenario(number), ("n_gen", T), seed=i)
            run_t.append(time.perf_counter() - t0)
            first.append(res.F[0])
            out = solve_until_success(problem, lambda n=number: EOSMA.scenario(n), ("n_gen", T),
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


def section_c(epochs: int) -> None:
    print(f"\n(c) moik vs mealpy 3.0.3, N={N}, {epochs} iterations, one run each")
    try:
        import mealpy  # noqa: F401
    except ImportError:
        print("    skipped: mealpy is not installed; pip install mealpy==3.0.3 (extra 'bench')")
        return
    problems = [("sphere 7-D", Sphere())]
    try:
        from moik.problems import PositionIK, random_reachable_targets
        from moik.robots import get_robot

        robot = get_robot("eosma7")
        problems.append(("eosma7 position IK",
                         PositionIK(robot, random_reachable_targets(robot, 1, seed=5)[0].position)))
    except ImportError as exc:
        print(f"    IK problem skipped: {exc}")
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
    quick = "--quick" in sys.argv
    section_a(T=300 if quick else 1000, repeats=3 if quick else 7)
    section_b(n_targets=5 if quick else 20)
    section_c(epochs=100 if quick else 1000)


if __name__ == "__main__":
    main()
