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
embed helpers from other modules (a fused IK objective holds the FK kernel of
:mod:`moik.robots.fk_kernels`): after an edit of ``fk_kernels.py`` the cached objective would be
stale. So the cache key also holds a digest of every moik module that compiles
kernels (those importing this module); editing one recompiles them all, once.

The cache heals itself. Every index (``.nbi``) and data (``.nbc``) file moik writes
starts with a SHA-256 digest of the rest, checked before numba unpickles or links a
byte of it: a truncated, emptied or bit-flipped file (which would make numba raise
``EOFError``/``UnpicklingError`` or abort the process inside LLVM) is discarded
with a :class:`~moik.exceptions.CacheWarning` and the kernel recompiled; so is an
entry that fails to load for any other reason. A cache that cannot be written (a
full disk, a vanished folder) warns once and the computation goes on uncached.

Kernels compile lazily, at their first call. The first real compilation in a
process (not a load from the cache) prints one line on stderr,
``compiling moik kernels, first run only``, and a long one a progress line
(kernels compiled so far, seconds) every few seconds; they are detected through
numba's ``numba:compile`` event, which numba fires only when it compiles.

:func:`kernel_array` is what every public entry passes its arrays through before a
kernel: numba compiles one machine-code version per argument type, and a
read-only, strided or non-float64 array is another type, so normalising inputs to
C-contiguous, writeable ``float64`` keeps each kernel at its one compiled version.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import os
import pickle
import sys
import time
import uuid
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numba
import numpy as np
from numba.core import event
from numba.core.caching import FunctionCache, IndexDataCacheFile
from numba.experimental import structref

from moik.exceptions import CacheWarning

COMPILE_NOTICE = ("compiling moik kernels, first run only (`moik compile` compiles "
                  "them all at once)")

_kernels: set[Callable] = set()  # the Python functions compiled by jit
_notice: dict[str, Any] = {"printed": False}  # and the sources digest, once computed
_warned: set[str] = set()  # the kinds of cache warning already issued in this process
_MAGIC = b"moik-kernel-cache-1\n"  # then the SHA-256 digest of the rest, then numba's bytes


PROGRESS_EVERY = 3.0  # seconds between two progress lines of a long compilation


class _CompileNotice(event.Listener):
    """Prints :data:`COMPILE_NOTICE` once, when numba starts compiling a moik kernel, and
    then a progress line (kernels compiled so far, seconds) whenever a kernel's
    compilation ends at least :data:`PROGRESS_EVERY` seconds after the last line (a whole
    line each time: no carriage return that later output could land on)."""

    def on_start(self, ev: event.Event) -> None:
        if not _ours(ev):
            return
        if not _notice["printed"]:
            _notice["printed"] = True
            _compiled["since"] = _compiled["last"] = time.perf_counter()
            print(COMPILE_NOTICE, file=sys.stderr, flush=True)
        _compiled["kernels"] += 1

    def on_end(self, ev: event.Event) -> None:
        if not _ours(ev):
            return
        now = time.perf_counter()
        if now - _compiled["last"] >= PROGRESS_EVERY:
            _compiled["last"] = now
            print(f"  ... {_compiled['kernels']} kernels compiled so far "
                  f"({now - _compiled['since']:.0f} s)", file=sys.stderr, flush=True)


def _ours(ev: event.Event) -> bool:
    """Whether a numba compile event is for a moik kernel."""
    data = ev.data if isinstance(ev.data, dict) else {}
    return getattr(data.get("dispatcher"), "py_func", None) in _kernels


# moik kernel compilations in this process (compile_count) and the times of the notice
# and of the last progress line
_compiled: dict[str, Any] = {"kernels": 0, "since": 0.0, "last": 0.0}


def compile_count() -> int:
    """How many moik kernels this process has compiled (not loaded from the cache)."""
    return _compiled["kernels"]


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


