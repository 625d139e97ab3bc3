"""EOSMA paper, scenario 1: position-only IK of 100 random reachable targets.

Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3:
Table 5 and Figs. 7-11. N=50, T=500 (Table 3 caption); a run is solved when its
error is below 1e-6, else the algorithm solves again, at most 10 runs (the
re-solve protocol); Wilcoxon rank-sum of EOSMA vs each algorithm (Fig. 11).
EOSMA uses the scenario 1 preset q=0, a1=1. Baselines marked optional are
included when registered (every baseline of the paper is registered); their
parameters are their classes' defaults, which follow Table 3.
The arm is ``eosma7-m`` (Table 1 in metres): the table's errors are in metres.
"""

_BASELINES = ["mrfo", "mpa", "pfa", "fpa", "gbo", "tlbo", "hho", "igwo", "psogsa", "code",
              "mtde", "sass"]

EXPERIMENT = {
    "name": "eosma-table5",
    "title": "EOSMA scenario 1: position only, 100 random reachable targets",
    "source": "Yin et al. 2022 (EOSMA), Table 5, Figs. 7-11",
    "robot": "eosma7-m",
    "problem": {"kind": "position"},
    "targets": {"kind": "random", "n": 100, "seed": 5, "with_orientation": False},
    "algorithms": [
        {"name": "eosma", "params": {"q": 0.0, "a1": 1.0}},
        {"name": "sma"},
        {"name": "eo"},
        {"name": "de", "params": {"F": 0.5, "CR": 0.9}},
        *[{"name": n, "optional": True} for n in _BASELINES],
        {"name": "pso"},
        {"name": "m-pso"},
    ],
    "pop_size": 50,
    "iterations": 500,
    "runs": 1,
    "seed": 2022,
    "protocol": {"threshold": 1e-6, "max_failures": 10},
    "success_threshold": 1e-6,
    "analyses": ["summary", "ranksum"],
    "proposed": "eosma",
    "paper": {
        "citation": "EOSMA paper, Table 5 (position error, m; MATLAB on an i7-9700)",
        "summary": {
            "eosma": {"worst": 7.85e-16, "mean": 2.64e-17, "best": 0.0, "std": 9.93e-17,
                      "time": 0.0567},
            "sma": {"worst": 3.09e-02, "mean": 9.57e-04, "best": 4.17e-05, "std": 3.27e-03,
                    "time": 0.5382},
            "eo": {"worst": 7.99e-07, "mean": 2.45e-08, "best": 0.0, "std": 1.06e-07,
                   "time": 0.0649},
            "mrfo": {"worst": 9.92e-07, "mean": 1.37e-07, "best": 0.0, "std": 2.27e-07,
                     "time": 0.1302},
            "mpa": {"worst": 4.28e-07, "mean": 7.75e-08, "best": 1.43e-08, "std": 6.73e-08,
                    "time": 0.1284},
            "pfa": {"worst": 2.66e-07, "mean": 5.73e-09, "best": 0.0, "std": 3.43e-08,
                    "time": 0.0812},
            "fpa": {"worst": 5.99e-02, "mean": 6.57e-03, "best": 3.26e-12, "std": 9.19e-03,
                    "time": 1.2808},
            "de": {"worst": 9.93e-07, "mean": 2.97e-07, "best": 5.00e-14, "std": 2.80e-07,
                   "time": 0.2809},
            "gbo": {"worst": 1.10e-11, "mean": 2.54e-13, "best": 0.0, "std": 1.48e-12,
                    "time": 0.3058},
            "tlbo": {"worst": 2.42e-03, "mean": 2.23e-04, "best": 9.12e-09, "std": 4.56e-04,
                     "time": 1.6861},
            "hho": {"worst": 3.99e-02, "mean": 1.64e-03, "best": 9.03e-12, "std": 4.54e-03,
                    "time": 1.7444},
            "igwo": {"worst": 1.35e-02, "mean": 2.84e-03, "best": 3.86e-05, "std": 3.26e-03,
                     "time": 5.5963},
            "psogsa": {"worst": 3.13e-13, "mean": 1.57e-13, "best": 4.37e-14, "std": 6.78e-14,
                       "time": 0.2084},
            "code": {"worst": 2.76e-01, "mean": 5.79e-02, "best": 3.11e-03, "std": 5.71e-02,
                     "time": 0.4410},
            "mtde": {"worst": 6.15e-03, "mean": 1.07e-03, "best": 1.27e-05, "std": 1.16e-03,
                     "time": 2.1214},
            "sass": {"worst": 1.01e-03, "mean": 1.99e-04, "best": 7.04e-11, "std": 2.28e-04,
                     "time": 1.2234},
        },
    },
    "quick": {"targets": {"n": 3}, "pop_size": 10, "iterations": 15,
              "protocol": {"max_failures": 2}},
}
