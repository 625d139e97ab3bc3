"""MOPSO-CD (moik.algorithms.moo.mopso_cd): pymoo's, seeded by the run, constraint-domination."""

import hashlib
import subprocess
import sys

import numpy as np
from pymoo.algorithms.moo.mopso_cd import MOPSO_CD
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOPSOCD
from moik.algorithms.moo import mopso_cd


def test_unconstrained_runs_are_pymoos_bit_for_bit_and_seeded_by_the_run():
    problem = get_problem("zdt1", n_var=6)
    ours = minimize(problem, MOPSOCD(pop_size=20), ("n_eval", 600), seed=3)
    theirs = minimize(problem, MOPSO_CD(pop_size=20), ("n_eval", 600), seed=3)
    np.testing.assert_array_equal(ours.F, theirs.F)
    again = minimize(problem, MOPSOCD(pop_size=20, seed=3), ("n_eval", 600))
    np.testing.assert_array_equal(again.F, ours.F)
    other = minimize(problem, MOPSOCD(pop_size=20), ("n_eval", 600), seed=4)
    assert not np.array_equal(other.F, ours.F)


def test_a_termination_given_to_the_constructor_is_kept():
    alg = MOPSOCD(pop_size=10, termination=("n_gen", 4))
    res = minimize(get_problem("zdt1", n_var=4), alg, seed=0)
    assert res.algorithm.n_gen == 5  # 4 generations (pymoo counts one past the last)


def test_constrained_archive_and_personal_bests_are_feasible_first():
    problem = get_problem("osy")
    res = minimize(problem, MOPSOCD(pop_size=30), ("n_eval", 3000), seed=1)
    G = problem.evaluate(res.X, return_values_of=["G"])
    assert np.all(G <= 0.0) and np.all(res.CV == 0.0)
    assert np.any(res.algorithm.pbest.get("CV")[:, 0] == 0.0)
    theirs = minimize(problem, MOPSO_CD(pop_size=30), ("n_eval", 3000), seed=1)
    # pymoo's own compares F only: its archive keeps infeasible points (here none of its
    # members is feasible, so its result is empty, or it mixes in infeasible ones)
    assert theirs.F is None or np.any(theirs.CV > 0.0)


DIGEST_SCRIPT = """
import hashlib, numpy as np
from pymoo.optimize import minimize
from pymoo.problems import get_problem
from moik.algorithms import MOPSOCD
from moik.algorithms.moo import mopso_cd
res = minimize(get_problem("zdt1"), MOPSOCD(), ("n_eval", 8_000), seed=1)
print(hashlib.sha256(np.ascontiguousarray(res.X).tobytes()
                     + np.ascontiguousarray(res.F).tobytes()).hexdigest())
"""


def test_a_seed_gives_one_run_once_the_archive_truncates(monkeypatch):
    """Issue 26: pymoo's ``Algorithm.advance`` adds the infills to MOPSO-CD's swarm archive,
    whose truncation drew from OS entropy; here from the run's ``random_state``. 8,000
    evaluations: the archive is truncated 5 times by then (none at 5,000); 20,000 for every
    algorithm is tests/algorithms/test_registry_determinism.py's."""
    calls = []
    draw = mopso_cd.SeededTruncation.__call__

    def counted(self, sols, k):
        calls.append(k)
        return draw(self, sols, k)

    monkeypatch.setattr(mopso_cd.SeededTruncation, "__call__", counted)
    runs = [minimize(get_problem("zdt1"), MOPSOCD(), ("n_eval", 8_000), seed=1)
            for _ in range(2)]
    assert calls  # the archive filled and was truncated
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    np.testing.assert_array_equal(runs[0].F, runs[1].F)
    out = subprocess.run([sys.executable, "-c", DIGEST_SCRIPT], capture_output=True,
                         text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    here = hashlib.sha256(np.ascontiguousarray(runs[0].X).tobytes()
                          + np.ascontiguousarray(runs[0].F).tobytes()).hexdigest()
    assert out.stdout.split() == [here]


def test_non_finite_rows_never_enter_the_archive():
    """MW11 returns NaN objectives at some points; seed 3 emptied the archive into a plain
    ``Population`` (``AttributeError: ... no attribute 'add'``) on main at 62ac347."""
    problem = get_problem("mw11")
    with np.errstate(invalid="ignore"):
        res = minimize(problem, MOPSOCD(), ("n_eval", 5000), seed=3)
    archive = res.algorithm.archive
    assert isinstance(archive, mopso_cd.SwarmArchive)
    assert np.isfinite(archive.get("F")).all() and np.isfinite(archive.get("CV")).all()
    if res.F is not None:
        assert np.isfinite(res.F).all() and np.all(res.CV <= 0.0)
