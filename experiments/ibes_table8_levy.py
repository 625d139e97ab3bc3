"""I-BES paper, Table 8, a reading of Eq. 9: the Levy step with and without its 0.01 factor.

Zhao et al., Biomimetics 9, 627 (2024). On youbot5 and sawyer7 the paper
reports 0 m in every I-BES run where moik's I-BES (Eq. 9 as printed,
``L = 0.01 sigma u / |v|^(1/beta)``) stops at medians of ~1e-7 m. These are
the two arms whose position-IK solution set is a continuum (the
``solution-rank`` table of ``ibes-table8``): there the population stays spread
along the solution set, and the Levy step, proportional to ``x_i - x_best``,
does not shrink with the error. This experiment measures the reading that
came closest to the paper: the same I-BES with the 0.01 factor left out
(``levy_scale = 1``; the paper's text prints 0.01, so it stays the default).
Same arms, targets, N=150, T=500, 25 runs and seed as ``ibes-table8``.
Full size: 6 arms x 2 readings x 25 runs = 300 trials.
"""

_ARMS = [("planar2", [0.35, 0.35, 0.00]), ("anthropomorphic3", [0.30, 0.20, 0.35]),
         ("scara4", [0.40, 0.20, 0.10]), ("youbot5", [0.40, 0.20, 0.10]),
         ("puma560", [0.40, 0.20, 0.50]), ("sawyer7", [0.80, 0.20, 0.60])]

EXPERIMENT = {
    "name": "ibes-table8-levy",
    "title": "I-BES: the Levy step of Eq. 9 with and without its 0.01 factor, Table 8 arms",
    "source": "Zhao et al. 2024 (I-BES), Section 3.2 Eq. 9, Section 5.1 Table 8",
    "robot": "planar2",
    "problem": {"kind": "position"},
    "targets": {"kind": "fixed", "points": [{"name": arm, "robot": arm, "position": p}
                                            for arm, p in _ARMS]},
    "algorithms": [
        {"name": "ibes"},
        {"name": "ibes", "label": "ibes-levy-unscaled", "params": {"levy_scale": 1.0}},
    ],
    "pop_size": 150,
    "n_gen": 500,
    "runs": 25,
    "seed": 2024,
    "success_threshold": 1e-6,
    "analyses": ["per-target", "per-target-ranksum", "solution-rank"],
    "proposed": "ibes",
    "quick": {"pop_size": 10, "n_gen": 8, "runs": 1},
}
