"""The experiments' tiny config (tests/experiments/conftest.py), for the ``experiment`` command."""

import copy

import pytest

from tests.experiments.conftest import TINY


@pytest.fixture
def tiny():
    """A fresh copy of the tiny experiment dict."""
    return copy.deepcopy(TINY)
