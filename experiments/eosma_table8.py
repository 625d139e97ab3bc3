"""EOSMA paper, multi-objective IK: MOEOSMA and MO baselines at two poses.

Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3:
Table 8 and Figs. 17-18. Objectives (position error, Eq. 30 Euler error with
the Eq. 26 angles); P1 = (-25, 100, 50, 0, 0, 0) (unreachable) and
P2 = (50, -25, 75, 0, 0, 0) (reachable), printed in cm and deg, computed in
metres: arm ``eosma7-m``, P1 = (-0.25, 1.00, 0.50) m, P2 = (0.50, -0.25, 0.75) m.
The paper's HV reference points settle the unit: P1's (2.088567, 2.466816)
box is nearly filled by the paper's fronts (MOEOSMA HV 5.076 of 5.152), which
needs position errors of a few hundredths; the P1 front keeps 0.0075-0.14 of
position error over 0.03-0.91 rad, i.e. HV ~5.0 in metres but ~2.2 in cm
(the cm reading was measured first: every algorithm at 40-50 % of the paper's
P1 values). P2 is reachable either way (HV = the whole box). N=100, T=1000, archive
100, 20 runs; hypervolume with the paper's reference points (text before
Table 8); Friedman mean ranks over the 20 runs (run j of every algorithm uses
the same seed). Baselines marked optional come with the baselines issue; the
pymoo algorithms registered today (NSGA-II, MOEA/D, SMS-EMOA, MOPSO-CD) and
MO-m-PSO are compared as well (pymoo's ``res.F`` is their final non-dominated set).
"""

_PAPER_BASELINES = ["mosma", "mopso", "mompa", "moalo", "moda", "mogwo", "momvo", "mssa"]

EXPERIMENT = {
    "name": "eosma-table8",
    "title": "MOEOSMA vs multi-objective algorithms at poses P1 (unreachable) and P2",
    "source": "Yin et al. 2022 (EOSMA), Table 8, Figs. 17-18",
    "robot": "eosma7-m",
    "problem": {"kind": "bi-objective", "orientation": "eosma-euler"},
    "targets": {"kind": "fixed", "points": [
        {"name": "P1", "position": [-0.25, 1.00, 0.50], "euler_deg": [0, 0, 0],
         "convention": "eosma-euler", "hv_ref_point": [2.088567, 2.466816]},
        {"name": "P2", "position": [0.50, -0.25, 0.75], "euler_deg": [0, 0, 0],
         "convention": "eosma-euler", "hv_ref_point": [1.695669, 2.524178]},
    ]},
    "algorithms": [
        {"name": "moeosma"},
        *[{"name": n, "optional": True} for n in _PAPER_BASELINES],
        {"name": "moead"},
        {"name": "mo-m-pso"},
        {"name": "nsga2"},
        {"name": "sms-emoa"},
        {"name": "mopso-cd"},
    ],
    "pop_size": 100,
    "archive_size": 100,
    "iterations": 1000,
    "runs": 20,
    "seed": 2022,
    "analyses": ["friedman-hv", "reference-front"],
    "paper": {
        "citation": "EOSMA paper, Table 8 (HV, Friedman rank, MATLAB time)",
        "hv": {
            "P1": {
                "moeosma": {"mean": 5.07631, "std": 0.02007, "fr": 1.40, "rank": 1,
                            "time": 5.87559},
                "mosma": {"mean": 4.65143, "std": 0.06950, "fr": 9.80, "rank": 10,
                          "time": 41.00294},
                "mopso": {"mean": 5.00599, "std": 0.04402, "fr": 4.60, "rank": 4,
                          "time": 28.82177},
                "mompa": {"mean": 5.04500, "std": 0.02733, "fr": 2.95, "rank": 2,
                          "time": 3.98753},
                "moalo": {"mean": 4.86302, "std": 0.09082, "fr": 7.95, "rank": 9,
                          "time": 25.23976},
                "moda": {"mean": 4.81951, "std": 0.22506, "fr": 7.90, "rank": 8,
                         "time": 119.88871},
                "mogwo": {"mean": 4.94830, "std": 0.08276, "fr": 5.95, "rank": 6,
                          "time": 138.56085},
                "momvo": {"mean": 5.02802, "std": 0.04602, "fr": 3.50, "rank": 3,
                          "time": 3.60248},
                "mssa": {"mean": 5.00469, "std": 0.05326, "fr": 4.80, "rank": 5,
                         "time": 5.12301},
                "moead": {"mean": 4.88152, "std": 0.26105, "fr": 6.15, "rank": 7,
                          "time": 249.77852},
            },
            "P2": {
                "moeosma": {"mean": 4.28017, "std": 3.17e-13, "fr": 1.00, "rank": 1,
                            "time": 0.81779},
                "mosma": {"mean": 4.00487, "std": 0.05168, "fr": 9.70, "rank": 10,
                          "time": 38.63682},
                "mopso": {"mean": 4.22408, "std": 0.07739, "fr": 5.75, "rank": 6,
                          "time": 25.27879},
                "mompa": {"mean": 4.27983, "std": 0.00148, "fr": 2.80, "rank": 2,
                          "time": 1.41943},
                "moalo": {"mean": 4.19377, "std": 0.08250, "fr": 7.10, "rank": 8,
                          "time": 25.87101},
                "moda": {"mean": 4.16979, "std": 0.09992, "fr": 8.10, "rank": 9,
                         "time": 152.13011},
                "mogwo": {"mean": 4.24412, "std": 0.03762, "fr": 5.45, "rank": 5,
                          "time": 67.21598},
                "momvo": {"mean": 4.25582, "std": 0.02288, "fr": 5.30, "rank": 4,
                          "time": 2.35827},
                "mssa": {"mean": 4.26781, "std": 0.02584, "fr": 3.60, "rank": 3,
                         "time": 2.65555},
                "moead": {"mean": 4.22517, "std": 0.08037, "fr": 6.20, "rank": 7,
                          "time": 229.49681},
            },
        },
    },
    "quick": {"pop_size": 10, "archive_size": 10, "iterations": 10, "runs": 2},
}