def _warn_once(kind: str, message: str) -> None:
    if kind not in _warned:
        _warned.add(kind)
        warnings.warn(message, CacheWarning, stacklevel=2)


def _discard(path: str, why: str) -> None:
    """Removes a damaged cache file (best effort: the next save overwrites it anyway)."""
    _warn_once("damaged", f"moik: discarded a damaged kernel cache file {path} ({why}); "
                          "recompiling")
    with contextlib.suppress(OSError):
        os.unlink(path)


class _CheckedCacheFile(IndexDataCacheFile):
    """numba's index and data files, each written with a digest that is checked on load.

    numba unpickles the index and links the data file's object code as it finds
    them; a damaged file raises there or aborts the process. Here every file is
    ``_MAGIC + sha256(body) + body``, written to a temporary name and renamed (as
    numba does), and a file whose digest does not match is discarded unread.
    """

    def _read_checked(self, path: str) -> bytes | None:
        try:
            with open(path, "rb") as f:
                raw = f.read()
        except OSError:  # gone (numba's load treats a missing file so), or unreadable
            return None
        head = len(_MAGIC) + hashlib.sha256().digest_size
        body = raw[head:]
        if raw[:len(_MAGIC)] == _MAGIC and hashlib.sha256(body).digest() == raw[len(_MAGIC):head]:
            return body
        if not raw.startswith(b"\x80"):  # a pickle's first byte: numba's plain format
            _discard(path, "checksum mismatch" if raw else "empty file")
        # a plain numba file (an older moik) is ignored quietly and overwritten at the save
        return None

    def _load_index(self) -> dict:
        body = self._read_checked(self._index_path)
        if body is None:
            return {}
        try:
            stream = io.BytesIO(body)
            if pickle.load(stream) != self._version:
                return {}  # another numba's cache: overwritten at the next save
            stamp, overloads = pickle.loads(stream.read())
        except Exception as exc:  # noqa: BLE001 - intact bytes that do not unpickle
            _discard(self._index_path, f"{type(exc).__name__}: {exc}")
            return {}
        return overloads if stamp == self._source_stamp else {}

    def _load_data(self, name: str) -> Any:
        path = self._data_path(name)
        body = self._read_checked(path)
        if body is None:
            return None  # numba then compiles, and the save overwrites the file
        try:
            return pickle.loads(body)
        except Exception as exc:  # noqa: BLE001
            _discard(path, f"{type(exc).__name__}: {exc}")
            return None

    @contextlib.contextmanager
    def _open_for_write(self, filepath: str):
        buffer = io.BytesIO()
        yield buffer
        body = buffer.getvalue()
        tmpname = f"{filepath}.tmp.{uuid.uuid4().hex[:16]}"
        try:
            with open(tmpname, "wb") as f:
                f.write(_MAGIC + hashlib.sha256(body).digest() + body)
            os.replace(tmpname, filepath)
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(tmpname)
            raise


class _KernelCache(FunctionCache):
    """numba's per-function disk cache, keyed also by :func:`_kernel_sources_digest`,
    with checked files (:class:`_CheckedCacheFile`) and saves that never fail a call."""

    def __init__(self, py_func: Callable):
        super().__init__(py_func)
        self._cache_file = _CheckedCacheFile(
            cache_path=self._cache_path, filename_base=self._impl.filename_base,
            source_stamp=self._impl.locator.get_source_stamp())

    def _index_key(self, sig, codegen):
        return (*super()._index_key(sig, codegen), _kernel_sources_digest())

    def _load_overload(self, sig, target_context):
        try:
            return super()._load_overload(sig, target_context)
        except Exception as exc:  # noqa: BLE001 - an intact file numba cannot rebuild
            _warn_once("damaged", f"moik: discarded a kernel cache entry of {self._name} that "
                                  f"failed to load ({type(exc).__name__}: {exc}); recompiling")
            return None

    def save_overload(self, sig, data):
        try:
            super().save_overload(sig, data)
        except OSError as exc:  # a full disk, a vanished or read-only folder
            self.disable()
            _warn_once("save", f"moik: cannot write the kernel cache in {self._cache_path} "
                               f"({exc}); going on without it (kernels compile in every "
                               "process until it can be written)")


