"""Trials (moik.experiments.trials): seeds shared by all algorithms; run_trial records failures;
a run's evaluation budget is the initial population plus ``iterations`` update iterations."""

import dataclasses
from pathlib import Path

import pytest

from moik.experiments.config import ExperimentConfig, load_config
from moik.experiments.trials import build_trials, run_trial


def test_seeds_are_identical_across_algorithms(tiny_config):
    specs = build_trials(tiny_config)
    assert len(specs) == 2 * 2 * 2
    by_alg = {}
    for s in specs:
        by_alg.setdefault(s.label, {})[(s.target_index, s.run)] = (s.seed, s.spawn_key)
    assert by_alg["eosma"] == by_alg["pso"]
    seeds = [v[0] for v in by_alg["eosma"].values()]
    assert len(set(seeds)) == len(seeds)


def test_run_trial_records_and_is_deterministic(tiny_config):
    spec = build_trials(tiny_config)[0]
    rec, arrays = run_trial(spec)
    rec2, _ = run_trial(spec)
    assert rec["status"] == "ok" and rec["best_f"] == rec2["best_f"]
    assert rec["best_x"] == rec2["best_x"] and rec["seed"] == spec.seed
    assert arrays["convergence"].shape == (7,)  # the initial population and 6 iterations


def test_run_trial_turns_exceptions_into_error_records(tiny_config):
    spec = build_trials(tiny_config)[0]
    broken = spec.__class__(**{**spec.__dict__, "robot": "no-such-robot"})
    rec, arrays = run_trial(broken)
    assert rec["status"] == "error" and "no-such-robot" in rec["error"] and arrays == {}


@pytest.mark.parametrize("name, params, per_iteration", [
    ("eosma", {"q": 0.0}, 1), ("eosma", {"q": 1.0}, 2), ("pso", {}, 1), ("tlbo", {}, 2),
    ("sma", {}, 1)])
def test_a_run_evaluates_the_initial_population_plus_iterations_times_per_iteration(
        tiny, name, params, per_iteration):
    tiny.update(algorithms=[{"name": name, "params": params}], analyses=["summary"])
    del tiny["proposed"]
    spec = build_trials(ExperimentConfig.from_dict(tiny))[0]
    rec, arrays = run_trial(spec)
    assert rec["n_eval"] == 8 + 6 * 8 * per_iteration  # pop_size + iterations x per iteration
    assert arrays["convergence"].shape == (1 + 6,)


def test_eosma_table5_budget_is_the_papers():
    """EOSMA Table 5: N = 50, T = 500, the q = 0 preset evaluates N per iteration."""
    config = load_config(Path(__file__).resolve().parents[2] / "experiments" / "eosma_table5.toml")
    assert config["iterations"] == 500
    spec = next(s for s in build_trials(config) if s.label == "eosma")
    rec, _ = run_trial(dataclasses.replace(spec, protocol=None))
    assert rec["status"] == "ok" and rec["n_eval"] == 50 + 500 * 50
