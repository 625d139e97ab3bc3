"""I-BES paper, Tables 14-17: the spring and pressure vessel design problems.

Zhao et al., Biomimetics 9, 627 (2024), Section 5.3: N=30, T=500, 30 runs,
Table 1's parameters. Constraints: every algorithm ranks by feasibility first
(Deb's rules, :mod:`moik.problems.benchmarks.engineering`); a run whose best
design violates a constraint counts as infeasible and is left out of the
statistics (the ``feasible runs`` column). Pressure vessel with the paper's
bounds and continuous thicknesses (its best design is not on the 0.0625 grid).
The paper's spring values (2.6952e6 at d = D = 0.25, N = 15) are penalized
values at an infeasible corner, not weights (best known weight 0.012665):
they are shown but cannot be compared. Full size: 2 x 6 x 30 = 360 trials.

Not reproduced: the paper's ranking (I-BES better than BES on both problems).
With the feasibility-first rules here BES beats I-BES on both (the rank-sum
table's comparison with the paper's means); the finding recorded on main is
that a penalty rule does not reverse it either (not rerun in this config, which
has no penalty mode).
"""

_LABELS = ["ibes", "bes", "pso", "fa", "mtsa", "cpso-at"]
# Tables 15 and 17: (best, worst, mean, std) of I-BES, BES, PSO, FA, MTSA, CPSO-AT.
_TABLE15 = [(2.6952e6, 4.6026e7, 8.1552e6, 1.1503e7), (2.8151e6, 6.3855e7, 2.5655e7, 2.0781e7),
            (2.6952e6, 2.6953e6, 2.6952e6, 1.7202e2), (2.7875e6, 6.8007e7, 1.1593e7, 1.5486e7),
            (2.6952e6, 2.0086e7, 6.2766e6, 5.1281e6), (2.6973e6, 2.9661e6, 2.7765e6, 7.0300e4)]
_TABLE17 = [(5.8862e3, 1.1489e5, 2.0310e4, 2.4556e4), (6.4930e3, 2.3109e5, 3.8668e4, 5.3125e4),
            (6.1251e3, 4.1947e5, 4.1409e4, 8.9159e4), (6.4065e3, 7.5295e5, 1.5491e5, 1.9404e5),
            (6.0799e3, 7.5439e4, 1.2482e4, 1.4948e4), (1.1426e4, 4.7605e4, 2.1284e4, 8.9094e3)]


def _rows(table):
    return {lab: {"best": v[0], "worst": v[1], "mean": v[2], "std": v[3]}
            for lab, v in zip(_LABELS, table, strict=True)}


EXPERIMENT = {
    "name": "ibes-engineering",
    "title": "I-BES: tension/compression spring and pressure vessel design, 30 runs",
    "source": "Zhao et al. 2024 (I-BES), Section 5.3, Tables 14-17",
    "problem": {"kind": "benchmark", "names": ["spring", "pressure_vessel"]},
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
    "seed": 53,
    "analyses": ["per-target", "per-target-ranksum"],
    "proposed": "ibes",
    "paper": {
        "citation": "I-BES paper, Tables 15 (spring; penalized values) and 17 (vessel cost)",
        "notes": ["the paper ranks I-BES above BES on both problems; that ranking is not "
                  "reproduced here with feasibility-first (Deb's) rules (rank-sum table), "
                  "nor, per the finding recorded on main, with a penalty rule"],
        "per_target": {"spring": _rows(_TABLE15), "pressure_vessel": _rows(_TABLE17)},
    },
    "quick": {"pop_size": 8, "iterations": 10, "runs": 2},
}
