"""MO-m-PSO paper, Section 4.3, second reading: random positions, independent random orientations.

Rokbani et al., Appl. Sci. 12, 7091 (2022), DOI 10.3390/app12147091: Table 3
and Fig. 6. 100 agents, 500 iterations; objectives Eq. 15 (ZYX Euler, Eq. 14);
the selected solution is the compromise closest to the utopia point (Eq. 8).

Two readings of "each point is associated with a random orientation": here the
positions are FK positions of uniform random joint vectors and each orientation
is drawn uniformly on SO(3), independent of the position (with 5 joints such a
pose is in general unreachable); ``mpso-table3`` takes the FK poses
(reachable, a pose error of 0 exists). Both MO-m-PSO guides run (``mo-m-pso``:
the archive compromise guides every swarm, the default; ``mo-m-pso-own-best``: independent swarms).
"""

EXPERIMENT = {
    "name": "mpso-table3-independent",
    "title": "MO-m-PSO, 100 random positions with independent random orientations",
    "source": "Rokbani et al. 2022 (MO-m-PSO), Section 4.3, Table 3, Fig. 6",
    "robot": "rokbani5",
    "problem": {"kind": "bi-objective", "orientation": "zyx-euler"},
    "targets": {"kind": "random", "n": 100, "seed": 3, "with_orientation": True,
                "orientation": "independent"},
    "algorithms": [
        {"name": "mo-m-pso", "params": {"w": 0.8, "c1": 1.493, "c2": 1.493}},
        {"name": "mo-m-pso", "label": "mo-m-pso-own-best",
         "params": {"w": 0.8, "c1": 1.493, "c2": 1.493, "guide": "own-best"}},
    ],
    "pop_size": 100,
    "iterations": 500,
    "runs": 1,
    "seed": 2022,
    "analyses": ["compromise", "paper-consistency"],
    "paper": {
        "citation": "MO-m-PSO paper, Table 3 (position cm, orientation rad)",
        "n_values": 100,
        "compromise": {"mo-m-pso": {
            "position": {"best": 1.88e-9, "worst": 2.925, "mean": 1.450, "std": 1.897},
            "orientation": {"best": 1.65e-10, "worst": 0.643, "mean": 0.091, "std": 0.126},
        }},
    },
    "quick": {"targets": {"n": 3}, "pop_size": 10, "iterations": 15},
}
