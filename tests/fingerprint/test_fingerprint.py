"""Bit-level fingerprints of results: every registered algorithm on a small
problem at a fixed seed, the IK problems' objectives, and ``solve_ik`` on a few
poses. A refactoring that keeps behaviour keeps these hashes.

Run ``python tests/fingerprint/test_fingerprint.py`` to print the current values
(the stored ones live in ``fingerprints.json`` beside this file).

Bit-level results hold on one kind of machine, not across them: numpy dispatches its
sorts (the order of ties) and reductions (the summation order) on the CPU's SIMD
features, so pymoo's NSGA-II gives other bits on an AVX2 machine than on an AVX-512
one from the same seed. ``fingerprints.json`` therefore holds one record per kind of
machine (keyed by numpy's x86-64 level, :func:`machine_signature`); the tests check
this kind's record and are skipped, saying why, on a kind with none. Running this file
records this kind's values; an entry that changed here is dropped from the other
kinds' records (re-record it there), a kind recorded for the first time drops nothing.
"""

from __future__ import annotations

import hashlib
import json
import platform
from pathlib import Path

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

import moik
from moik.algorithms import available, get_algorithm
from moik.algorithms.registry import is_multi_objective
from moik.problems import BiObjectiveIK, PoseIK, PositionIK, random_reachable_targets
from moik.robots import get_robot

FILE = Path(__file__).with_name("fingerprints.json")


class _ShiftedSphere(Problem):
    def __init__(self):
        super().__init__(n_var=5, n_obj=1, xl=-5.0, xu=3.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = ((X - 1.3) ** 2).sum(axis=1)


def digest(*arrays) -> str:
    h = hashlib.sha256()
    for a in arrays:
        a = np.ascontiguousarray(np.atleast_1d(np.asarray(a, dtype=float)))
        h.update(str(a.shape).encode())
        h.update(a.tobytes())
    return h.hexdigest()[:20]


def algorithm_fingerprint(name: str) -> str:
    if is_multi_objective(name):
        problem, budget = get_problem("zdt1", n_var=6), 600
    else:
        problem, budget = _ShiftedSphere(), 600
    res = minimize(problem, get_algorithm(name), ("n_eval", budget), seed=3)
    return digest(res.X, res.F)


def problem_fingerprints() -> dict[str, str]:
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=5)[0]
    X = np.random.default_rng(0).uniform(robot.lower, robot.upper, (20, robot.dof))
    out = {}
    for key, problem in [("PositionIK", PositionIK(robot, target.position)),
                         ("PoseIK-eosma-euler", PoseIK(robot, target, orientation="eosma-euler")),
                         ("PoseIK-geodesic", PoseIK(robot, target, orientation="geodesic")),
                         ("BiObjectiveIK", BiObjectiveIK(robot, target))]:
        out[key] = digest(problem.evaluate(X, return_values_of=["F"]))
    return out


def solver_fingerprints() -> dict[str, str]:
    out = {}
    for name in ("eosma7", "puma560", "rokbani5"):
        robot = get_robot(name)
        for i, target in enumerate(random_reachable_targets(robot, 2, seed=11)):
            pose = target.position if name == "rokbani5" else target.pose
            res = moik.solve_ik(robot, pose, seed=i, n_solutions=2)
            out[f"{name}-{i}"] = digest(res.q, res.solutions, [res.n_eval]) + ":" + res.status
    return out


X86_LEVELS = ("X86_V4", "X86_V3", "X86_V2")  # numpy's x86-64 levels, highest first


def machine_signature() -> str:
    """The kind of machine, as far as numpy's sorts' and sums' bits go: on x86-64 the highest
    microarchitecture level numpy dispatches to (``X86_V4``: AVX-512 SKX, ``X86_V3``:
    AVX2), elsewhere the machine and every SIMD feature numpy reports. Measured: an Intel
    Sapphire Rapids and an AMD Zen 4 (both ``X86_V4``, with different AVX-512 extensions)
    give the same fingerprints, an AVX2 machine 6 other algorithm fingerprints."""
    from numpy._core._multiarray_umath import __cpu_features__

    features = {k for k, on in __cpu_features__.items() if on}
    for level in X86_LEVELS:
        if level in features:
            return level
    return " ".join([platform.machine(), *sorted(features)])


