"""Khishe & Mosavi's ChOA (``chimp.m``, "Chimp Optimization Algorithm (ChOA) source codes
version 1.0"), ported for a single-objective pymoo problem.

Read in github.com/abcdvvvv/MetaheuristicsAlgorithms.jl, ``src/algo/ChOA.jl`` (commit
11ecd215, a line-by-line Julia port of the MATLAB file, same control flow); the MATLAB
headers of the same code are in github.com/VG-TechCenter/Improved-Optimizers
(``改进黑猩猩算法/``). Quirks kept (noted inline): the chaotic value ``m = chaos(3, 1, 1)``
is the Gauss map's *first* value, 0.7, at every use; the leader update is an
``if/elseif`` chain whose Driver branch needs a fitness *above* the Driver's score, so
the Driver stays at its initial zeros; agents are evaluated one by one, in order, and
the leaders updated at once (no batch).
"""

from __future__ import annotations

import numpy as np


def choa_reference(problem, n: int, iterations: int, rng: np.random.Generator
                   ) -> tuple[np.ndarray, np.ndarray, int]:
    """Run the ChOA code on ``problem``; ``(best_x[None], best_f[None], n_eval)``."""
    lb, ub, dim = problem.xl.astype(float), problem.xu.astype(float), problem.n_var
    leaders = np.zeros((4, dim))  # Attacker, Barrier, Chaser, Driver (the code's zeros)
    scores = np.full(4, np.inf)
    X = rng.random((n, dim)) * (ub - lb) + lb  # initialization.m
    n_eval, T = 0, iterations
    for t in range(T):  # the code's l
        for i in range(n):
            X[i] = np.clip(X[i], lb, ub)  # the code's Flag4ub / Flag4lb
            fit = float(problem.evaluate(X[i][None])[0, 0])
            n_eval += 1
            a, b, c, d = scores
            if fit < a:
                scores[0], leaders[0] = fit, X[i]
            elif a < fit < b:
                scores[1], leaders[1] = fit, X[i]
            elif fit > a and fit > b and fit < c:
                scores[2], leaders[2] = fit, X[i]
            elif fit > a and fit > b and fit > c and fit > d:  # as published: never true
                scores[3], leaders[3] = fit, X[i]  # after the first (d = inf)
        f = 2 - t * (2 / T)
        cube, root = t ** 3 / T ** 3, t ** (1 / 3) / T ** (1 / 3)
        C1 = (1.95 - 2 * root, 1.95 - 2 * root, -2 * cube + 2.5, -2 * cube + 2.5)
        C2 = (2 * root + 0.5, 2 * cube + 0.5, 2 * root + 0.5, 2 * cube + 0.5)
        m = 0.7  # chaos(3, 1, 1): x(1) = 0.7, the map never iterated
        for i in range(n):
            for j in range(dim):
                total = 0.0
                for k in range(4):
                    r1, r2 = C1[k] * rng.random(), C2[k] * rng.random()
                    A, C = 2 * f * r1 - f, 2 * r2
                    total += leaders[k, j] - A * abs(C * leaders[k, j] - m * X[i, j])
                X[i, j] = total / 4
    return leaders[0][None].copy(), np.array([[scores[0]]]), n_eval
