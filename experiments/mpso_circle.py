"""MO-m-PSO paper, Section 4.4: tracking a 50-point circle with a fixed orientation.

Rokbani et al., Appl. Sci. 12, 7091 (2022), DOI 10.3390/app12147091: Table 4
and Fig. 7. Circle of Eqs. 17-18 in the plane x = 15 cm, centre (15, 0, 12) cm,
radius 8 cm, 50 points; orientation alpha = beta = 0, gamma free: the Eq. 14
error without its gamma term (metric ``zyx-euler-free-gamma``). Each point is solved
independently by MO-m-PSO with the Section 4.3 settings (100 agents, 500
iterations; the section gives none), keeping the compromise closest to the
utopia point.
"""

EXPERIMENT = {
    "name": "mpso-circle",
    "title": "MO-m-PSO, 50-point circle path, centre (15, 0, 12) cm, radius 8 cm",
    "source": "Rokbani et al. 2022 (MO-m-PSO), Section 4.4, Table 4, Fig. 7",
    "robot": "rokbani5",
    "problem": {"kind": "bi-objective", "orientation": "zyx-euler-free-gamma"},
    "targets": {"kind": "circle", "center": [15, 0, 12], "radius": 8, "n_points": 50,
                "euler_deg": [0, 0, 0], "convention": "zyx-euler"},
    "algorithms": [{"name": "mo-m-pso", "params": {"w": 0.8, "c1": 1.493, "c2": 1.493}}],
    "pop_size": 100,
    "iterations": 500,
    "runs": 1,
    "seed": 2022,
    "analyses": ["compromise"],
    "paper": {
        "citation": "MO-m-PSO paper, Table 4 (position cm, orientation rad)",
        "compromise": {"mo-m-pso": {
            "position": {"best": 2.31e-6, "worst": 0.268, "mean": 0.032, "std": 0.191},
            "orientation": {"best": 1.85e-8, "worst": 4.58e-4, "mean": 5.73e-5, "std": 0.002},
        }},
    },
    "quick": {"targets": {"n_points": 6}, "pop_size": 10, "iterations": 15},
}
