"""Tables per target and the solution branches (moik.experiments.per_target)."""

import numpy as np
import pytest


def test_branch_clustering_wraps_revolute_angles_only():
    from moik.experiments.per_target import cluster_solutions, wrapped_distance
    from moik.robots import get_robot

    scara = get_robot("scara4")  # R R P R
    assert scara.is_prismatic.tolist() == [False, False, True, False]
    a, b = [np.pi - 0.01, 0.0, 0.0, 0.0], [-np.pi + 0.01, 0.0, 0.0, 0.0]
    assert wrapped_distance(scara, a, b) == pytest.approx(0.02)
    c = [0.0, 0.0, 0.0, 0.0]  # a prismatic stroke of 2 pi is not a full turn
    assert wrapped_distance(scara, c, [0.0, 0.0, 2 * np.pi, 0.0]) == pytest.approx(2 * np.pi)
    recs = [{"best_f": 0.0, "best_x": [3.14, 0.0, 0.0, 0.0]},
            {"best_f": 1e-9, "best_x": [-3.14, 0.01, 0.0, 0.0]},
            {"best_f": 0.0, "best_x": [0.0, 1.0, 0.0, 0.0]}]
    assert sorted(len(b) for b in cluster_solutions(scara, recs)) == [1, 2]
