"""The trial spec (moik.experiments.spec): seeds shared by all algorithms, picklable."""

import pickle

import numpy as np

from moik.experiments.spec import spec_summary, trial_seeds
from moik.experiments.trials import build_trials, run_trial


def test_seeds_come_from_seedsequence_spawn(tiny_config):
    specs = build_trials(tiny_config)
    children = trial_seeds(11, 2, 2)
    for s in specs:
        child = children[s.target_index * 2 + s.run]
        assert s.spawn_key == child.spawn_key and s.entropy == 11
        assert s.seed == int(child.generate_state(1, dtype=np.uint32)[0])
        assert (s.seed_sequence.generate_state(4) == child.generate_state(4)).all()


def test_a_spec_pickles_for_the_workers(tiny_config):
    spec = build_trials(tiny_config)[0]
    copy = pickle.loads(pickle.dumps(spec))
    assert copy.kind == "ik" and copy.trial_id == spec.trial_id
    assert run_trial(copy)[0]["best_f"] == run_trial(spec)[0]["best_f"]


def test_summary_has_the_identity_and_seeds_only(tiny_config):
    spec = build_trials(tiny_config)[3]
    assert spec_summary(spec) == {"trial_id": "eosma/1/1", "label": "eosma", "target_index": 1,
                                  "run": 1, "seed": spec.seed, "entropy": 11,
                                  "spawn_key": spec.spawn_key}
