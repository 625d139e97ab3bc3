"""I-BES paper, Table 9: the four solution branches of the Puma 560 wrist position.

Zhao et al., Biomimetics 9, 627 (2024), Section 5.1.3: the Puma 560 with
joints 4-6 fixed (only the position matters, so the first three joints), the
five targets of Kalra et al., I-BES with the Section 5.1.1 settings (N=150,
T=500); each target has four geometric solutions. The arm is
``puma560-kalra``: Table 9's angles belong to Kalra's Puma, not to the Table 6
arm (they miss the targets by ~0.4 m there), so the branches compare.

The arm's lengths come from the ``dh-fit`` table of the report: a least-squares
fit of a2, a3, d3, d4 (twists fixed) to the paper's 16 I-BES solutions of T2-T5
(printed to 8 decimals) and the printed targets gives a2 = 0.4318,
a3 = -0.02032, d3 = 0.14909, d4 = 0.43307 m with residuals of 3e-9 m (the
solutions' rounding); the catalog arm carries these values.

Target T1: the paper prints (0.60, 0.15, 0.20), but its I-BES solutions (q1 = 0
on two branches, so y = d3 exactly) all land on (0.6, 0.14909, 0.2): 0.15 is d3
rounded to two decimals (the ``dh-fit`` table shows where they land). T1 is
therefore read as (0.60, d3, 0.20); with y = 0.15 the four branches move by
~1.5e-3 rad (q1 = +-0.0015) and no longer compare with the printed angles.

Reading: the paper runs I-BES once per target yet lists four I-BES solutions;
a single run converges to one branch. Here I-BES runs 20 times per target (seeded),
the solved runs (error < 1e-6 m) are grouped into branches (joint angles modulo
2 pi, distinct beyond 0.1 rad), and each of the paper's branches is matched
to the nearest one found: the table reports whether I-BES finds all four, how
many runs land in each, and |q_geometric - q_I-BES|.
"""

_PRINTED = [[0.60, 0.15, 0.20], [0.50, 0.24, 0.23], [0.54, 0.21, 0.26], [0.18, -0.40, 0.40],
            [-0.18, 0.40, -0.20]]
"""The targets as Table 9 prints them (Kalra et al.'s)."""
_TARGETS = [[0.60, 0.14909, 0.20], [0.50, 0.24, 0.23], [0.54, 0.21, 0.26], [0.18, -0.40, 0.40],
            [-0.18, 0.40, -0.20]]
# Table 9: per target, per branch, (geometric q, I-BES q) in rad.
_TABLE9 = [
    [((0, -1.0748, 3.1201), (0, -1.07483809, 3.12008845)),
     ((0, 0.4313, 0.1153), (0, 0.43133699, 0.11527708)),
     ((-2.6545, -2.0668, 0.1153), (-2.65449125, -2.06675456, 0.11527708)),
     ((-2.6545, 2.7103, 3.1201), (-2.65449125, 2.71025567, 3.12008845))],
    [((0.1754, -1.2425, -2.998), (0.17535625, -1.24252231, -2.99802640)),
     ((0.1754, 0.4294, -0.0498), (0.17535625, 0.42940065, -0.04979338)),
     ((-2.4219, -1.8991, -0.0498), (-2.42190895, -1.89907034, -0.04979338)),
     ((-2.4219, 2.7122, -2.998), (-2.42190895, 2.71219200, -2.99802640))],
    [((0.1106, -1.2132, -3.1125), (0.11064393, -1.21323656, -3.11249085)),
     ((0.1106, 0.3437, 0.0647), (0.11064393, 0.34374040, 0.06467106)),
     ((-2.5105, -1.9284, 0.0647), (-2.51045401, -1.92835609, 0.06467106)),
     ((-2.5105, 2.7979, -3.1125), (-2.51045401, 2.79785225, -3.11249085))],
    [((-1.4947, -1.6169, -2.9763), (-1.49474865, -1.61688215, -2.97626623)),
     ((-1.4947, 0.0769, -0.0716), (-1.49474865, 0.07689939, -0.07155356)),
     ((2.3405, -1.5247, -0.0716), (2.34045650, -1.52471050, -0.07155356)),
     ((2.3405, 3.0647, -2.9763), (2.34045650, 3.06469327, -2.97626623))],
    [((1.6468, -0.5643, -2.6406), (1.64684400, -0.56425178, -2.64059151)),
     ((1.6468, 1.4671, -0.4072), (1.64684400, 1.46712123, -0.40722827)),
     ((-0.8011, -2.5773, -0.4072), (-0.80113615, -2.57734087, -0.40722827)),
     ((-0.8011, 1.6745, -2.6406), (-0.80113615, 1.67447142, -2.64059151))],
]

EXPERIMENT = {
    "name": "ibes-table9",
    "title": "I-BES: four solution branches of the Puma 560 wrist position (5 targets)",
    "source": "Zhao et al. 2024 (I-BES), Section 5.1.3, Table 9 (targets of Kalra et al.)",
    "robot": "puma560-kalra",
    "problem": {"kind": "position", "locked_joints_deg": [None, None, None, 0.0, 0.0, 0.0]},
    "targets": {"kind": "fixed", "points": [{"name": f"T{i + 1}", "position": p}
                                            for i, p in enumerate(_TARGETS)]},
    "algorithms": [{"name": "ibes"}],
    "pop_size": 150,
    "iterations": 500,
    "runs": 20,
    "seed": 9,
    "success_threshold": 1e-6,
    "analyses": ["per-target", "branches", "dh-fit"],
    "paper": {
        "citation": "I-BES paper, Table 9 (rad; geometric solutions of Kalra et al.)",
        "branches": {f"T{i + 1}": [{"geometric": list(g), "paper": list(q)} for g, q in rows]
                     for i, rows in enumerate(_TABLE9)},
        "dh_fit": {"solutions": "paper", "lengths": [["a", 1], ["a", 2], ["d", 2], ["d", 3]],
                   "start": [0.431, -0.020, 0.150, 0.432],
                   "targets": {f"T{i + 1}": p for i, p in enumerate(_PRINTED)},
                   "fit_targets": ["T2", "T3", "T4", "T5"]},
    },
    "quick": {"pop_size": 20, "iterations": 30, "runs": 2},
}
