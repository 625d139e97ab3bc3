"""Helpers for testing algorithm kernels on tiny hand-computed arrays."""

from __future__ import annotations

import numpy as np


class ScriptedRng:
    """A stand-in for ``numpy.random.Generator`` that hands out scripted values.

    Every drawing method returns the next queued value, checking that its shape
    is the requested ``size``; 0-d values come back as Python scalars. Kernels
    take ``rng=`` as a keyword, so a test can pass this object and compare the
    kernel's output with a hand computation.

    Example:
        >>> rng = ScriptedRng([[0.25, 0.75]], 0.5)
        >>> rng.random((1, 2)), rng.uniform()
    """

    def __init__(self, *values):
        self.values = [np.asarray(v) for v in values]

    def _next(self, size=None):
        value = self.values.pop(0)
        if size is not None:
            assert value.shape == np.empty(size).shape, (value.shape, size)
        return value if value.ndim else value.item()

    def random(self, size=None):
        return self._next(size)

    def integers(self, low, high=None, size=None):
        return self._next(size)

    def uniform(self, low=0.0, high=1.0, size=None):
        return self._next(size)

    def standard_normal(self, size=None):
        return self._next(size)

    def permutation(self, n):
        return self._next((n,))
