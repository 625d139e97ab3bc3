"""Shared fixtures: a tiny experiment config, written to a file or used as a dict."""

import copy

import pytest

from moik.experiments import docs as docs_module
from moik.experiments.docs import git_commit

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


@pytest.fixture(autouse=True)
def _clean_tree(monkeypatch):
    """The checkout's commit as if its code had no uncommitted changes (the tests run in
    working trees that may have some; ``moik report --docs`` refuses them): refusing a
    dirty tree is tested on its own (tests/experiments/test_docs.py)."""
    monkeypatch.setattr(docs_module, "git_commit",
                        lambda: (git_commit() or "").removesuffix("-dirty") or None)
