"""Per-generation cost of the array fast path against pymoo's Evaluator path.

Run: ``.venv/bin/python benchmarks/evaluator_path.py [--gens N]``

moik's array-state algorithms evaluate through ``problem.evaluate`` on the array (the
fast path) unless something is attached to pymoo's Evaluator (an Evaluator subclass or
callback, ``archive=``, ``requires_kwargs=True`` problems), when every batch goes
through ``evaluator.eval`` on a ``Population`` (moik.algorithms.array_base). This
prints the median per-generation time of both paths (interleaved repeats, N=100,
7 variables, a vectorized sphere / ZDT1) and their ratio.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from pymoo.core.evaluator import Evaluator
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import EO, MOEOSMA, PSO


class Sphere(Problem):
    def __init__(self):
        super().__init__(n_var=7, n_obj=1, xl=-100.0, xu=100.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = (X * X).sum(axis=1)


def per_generation(make, problem, gens: int, attached: bool) -> float:
    kw = {"evaluator": Evaluator(callback=lambda pop: None)} if attached else {}
    t0 = time.perf_counter()
    minimize(problem, make(**kw), ("n_gen", gens), seed=1)
    return (time.perf_counter() - t0) / gens


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gens", type=int, default=300)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    cases = [("PSO", lambda **k: PSO(pop_size=100, **k), Sphere()),
             ("EO", lambda **k: EO(pop_size=100, **k), Sphere()),
             ("MOEOSMA", lambda **k: MOEOSMA(pop_size=100, **k), get_problem("zdt1", n_var=7))]
    print(f"{'algorithm':<10} {'fast path us/gen':>17} {'Evaluator us/gen':>17} {'ratio':>6}")
    for name, make, problem in cases:
        per_generation(make, problem, 5, False)  # warm (compile)
        fast, slow = [], []
        for _ in range(args.repeats):
            fast.append(per_generation(make, problem, args.gens, False))
            slow.append(per_generation(make, problem, args.gens, True))
        f, s = np.median(fast) * 1e6, np.median(slow) * 1e6
        print(f"{name:<10} {f:17.1f} {s:17.1f} {s / f:6.2f}")


if __name__ == "__main__":
    main()
