"""The experiment kind is chosen once from problem.kind (moik.experiments.kinds)."""

import pytest

from moik.exceptions import ConfigError
from moik.experiments.kinds import (
    KINDS,
    MULTI_OBJECTIVE_PROBLEMS,
    baselines,
    functions,
    ik,
    kind_of,
    moo_functions,
)
from moik.experiments.trials import build_trials


def test_problem_kinds_map_to_their_kind():
    assert {"ik": ik, "functions": functions, "moo-functions": moo_functions} == KINDS
    assert [kind_of("p", {"kind": k}) for k in ("position", "pose", "bi-objective")] == ["ik"] * 3
    assert kind_of("p", {"kind": "benchmark"}) == "functions"
    assert kind_of("p", {"kind": "moo-benchmark"}) == "moo-functions"


def test_multi_objective_problem_kinds_and_baselines():
    assert {"bi-objective", "moo-benchmark"} == MULTI_OBJECTIVE_PROBLEMS
    assert baselines("moo-functions") == {"random-search": ("pop_size",)}
    assert baselines("ik") == {} and baselines("functions") == {}


def test_unknown_problem_kinds_list_the_valid_ones():
    with pytest.raises(ConfigError, match="p.kind must be one of position, pose, bi-objective, "
                                          "benchmark, moo-benchmark, got 'torque'"):
        kind_of("p", {"kind": "torque"})
    with pytest.raises(ConfigError, match="p must be a dict, got str"):
        kind_of("p", "position")


def test_the_config_and_every_trial_carry_the_kind(tiny_config):
    assert tiny_config.kind == "ik"
    assert {s.kind for s in build_trials(tiny_config)} == {"ik"}
