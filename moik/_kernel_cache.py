"""moik's kernel disk cache: numba's per-function cache, keyed by every kernel module's source
and healing itself (used by :func:`moik._jit.jit`).

numba keys a cached function by its own source file only, while moik's kernels
embed helpers from other modules (a fused IK objective holds the FK kernel of
:mod:`moik.robots.fk_kernels`): after an edit of ``fk_kernels.py`` the cached objective would be
stale. So the cache key also holds a digest of every moik module that compiles
kernels (those importing :mod:`moik._jit`); editing one recompiles them all, once.

The cache heals itself. Every index (``.nbi``) and data (``.nbc``) file moik writes
starts with a SHA-256 digest of the rest, checked before numba unpickles or links a
byte of it: a truncated, emptied or bit-flipped file (which would make numba raise
``EOFError``/``UnpicklingError`` or abort the process inside LLVM) is discarded
with a :class:`~moik.exceptions.CacheWarning` and the kernel recompiled; so is an
entry that fails to load for any other reason, and one that loads but holds another
kernel's code or another signature (intact files that disagree, which would otherwise
fail or compute the wrong thing when called). A cache that cannot be written (a
full disk, a vanished folder) warns once and the computation goes on uncached.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import os
import pickle
import uuid
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

from numba.core.caching import FunctionCache, IndexDataCacheFile

from moik.exceptions import CacheWarning

MAGIC = b"moik-kernel-cache-1\n"  # then the SHA-256 digest of the rest, then numba's bytes
warned: set[str] = set()  # the kinds of cache warning already issued in this process
_digest: dict[str, str] = {}  # the sources digest, once computed


def sources_digest() -> str:
    """SHA-256 of the source of every moik module that compiles kernels, and of
    :mod:`moik._jit` (the options they are compiled with)."""
    if "digest" not in _digest:
        h = hashlib.sha256()
        for path in sorted(Path(__file__).parent.rglob("*.py")):
            text = path.read_bytes()
            if b"moik._jit import" in text or path.name == "_jit.py":  # or the jit options
                h.update(path.relative_to(Path(__file__).parent).as_posix().encode())
                h.update(text)
        _digest["digest"] = h.hexdigest()
    return _digest["digest"]


def warn_once(kind: str, message: str) -> None:
    if kind not in warned:
        warned.add(kind)
        warnings.warn(message, CacheWarning, stacklevel=2)


def discard(path: str, why: str) -> None:
    """Removes a damaged cache file (best effort: the next save overwrites it anyway)."""
    warn_once("damaged", f"moik: discarded a damaged kernel cache file {path} ({why}); "
                          "recompiling")
    with contextlib.suppress(OSError):
        os.unlink(path)


class CheckedCacheFile(IndexDataCacheFile):
    """numba's index and data files, each written with a digest that is checked on load.

    numba unpickles the index and links the data file's object code as it finds
    them; a damaged file raises there or aborts the process. Here every file is
    ``MAGIC + sha256(body) + body``, written to a temporary name and renamed (as
    numba does), and a file whose digest does not match is discarded unread.
    """

    def _read_checked(self, path: str) -> bytes | None:
        try:
            with open(path, "rb") as f:
                raw = f.read()
        except OSError:  # gone (numba's load treats a missing file so), or unreadable
            return None
        head = len(MAGIC) + hashlib.sha256().digest_size
        body = raw[head:]
        if raw[:len(MAGIC)] == MAGIC and hashlib.sha256(body).digest() == raw[len(MAGIC):head]:
            return body
        if not raw.startswith(b"\x80"):  # a pickle's first byte: numba's plain format
            discard(path, "checksum mismatch" if raw else "empty file")
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
            discard(self._index_path, f"{type(exc).__name__}: {exc}")
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
            discard(path, f"{type(exc).__name__}: {exc}")
            return None

    @contextlib.contextmanager
    def _open_for_write(self, filepath: str):
        buffer = io.BytesIO()
        yield buffer
        body = buffer.getvalue()
        tmpname = f"{filepath}.tmp.{uuid.uuid4().hex[:16]}"
        try:
            with open(tmpname, "wb") as f:
                f.write(MAGIC + hashlib.sha256(body).digest() + body)
            os.replace(tmpname, filepath)
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(tmpname)
            raise


class KernelCache(FunctionCache):
    """numba's per-function disk cache, keyed also by :func:`sources_digest`,
    with checked files (:class:`CheckedCacheFile`) and saves that never fail a call."""

    def __init__(self, py_func: Callable):
        super().__init__(py_func)
        self._cache_file = CheckedCacheFile(
            cache_path=self._cache_path, filename_base=self._impl.filename_base,
            source_stamp=self._impl.locator.get_source_stamp())

    def _index_key(self, sig, codegen):
        return (*super()._index_key(sig, codegen), sources_digest())

    def _load_overload(self, sig, target_context):
        try:
            result = super()._load_overload(sig, target_context)
        except Exception as exc:  # noqa: BLE001 - an intact file numba cannot rebuild
            warn_once("damaged", f"moik: discarded a kernel cache entry of {self._name} that "
                                  f"failed to load ({type(exc).__name__}: {exc}); recompiling")
            return None
        why = None if result is None else self._mismatch(result, sig)
        if why is not None:  # a whole, valid-looking entry of another kernel or signature
            warn_once("damaged", f"moik: discarded a kernel cache entry of {self._name} that "
                                  f"holds {why}; recompiling")
            return None
        return result

    def _mismatch(self, result: Any, sig: Any) -> str | None:
        """What makes a loaded entry not this kernel's compiled ``sig`` (None: it is).

        An index and a data file that are each intact can still disagree (a data file
        renamed or copied over another, two writers numbering their entries alike): the
        entry would load and then run another kernel's code, or fail, when called."""
        try:
            fndesc, loaded = result.fndesc, tuple(result.signature.args)
            wanted = tuple(getattr(sig, "args", sig))
        except Exception:  # noqa: BLE001 - not a compile result at all
            return "no compiled function"
        func = self._py_func
        if (fndesc.qualname, fndesc.modname) != (func.__qualname__, func.__module__):
            return f"the code of {fndesc.modname}.{fndesc.qualname}"
        if loaded != wanted:
            return f"the signature {loaded} instead of {wanted}"
        return None

    def save_overload(self, sig, data):
        try:
            super().save_overload(sig, data)
        except OSError as exc:  # a full disk, a vanished or read-only folder
            self.disable()
            warn_once("save", f"moik: cannot write the kernel cache in {self._cache_path} "
                               f"({exc}); going on without it (kernels compile in every "
                               "process until it can be written)")
