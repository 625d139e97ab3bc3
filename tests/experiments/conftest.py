"""Shared fixtures: a tiny experiment config, written to a file or used as a dict."""

import copy

import pytest

TINY = {
    "name": "tiny-test",
    "title": "tiny position experiment",
    "source": "test",
    "robot": "planar2",
    "problem": {"kind": "position"},
    "targets": {"kind": "random", "n": 2, "seed": 1, "with_orientation": False},
    "algorithms": [{"name": "eosma"}, {"name": "pso"}],
    "pop_size": 8,
    "iterations": 6,
    "runs": 2,
    "seed": 11,
    "analyses": ["summary", "ranksum"],
    "proposed": "eosma",
    "quick": {"runs": 1},
}


@pytest.fixture
def tiny():
    """A fresh copy of the tiny experiment dict."""
    return copy.deepcopy(TINY)


@pytest.fixture
def tiny_config(tiny):
    """The tiny experiment, validated."""
    from moik.experiments.config import ExperimentConfig

    return ExperimentConfig.from_dict(tiny)


def stable(record: dict) -> dict:
    """A record without its timing and machine fields (what must be reproducible)."""
    return {k: v for k, v in record.items() if k not in ("time", "worker", "finished_at")}
