"""MO-m-PSO paper, Section 4.3: 100 random targets with random orientations.

Rokbani et al., Appl. Sci. 12, 7091 (2022), DOI 10.3390/app12147091: Table 3
and Fig. 6. Targets are FK poses of uniform random joint vectors (reachable);
100 agents, 500 iterations; objectives Eq. 15 (ZYX Euler, Eq. 14); the
selected solution is the compromise closest to the utopia point (Eq. 8).
"""

EXPERIMENT = {
    "name": "mpso-table3",
    "title": "MO-m-PSO, 100 random targets with orientations",
    "source": "Rokbani et al. 2022 (MO-m-PSO), Section 4.3, Table 3, Fig. 6",
    "robot": "rokbani5",
    "problem": {"kind": "bi-objective", "orientation": "zyx-euler"},
    "targets": {"kind": "random", "n": 100, "seed": 3, "with_orientation": True},
    "algorithms": [{"name": "mo-m-pso", "params": {"w": 0.8, "c1": 1.493, "c2": 1.493}}],
    "pop_size": 100,
    "iterations": 500,
    "runs": 1,
    "seed": 2022,
    "analyses": ["compromise"],
    "paper": {
        "citation": "MO-m-PSO paper, Table 3 (position cm, orientation rad)",
        "compromise": {"mo-m-pso": {
            "position": {"best": 1.88e-9, "worst": 2.925, "mean": 1.450, "std": 1.897},
            "orientation": {"best": 1.65e-10, "worst": 0.643, "mean": 0.091, "std": 0.126},
        }},
    },
    "quick": {"targets": {"n": 3}, "pop_size": 10, "iterations": 15},
}
