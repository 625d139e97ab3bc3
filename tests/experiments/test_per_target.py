"""Tables per target and the solution branches (moik.experiments.per_target)."""

import numpy as np
import pytest


def test_branch_clustering_wraps_angles():
    from moik.experiments.per_target import cluster_solutions, wrapped_distance

    assert wrapped_distance([np.pi - 0.01], [-np.pi + 0.01]) == pytest.approx(0.02)
    recs = [{"best_f": 0.0, "best_x": [3.14, 0.0]}, {"best_f": 1e-9, "best_x": [-3.14, 0.01]},
            {"best_f": 0.0, "best_x": [0.0, 1.0]}]
    assert sorted(len(b) for b in cluster_solutions(recs)) == [1, 2]
