"""MO-m-PSO paper, Section 4.1: m-PSO on one reachable target, 30 runs.

Rokbani et al., Appl. Sci. 12, 7091 (2022), DOI 10.3390/app12147091: the target
is the FK of q = (30, 60, 45, 60, 60) deg, (25.144, 9.573, 18.092) cm; 50
particles, w=0.8, c1=c2=1.493, 500 iterations (Section 4.1, Fig. 4).
"""

EXPERIMENT = {
    "name": "mpso-single",
    "title": "m-PSO, single reachable target, position only, 30 runs",
    "source": "Rokbani et al. 2022 (MO-m-PSO), Section 4.1, Fig. 4",
    "robot": "rokbani5",
    "problem": {"kind": "position"},
    "targets": {"kind": "fixed", "points": [{"name": "q=(30,60,45,60,60)",
                                              "fk_q_deg": [30, 60, 45, 60, 60]}]},
    "algorithms": [{"name": "m-pso", "params": {"w": 0.8, "c1": 1.493, "c2": 1.493}}],
    "pop_size": 50,
    "iterations": 500,
    "runs": 30,
    "seed": 2022,
    "success_threshold": 1e-4,
    "analyses": ["summary"],
    "paper": {
        "citation": "MO-m-PSO paper, Section 4.1 text (position error, cm)",
        "summary": {"m-pso": {"best": 3.01e-10, "worst": 1.08e-5, "mean": 2.01e-6}},
    },
    "quick": {"runs": 3, "iterations": 20, "pop_size": 10},
}
