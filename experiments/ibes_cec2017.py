"""I-BES paper, Tables 12-13: nine CEC2017 functions, six algorithms, rank-sum test.

Zhao et al., Biomimetics 9, 627 (2024), Section 5.2: D=30, bounds [-100, 100],
N=30, T=500, 30 independent runs, Table 1's parameters (PSO as the
``PSO.ibes()`` preset written as params, with N=30); best/mean/std (Table 12)
and the Wilcoxon rank-sum test of I-BES vs each at alpha 5% (Table 13; the
paper's text also says "signed-rank", its table and method are rank-sum). The
official functions and data come from minionpy, a C++ port of the official
``cec17_func.cpp`` (extra ``cec``). Full size:
9 functions x 6 algorithms x 30 runs = 1620 trials of 15,000 evaluations.
"""

_F = [3, 8, 9, 14, 15, 18, 19, 27, 30]
_LABELS = ["ibes", "bes", "pso", "fa", "mtsa", "cpso-at"]
# Table 12: per function, (best, mean, std) of I-BES, BES, PSO, FA, MTSA, CPSO-AT.
_TABLE12 = {
    3: [(1.43e4, 2.78e4, 8.05e3), (5.47e4, 8.59e4, 1.89e4), (5.66e4, 1.24e5, 5.96e4),
        (1.62e5, 2.92e5, 6.24e4), (7.39e4, 1.32e5, 3.22e4), (1.70e5, 2.65e5, 5.22e4)],
    8: [(9.57e2, 1.01e3, 2.60e1), (1.06e3, 1.14e3, 3.69e1), (9.36e2, 1.03e3, 4.40e1),
        (1.16e3, 1.28e3, 6.01e1), (1.02e3, 1.14e3, 4.70e1), (1.14e3, 1.23e3, 2.88e1)],
    9: [(4.07e3, 5.50e3, 6.42e2), (6.67e3, 1.09e4, 2.33e3), (3.47e3, 6.81e3, 2.44e3),
        (1.23e4, 1.96e4, 4.74e3), (1.21e4, 1.73e4, 2.63e3), (1.59e4, 2.15e4, 2.38e3)],
    14: [(1.63e3, 5.42e3, 5.35e3), (8.74e3, 2.17e5, 3.40e5), (1.87e3, 6.13e5, 1.97e6),
         (5.79e3, 3.11e6, 4.95e6), (4.91e3, 9.42e4, 1.18e5), (3.26e5, 1.91e6, 1.56e6)],
    15: [(4.46e3, 2.57e4, 2.53e4), (9.06e3, 3.74e8, 5.14e8), (8.79e3, 1.62e5, 1.43e5),
         (3.57e5, 1.07e9, 1.05e9), (8.51e4, 3.00e5, 1.20e5), (5.37e7, 6.41e8, 3.64e8)],
    18: [(1.77e4, 7.56e4, 4.21e4), (6.95e4, 4.17e6, 5.82e6), (3.92e4, 3.86e6, 6.12e6),
         (6.27e5, 2.92e7, 3.98e7), (8.90e4, 1.05e6, 1.16e6), (1.89e6, 1.74e7, 1.33e7)],
    19: [(4.01e3, 4.87e5, 1.92e6), (2.18e6, 4.84e8, 7.60e8), (2.52e4, 1.96e7, 5.50e7),
         (3.20e7, 2.11e9, 2.17e9), (6.72e5, 3.05e6, 1.35e6), (1.12e8, 6.69e8, 4.39e8)],
    27: [(3.20e3, 3.21e3, 6.83e1), (3.20e3, 3.25e3, 2.47e2), (3.28e3, 3.46e3, 1.40e2),
         (3.41e3, 3.63e3, 1.61e2), (3.35e3, 3.62e3, 2.32e2), (3.27e3, 3.31e3, 2.51e1)],
    30: [(6.54e3, 1.16e6, 2.17e6), (6.69e7, 6.54e8, 8.07e8), (3.63e5, 6.78e7, 2.52e8),
         (1.51e8, 9.83e8, 9.01e8), (6.39e5, 4.28e6, 3.57e6), (5.07e7, 3.71e8, 2.61e8)],
}
# Table 13: p-values of I-BES vs BES, PSO, FA, MTSA, CPSO-AT (R is "+" everywhere).
_TABLE13 = {
    3: (3.02e-11, 3.02e-11, 3.02e-11, 1.78e-10, 3.02e-11),
    8: (1.33e-10, 8.19e-1, 3.02e-11, 7.38e-10, 3.02e-11),
    9: (3.69e-11, 2.71e-1, 3.02e-11, 3.02e-11, 3.02e-11),
    14: (9.53e-7, 3.96e-8, 2.61e-10, 1.87e-7, 3.02e-11),
    15: (8.89e-10, 1.07e-7, 3.02e-11, 1.55e-9, 3.02e-11),
    18: (3.34e-11, 7.39e-11, 3.02e-11, 6.70e-11, 3.02e-11),
    19: (3.34e-11, 8.89e-10, 3.02e-11, 4.98e-11, 3.02e-11),
    27: (8.56e-4, 6.53e-8, 1.10e-8, 1.56e-8, 8.84e-7),
    30: (3.02e-11, 1.25e-7, 3.02e-11, 2.78e-7, 3.02e-11),
}

EXPERIMENT = {
    "name": "ibes-cec2017",
    "title": "I-BES: nine CEC2017 functions (D=30), six algorithms, 30 runs",
    "source": "Zhao et al. 2024 (I-BES), Section 5.2, Tables 12-13 (Fig. 19)",
    "problem": {"kind": "benchmark", "names": [f"cec2017_F{i}" for i in _F],
                "params": {"n_var": 30}},
    "requires": ["cec"],
    "algorithms": [
        {"name": "ibes"},
        {"name": "bes"},
        {"name": "pso", "params": {"w": 0.9, "c1": 1.4, "c2": 1.4, "vmax_rate": 0.5}},
        {"name": "fa"},
        {"name": "mtsa"},
        {"name": "cpso-at"},
    ],
    "pop_size": 30,
    "iterations": 500,
    "runs": 30,
    "seed": 2017,
    "analyses": ["per-target", "per-target-ranksum"],
    "proposed": "ibes",
    "paper": {
        "citation": "I-BES paper, Tables 12 (best/mean/std) and 13 (rank-sum p, R)",
        "per_target": {f"cec2017_F{i}": {lab: {"best": v[0], "mean": v[1], "std": v[2]}
                                         for lab, v in zip(_LABELS, rows, strict=True)}
                       for i, rows in _TABLE12.items()},
        "ranksum": {f"cec2017_F{i}": {lab: {"p": p, "R": "+"}
                                      for lab, p in zip(_LABELS[1:], ps, strict=True)}
                    for i, ps in _TABLE13.items()},
    },
    "quick": {"problem": {"names": ["cec2017_F3", "cec2017_F30"]}, "pop_size": 8, "iterations": 4,
              "runs": 2},
}
