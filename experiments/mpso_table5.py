"""MO-m-PSO paper, Section 5.1: Wilcoxon signed-rank of m-PSO vs PSO (SSA, CSA).

Rokbani et al., Appl. Sci. 12, 7091 (2022), DOI 10.3390/app12147091: Table 5
and Fig. 8. The Section 4.1 target (FK of (30, 60, 45, 60, 60) deg), position
error only; 50 agents, 500 iterations, 30 independent runs; run j of every
algorithm uses the same seed, so the samples are paired by run. SSA and CSA are
included when registered.
"""

EXPERIMENT = {
    "name": "mpso-table5",
    "title": "m-PSO vs PSO (and SSA, CSA when registered): Wilcoxon signed-rank, 30 runs",
    "source": "Rokbani et al. 2022 (MO-m-PSO), Section 5.1, Table 5, Fig. 8",
    "robot": "rokbani5",
    "problem": {"kind": "position"},
    "targets": {"kind": "fixed", "points": [{"name": "q=(30,60,45,60,60)",
                                              "fk_q_deg": [30, 60, 45, 60, 60]}]},
    "algorithms": [
        {"name": "m-pso", "params": {"w": 0.8, "c1": 1.493, "c2": 1.493}},
        {"name": "pso", "params": {"w": 0.8, "c1": 1.493, "c2": 1.493}},
        {"name": "ssa", "optional": True},
        {"name": "csa", "optional": True},
    ],
    "pop_size": 50,
    "iterations": 500,
    "runs": 30,
    "seed": 2022,
    "success_threshold": 1e-4,
    "analyses": ["signed-rank", "summary"],
    "proposed": "m-pso",
    "paper": {
        "citation": "MO-m-PSO paper, Table 5 (position error, 30 runs)",
        "signed_rank": {
            "pso": {"r_plus": 0, "r_minus": 465, "p": 3.01e-11, "best": "m-pso"},
            "ssa": {"r_plus": 30, "r_minus": 435, "p": 5.57e-10, "best": "m-pso"},
            "csa": {"r_plus": 0, "r_minus": 465, "p": 3.01e-11, "best": "m-pso"},
        },
    },
    "quick": {"pop_size": 10, "iterations": 15, "runs": 6},
}
