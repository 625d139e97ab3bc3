"""Numba compilation of moik's kernels, and the one normalisation of kernel inputs.

:func:`jit` compiles a function in nopython mode with ``fastmath`` off and no thread
parallelism, so a kernel's result is bit-reproducible on a machine and does not
depend on the batch it is part of. It asks numba for an on-disk cache
(``cache=True``): numba stores compiled code in ``NUMBA_CACHE_DIR``, beside the
source (``__pycache__``) or in the user cache directory, whichever it can write.
When it can write none of them (a read-only installation and home), numba refuses
to build the cache when the function is decorated; :func:`jit` then compiles
without a cache instead, so importing moik never fails for a cache.

numba keys a cached function by its own source file only, while moik's kernels
inline helpers from other modules (a fused IK objective holds the FK kernel of
:mod:`moik.robots.dh`): after an edit of ``dh.py`` the cached objective would be
stale. So the cache key also holds a digest of every moik module that compiles
kernels (those importing this module); editing one recompiles them all, once.

Kernels compile lazily, at their first call. The first real compilation in a
process (not a load from the cache) prints one line on stderr,
``compiling kinematics kernels, first run only``; it is detected through numba's
``numba:compile`` event, which numba fires only when it compiles.

:func:`kernel_array` is what every public entry passes its arrays through before a
kernel: numba compiles one machine-code version per argument type, and a
read-only, strided or non-float64 array is another type, so normalising inputs to
C-contiguous, writeable ``float64`` keeps each kernel at its one compiled version.
"""

from __future__ import annotations

import hashlib
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numba
import numpy as np
from numba.core import event
from numba.core.caching import FunctionCache

COMPILE_NOTICE = "compiling kinematics kernels, first run only"

_kernels: set[Callable] = set()  # the Python functions compiled by jit
_notice: dict[str, Any] = {"printed": False}  # and the sources digest, once computed


class _CompileNotice(event.Listener):
    """Prints :data:`COMPILE_NOTICE` once, when numba starts compiling a moik kernel."""

    def on_start(self, ev: event.Event) -> None:
        data = ev.data if isinstance(ev.data, dict) else {}
        dispatcher = data.get("dispatcher")
        if not _notice["printed"] and getattr(dispatcher, "py_func", None) in _kernels:
            _notice["printed"] = True
            print(COMPILE_NOTICE, file=sys.stderr, flush=True)

    def on_end(self, ev: event.Event) -> None:
        pass


event.register("numba:compile", _CompileNotice())


def _kernel_sources_digest() -> str:
    """SHA-256 of the source of every moik module that compiles kernels."""
    if "digest" not in _notice:
        h = hashlib.sha256()
        for path in sorted(Path(__file__).parent.rglob("*.py")):
            text = path.read_bytes()
            if b"moik._jit import" in text:
                h.update(path.relative_to(Path(__file__).parent).as_posix().encode())
                h.update(text)
        _notice["digest"] = h.hexdigest()
    return _notice["digest"]


class _KernelCache(FunctionCache):
    """numba's per-function disk cache, keyed also by :func:`_kernel_sources_digest`."""

    def _index_key(self, sig, codegen):
        return (*super()._index_key(sig, codegen), _kernel_sources_digest())


def jit(func: Callable | None = None, *, inline: bool = False) -> Any:
    """Compile ``func`` with numba (nopython, no fastmath, cached when a cache can be written).

    Used as ``@jit`` or ``@jit(inline=True)``; the latter inlines the function into
    compiled callers at numba's IR level (for small helpers on the hot path: numba
    does not otherwise inline one compiled function into another). The result is a
    numba dispatcher, callable from Python and from other compiled kernels.
    """
    if func is None:
        return lambda f: jit(f, inline=inline)
    _kernels.add(func)
    dispatcher = numba.njit(cache=False, fastmath=False,
                            inline="always" if inline else "never")(func)
    try:
        # what cache=True does, with our key (numba's types omit the private _cache)
        dispatcher._cache = _KernelCache(func)  # type: ignore[attr-defined]
    except RuntimeError as exc:  # numba found no writable cache location: stay uncached
        if "no locator available" not in str(exc):
            raise
    return dispatcher


def kernel_array(values: Any) -> np.ndarray:
    """``values`` as a C-contiguous, writeable ``float64`` array (no copy when it is one).

    No validation (shapes and finiteness are the caller's business); this only
    guarantees that a kernel sees the one array type it was compiled for.
    """
    if (type(values) is np.ndarray and values.dtype == np.float64
            and values.flags.c_contiguous and values.flags.writeable):
        return values
    return np.array(values, dtype=np.float64, order="C", copy=True)
