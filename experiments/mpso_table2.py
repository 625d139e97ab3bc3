"""MO-m-PSO paper, Section 4.2: one target with an orientation, 100 runs.

Rokbani et al., Appl. Sci. 12, 7091 (2022), DOI 10.3390/app12147091: Table 2
and Fig. 5. Position = FK of (30, 60, 45, 60, 60) deg = (25.144, 9.573, 18.092)
cm; orientation (alpha, beta, gamma) = (0, -30, -23.8) deg, ZYX Euler (Eq. 16);
objectives Eq. 15 (position error; Eq. 14 mean absolute Euler error, rad). The
section repeats the Section 4.1 test, so 50 particles per swarm, 500
iterations, w=0.8, c1=c2=1.493. The selected solution is the archive member
closest to the utopia point (Eq. 8).
"""

EXPERIMENT = {
    "name": "mpso-table2",
    "title": "MO-m-PSO, single target with orientation (0, -30, -23.8) deg, 100 runs",
    "source": "Rokbani et al. 2022 (MO-m-PSO), Section 4.2, Table 2, Fig. 5",
    "robot": "rokbani5",
    "problem": {"kind": "bi-objective", "orientation": "zyx-euler"},
    "targets": {"kind": "fixed", "points": [
        {"name": "Eq. 16 pose", "fk_q_deg": [30, 60, 45, 60, 60], "euler_deg": [0, -30, -23.8],
         "convention": "zyx-euler"},
    ]},
    "algorithms": [{"name": "mo-m-pso", "params": {"w": 0.8, "c1": 1.493, "c2": 1.493}}],
    "pop_size": 50,
    "iterations": 500,
    "runs": 100,
    "seed": 2022,
    "analyses": ["compromise"],
    "paper": {
        "citation": "MO-m-PSO paper, Table 2 (position cm, orientation rad)",
        "compromise": {"mo-m-pso": {
            "position": {"best": 3.81e-10, "worst": 0.0492, "mean": 0.0150, "std": 0.1973},
            "orientation": {"best": 2.34e-9, "worst": 0.6439, "mean": 0.0918, "std": 0.2268},
        }},
    },
    "quick": {"pop_size": 10, "iterations": 15, "runs": 3},
}
