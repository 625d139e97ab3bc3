"""Trials (moik.experiments.trials): seeds shared by all algorithms; run_trial records failures."""

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
    assert arrays["convergence"].shape == (6,)


def test_run_trial_turns_exceptions_into_error_records(tiny_config):
    spec = build_trials(tiny_config)[0]
    broken = spec.__class__(**{**spec.__dict__, "robot": "no-such-robot"})
    rec, arrays = run_trial(broken)
    assert rec["status"] == "error" and "no-such-robot" in rec["error"] and arrays == {}
