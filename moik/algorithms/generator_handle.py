"""A compiled handle on a numpy ``Generator``: kernels draw on it without converting it.

numba accepts ``numpy.random.Generator`` arguments, but converting one at each call
costs about 5 us (a type lookup and three ctypes casts), more than all the draws of an
EOSMA generation. :class:`GeneratorHandles` wraps the algorithm's Generator once in a
numba structure (a ``structref`` with the one field ``rng``); a kernel takes the handle
(a fraction of a microsecond to pass) and draws with ``handle.rng``. It is the same bit
generator, so the stream is shared with every numpy draw on the Generator before and
after: seeds mean the same thing as everywhere else.
"""

from __future__ import annotations

import numpy as np
from numba.experimental import structref

from moik._jit import StructType, define_struct, jit


@structref.register
class GeneratorHandleType(StructType):
    """numba type of :class:`GeneratorHandle`."""


class GeneratorHandle(structref.StructRefProxy):
    """A numba structure holding one ``numpy.random.Generator`` (field ``rng``)."""


define_struct(GeneratorHandle, GeneratorHandleType, ["rng"])


@jit
def wrap_generator(rng):
    """The :class:`GeneratorHandle` of ``rng`` (it keeps ``rng`` alive)."""
    return GeneratorHandle(rng)


class GeneratorHandles:
    """The handle of an algorithm's current Generator, rebuilt when the Generator changes.

    pymoo builds ``random_state`` in ``setup`` and a deep copy (``save_history``) or a
    pickle carries its own Generator, so the handle is looked up by identity at each use;
    copies and pickles of this object start empty and rebuild their own.
    """

    __slots__ = ("_handle", "_rng")

    def __init__(self) -> None:
        self._rng: np.random.Generator | None = None
        self._handle: GeneratorHandle | None = None

    def of(self, rng: np.random.Generator) -> GeneratorHandle:
        """The handle of ``rng``."""
        if rng is not self._rng or self._handle is None:
            self._rng, self._handle = rng, wrap_generator(rng)
        return self._handle

    def __reduce__(self):
        return (GeneratorHandles, ())