def jit(func: Callable | None = None) -> Any:
    """Compile ``func`` with numba (nopython, no fastmath, cached when a cache can be written).

    Used as ``@jit``. The result is a numba dispatcher, callable from Python and from
    other compiled kernels. No helper is inlined at numba's IR level (``inline="always"``):
    measured, that made the first compile of the solver about 25 % slower (32.5 -> 25.3 s
    for a cold first solve, empty cache) and no kernel faster (LLVM inlines small
    callees itself; the same results bit for bit).
    """
    if func is None:
        return jit
    _kernels.add(func)
    dispatcher = numba.njit(cache=False, fastmath=False)(func)
    try:
        # what cache=True does, with our key (numba's types omit the private _cache)
        dispatcher._cache = _KernelCache(func)  # type: ignore[attr-defined]
    except RuntimeError as exc:  # numba found no writable cache location: stay uncached
        if "no locator available" not in str(exc):
            raise
    return dispatcher


def is_cached(dispatcher: Any) -> bool:
    """Whether the kernel cache holds a version of ``dispatcher`` (a :func:`jit` kernel)
    compiled from the current sources, for any signature; also True when it has no cache
    (nothing another process compiles could reach it)."""
    cache = getattr(dispatcher, "_cache", None)
    if not isinstance(cache, _KernelCache):
        return True
    digest = _kernel_sources_digest()
    with contextlib.suppress(Exception):  # an unreadable index: as if empty
        return any(key[-1] == digest for key in cache._cache_file._load_index())
    return False


def kernel_array(values: Any) -> np.ndarray:
    """``values`` as a C-contiguous, writeable ``float64`` array (no copy when it is one).

    No validation (shapes and finiteness are the caller's business); this only
    guarantees that a kernel sees the one array type it was compiled for.
    """
    if (type(values) is np.ndarray and values.dtype == np.float64
            and values.flags.c_contiguous and values.flags.writeable):
        return values
    return np.array(values, dtype=np.float64, order="C", copy=True)


def define_struct(proxy: type, struct_type: type, fields: Sequence[str]) -> None:
    """``numba.experimental.structref.define_proxy(proxy, struct_type, fields)``: ``proxy(*values)``
    builds the StructRef in Python and in compiled code.

    Under ``NUMBA_DISABLE_JIT=1`` (every kernel runs as plain Python, numba's debugging mode)
    numba's constructor calls itself without end (numba issue #7117); there ``proxy(*values)``
    is a plain object holding the fields as attributes, which is all Python kernels read.
    """
    structref.define_proxy(proxy, struct_type, list(fields))
    if getattr(numba.config, "DISABLE_JIT", False):
        names = tuple(fields)

        def plain(cls: type, *values: Any) -> Any:
            instance: Any = object.__new__(cls)
            for name, value in zip(names, values, strict=True):
                setattr(instance, name, value)
            return instance

        proxy.__new__ = plain  # type: ignore[assignment]


def objectives_row(spec, Q, out, i):
    """The objectives of row ``i`` of ``Q`` into ``out[i]`` for a problem's compiled
    objectives ``spec`` (moik's IK problems:
    :class:`~moik.problems.ik_kernels.IKObjectives`, from their ``compiled_objectives()``).

    The protocol by which an algorithm's kernel (which may not import a problem) evaluates
    one row at a time without returning to Python: the problem's module overloads this
    function for the numba type of its ``spec``, and numba picks that implementation when
    it compiles the caller. Called from Python, it is ``spec.write_row(Q, out, i)``.
    """
    spec.write_row(Q, out, i)