def current() -> dict[str, dict[str, str]]:
    return {"algorithms": {n: algorithm_fingerprint(n) for n in available()},
            "problems": problem_fingerprints(),
            "solver": solver_fingerprints()}


STORED: dict[str, dict] = json.loads(FILE.read_text()) if FILE.exists() else {"machines": {}}
HERE = STORED["machines"].get(machine_signature())  # this kind of machine's record, if any


def record(records: dict, now: dict[str, dict[str, str]], machine: str) -> list[str]:
    """Store ``now`` as ``machine``'s record in ``records`` (``{"machines": {...}}``); an
    entry that changed from that machine's old record is dropped from every other
    machine's record (its bits there are unknown until recorded there). A machine kind
    recorded for the first time drops nothing (its bits differ from the others' by its
    SIMD, not by a change of behaviour). Returns the entries dropped, as
    ``"machine-kind: section/name"``."""
    old = records["machines"].get(machine)
    dropped: list[str] = []
    if old is None:
        records["machines"][machine] = now
        return dropped
    for other, rec in records["machines"].items():
        if other == machine:
            continue
        for section, entries in now.items():
            for name, value in entries.items():
                if name in rec.get(section, {}) and old.get(section, {}).get(name) != value:
                    del rec[section][name]
                    dropped.append(f"{other[-40:]}: {section}/{name}")
    records["machines"][machine] = now
    return dropped


@pytest.fixture()
def here():
    """This kind of machine's record; the test is skipped on a kind with none."""
    if HERE is None:
        pytest.skip("no fingerprints recorded for this kind of machine (numpy SIMD features "
                    f"{machine_signature()!r}; recorded: {len(STORED['machines'])} other kinds): "
                    "numpy's sorts and sums give other bits here. Record them with "
                    "`python tests/fingerprint/test_fingerprint.py` on a commit whose "
                    "fingerprints are checked on a recorded kind")
    return HERE


ALL_ALGORITHMS = sorted({n for rec in STORED["machines"].values() for n in rec["algorithms"]})


@pytest.mark.parametrize("name", ALL_ALGORITHMS)
def test_algorithm_result_unchanged(name, here):
    if name not in here["algorithms"]:
        pytest.skip(f"{name}'s fingerprint was re-recorded on another kind of machine only")
    assert algorithm_fingerprint(name) == here["algorithms"][name]


def test_registry_has_no_unfingerprinted_algorithm():
    for machine, rec in STORED["machines"].items():
        missing = sorted(set(available()) - set(rec["algorithms"]))
        assert not missing or machine != machine_signature(), missing
    assert sorted(available()) == ALL_ALGORITHMS


def test_ik_objectives_unchanged(here):
    now = problem_fingerprints()
    assert {k: now[k] for k in here["problems"]} == here["problems"]


def test_solver_unchanged(here):
    now = solver_fingerprints()
    assert {k: now[k] for k in here["solver"]} == here["solver"]


def test_record_drops_what_changed_from_other_machines():
    records = {"machines": {"A": {"solver": {"x": "1", "y": "2"}},
                            "B": {"solver": {"x": "1b", "y": "2b"}}}}
    dropped = record(records, {"solver": {"x": "1", "y": "3"}}, "A")
    assert dropped == ["B: solver/y"]
    assert records["machines"]["B"] == {"solver": {"x": "1b"}}
    assert records["machines"]["A"] == {"solver": {"x": "1", "y": "3"}}


def test_record_of_a_new_machine_kind_drops_nothing():
    records = {"machines": {"A": {"solver": {"x": "1", "y": "2"}}}}
    assert record(records, {"solver": {"x": "1c", "y": "2c"}}, "C") == []
    assert records["machines"] == {"A": {"solver": {"x": "1", "y": "2"}},
                                   "C": {"solver": {"x": "1c", "y": "2c"}}}


if __name__ == "__main__":
    records = STORED
    for line in record(records, current(), machine_signature()):
        print(f"dropped (changed here; re-record on that kind of machine): {line}")
    FILE.write_text(json.dumps(records, indent=1, sort_keys=True) + "\n")
    print(f"recorded {machine_signature()!r}; {len(records['machines'])} kinds of machine")
