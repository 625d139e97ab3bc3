"""EOSMA paper, scenario 2: position and posture, 100 random reachable poses.

Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3:
Table 7 and Figs. 12-16. Objective Eq. 28, w1 = w2 = 0.5, with the Eq. 26
Euler angles and the Eq. 30 L2 angle error (``eosma-euler``); N=100, T=1000;
the same re-solve protocol as scenario 1 (threshold 1e-6, at most 10 runs).
EOSMA uses the scenario 2 preset q=1, a1=2 (its defaults).
The arm is ``eosma7-m`` (Table 1 in metres): Eq. 28 adds metres to radians,
as the paper's Table 7 does.
"""

_BASELINES = ["mrfo", "mpa", "pfa", "fpa", "gbo", "tlbo", "hho", "igwo", "psogsa", "code",
              "mtde", "sass"]

EXPERIMENT = {
    "name": "eosma-table7",
    "title": "EOSMA scenario 2: position and posture, 100 random reachable poses",
    "source": "Yin et al. 2022 (EOSMA), Table 7, Figs. 12-16",
    "robot": "eosma7-m",
    "problem": {"kind": "pose", "orientation": "eosma-euler", "weights": [0.5, 0.5]},
    "targets": {"kind": "random", "n": 100, "seed": 7, "with_orientation": True},
    "algorithms": [
        {"name": "eosma", "params": {"q": 1.0, "a1": 2.0}},
        {"name": "sma"},
        {"name": "eo"},
        {"name": "de", "params": {"F": 0.5, "CR": 0.9}},
        *[{"name": n, "optional": True} for n in _BASELINES],
        {"name": "pso"},
        {"name": "m-pso"},
    ],
    "pop_size": 100,
    "iterations": 1000,
    "runs": 1,
    "seed": 2022,
    "protocol": {"threshold": 1e-6, "max_failures": 10},
    "success_threshold": 1e-6,
    "analyses": ["summary", "ranksum"],
    "proposed": "eosma",
    "paper": {
        "citation": "EOSMA paper, Table 7 (Eq. 28 objective; MATLAB on an i7-9700)",
        "summary": {
            "eosma": {"worst": 5.55e-17, "mean": 7.79e-18, "best": 0.0, "std": 1.21e-17,
                      "time": 0.360804},
            "sma": {"worst": 0.242342, "mean": 0.043938, "best": 0.001052, "std": 0.050096,
                    "time": 1.680179},
            "eo": {"worst": 0.289362, "mean": 0.02786, "best": 5.82e-11, "std": 0.047801,
                   "time": 2.207461},
            "mrfo": {"worst": 0.26697, "mean": 0.009398, "best": 1.99e-16, "std": 0.035825,
                     "time": 1.395682},
            "mpa": {"worst": 9.71e-07, "mean": 4.55e-07, "best": 4.01e-08, "std": 2.54e-07,
                    "time": 0.424897},
            "pfa": {"worst": 0.23774, "mean": 0.020017, "best": 2.95e-13, "std": 0.044404,
                    "time": 2.057285},
            "fpa": {"worst": 0.230746, "mean": 0.037691, "best": 6.58e-05, "std": 0.045514,
                    "time": 9.616893},
            "de": {"worst": 1.28e-12, "mean": 1.04e-13, "best": 5.26e-16, "std": 1.95e-13,
                   "time": 0.896265},
            "gbo": {"worst": 0.229208, "mean": 0.007624, "best": 0.0, "std": 0.035906,
                    "time": 4.995488},
            "tlbo": {"worst": 0.053045, "mean": 0.004314, "best": 8.53e-11, "std": 0.009956,
                     "time": 5.640442},
            "hho": {"worst": 0.473011, "mean": 0.147295, "best": 0.005506, "std": 0.10784,
                    "time": 8.849817},
            "igwo": {"worst": 0.101893, "mean": 0.0027, "best": 0.000123, "std": 0.010879,
                     "time": 22.94664},
            "psogsa": {"worst": 0.410281, "mean": 0.07595, "best": 1.76e-13, "std": 0.091469,
                       "time": 12.72971},
            "code": {"worst": 0.117581, "mean": 0.027037, "best": 0.005138, "std": 0.0198,
                     "time": 7.604563},
            "mtde": {"worst": 0.016585, "mean": 0.000283, "best": 1.85e-09, "std": 0.002008,
                     "time": 2.485424},
            "sass": {"worst": 8.09e-17, "mean": 5.35e-18, "best": 0.0, "std": 1.06e-17,
                     "time": 0.61688},
        },
    },
    "quick": {"targets": {"n": 3}, "pop_size": 10, "iterations": 15,
              "protocol": {"max_failures": 2}},
}
