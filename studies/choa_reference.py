"""ChOA on pymoo's sphere: moik's ChOA beside the port of Khishe & Mosavi's ``chimp.m``.

Run: ``.venv/bin/python -m studies.choa_reference [--seeds 5] [--iterations 1000]`` from
the repository root. pymoo's single-objective quality test wants 1e-5 on its 10-D sphere
(bounds [0, 1], optimum at 0.5); moik's ``choa`` ends near 1e-2 (tests/algorithms/
test_pymoo_contract.py marks it a known failure). Both run N = 50 (the MChOA paper's)
for the same iterations, seeds 0..n-1; the port (reference/choa.py) keeps the code's
quirks (a constant chaotic value 0.7, a Driver that stays at zeros). Where both end at
the same order, the stall is the method's, not moik's.
"""

from __future__ import annotations

import argparse

import numpy as np
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import get_algorithm
from reference.choa import choa_reference


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--iterations", type=int, default=1000)
    args = parser.parse_args(argv)
    problem = get_problem("sphere")
    rows = []
    for seed in range(args.seeds):
        _, F, _ = choa_reference(problem, 50, args.iterations, np.random.default_rng(seed))
        res = minimize(problem, get_algorithm("choa"), ("n_gen", args.iterations + 1),
                       seed=seed)
        rows.append((float(F[0, 0]), float(res.F[0])))
        print(f"seed {seed}: chimp.m port {rows[-1][0]:.3g}, moik choa {rows[-1][1]:.3g}",
              flush=True)
    ref, moik = np.array(rows).T
    print(f"median: chimp.m port {np.median(ref):.3g}, moik choa {np.median(moik):.3g} "
          f"({args.seeds} seeds, N=50, T={args.iterations}; pymoo's test wants 1e-5)")


if __name__ == "__main__":
    main()
