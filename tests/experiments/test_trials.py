"""Trials: seeds shared by all algorithms and recorded; run_trial records failures."""

import numpy as np

from moik.experiments.spec import trial_seeds
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


def test_seeds_come_from_seedsequence_spawn(tiny_config):
    specs = build_trials(tiny_config)
    children = trial_seeds(11, 2, 2)
    for s in specs:
        child = children[s.target_index * 2 + s.run]
        assert s.spawn_key == child.spawn_key and s.entropy == 11
        assert s.seed == int(child.generate_state(1, dtype=np.uint32)[0])
        assert (s.seed_sequence.generate_state(4) == child.generate_state(4)).all()


def test_random_targets_are_reachable_positions(tiny_config):
    targets = tiny_config.targets
    assert len(targets) == 2 and targets[0].rotation is None


def test_run_trial_records_and_is_deterministic(tiny_config):
    spec = build_trials(tiny_config)[0]
    rec, arrays = run_trial(spec)
    rec2, _ = run_trial(spec)
    assert rec["status"] == "ok" and rec["best_f"] == rec2["best_f"]
    assert rec["best_x"] == rec2["best_x"] and rec["seed"] == spec.seed
    assert arrays["convergence"].shape == (6,)


def test_run_trial_turns_exceptions_into_error_records(tiny_config):
    spec = build_trials(tiny_config)[0]
    broken = spec.__class__(**{**spec.__dict__, "robot": "no-such-robot"})
    rec, arrays = run_trial(broken)
    assert rec["status"] == "error" and "no-such-robot" in rec["error"] and arrays == {}
