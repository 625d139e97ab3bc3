"""Shared pytest configuration: the ``slow`` marker.

Tests marked ``slow`` are measurements that take tens of seconds; deselect them
with ``pytest -m "not slow"``.
"""


def pytest_configure(config):
    config.addinivalue_line(
        "markers", "slow: long accuracy measurements (deselect with -m 'not slow')")
