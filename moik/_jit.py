"""Numba compilation of moik's kernels, and the one normalisation of kernel inputs.

:func:`jit` compiles a function in nopython mode with ``fastmath`` off and no thread
parallelism, so a kernel's result is bit-reproducible on a machine and does not
depend on the batch it is part of. It asks numba for an on-disk cache
(``cache=True``): numba stores compiled code in ``NUMBA_CACHE_DIR``, beside the
source (``__pycache__``) or in the user cache directory, whichever it can write.
When it can write none of them (a read-only installation and home), numba refuses
to build the cache when the function is decorated; :func:`jit` then compiles
without a cache instead, so importing moik never fails for a cache.

The cache (:mod:`moik._kernel_cache`) is keyed also by the source of every kernel
module, so editing one recompiles the kernels that embed it, and it heals itself: a
damaged file is discarded with a :class:`~moik.exceptions.CacheWarning` and the kernel
recompiled; a cache that cannot be written warns once and the computation goes on.

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
import sys
import time
from collections.abc import Callable, Sequence
from typing import Any

import numba
import numpy as np
from numba.core import event
from numba.core import types as nb_types
from numba.experimental import structref

from moik._kernel_cache import KernelCache, sources_digest

COMPILE_NOTICE = ("compiling moik kernels, first run only (`moik compile` compiles "
                  "them all at once)")

_kernels: set[Callable] = set()  # the Python functions compiled by jit
_notice: dict[str, Any] = {"printed": False}


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
        if _compiled["depth"] == 0:  # a kernel compiling another: counted once
            _compiled["began"] = time.perf_counter()
        _compiled["depth"] += 1

    def on_end(self, ev: event.Event) -> None:
        if not _ours(ev):
            return
        now = time.perf_counter()
        _compiled["depth"] -= 1
        if _compiled["depth"] == 0:
            _compiled["seconds"] += now - _compiled["began"]
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
_compiled: dict[str, Any] = {"kernels": 0, "since": 0.0, "last": 0.0, "seconds": 0.0,
                             "depth": 0, "began": 0.0}


def compile_count() -> int:
    """How many moik kernels this process has compiled (not loaded from the cache)."""
    return _compiled["kernels"]


def compile_seconds() -> float:
    """Wall seconds this process has spent compiling moik kernels, or waiting for a child
    process compiling them (:meth:`moik._background.Background.wait`)."""
    return _compiled["seconds"]


def add_compile_seconds(seconds: float) -> None:
    """Count ``seconds`` (spent waiting for kernels compiled elsewhere) as compiling."""
    _compiled["seconds"] += seconds


event.register("numba:compile", _CompileNotice())


JIT_OPTIONS: dict[str, Any] = {"fastmath": False, "no_cfunc_wrapper": True}
"""numba's options of every kernel (the kernel cache's digest covers this file). No C
wrapper (``no_cfunc_wrapper``): it is only needed to pass a kernel as a first-class
function value, which moik never does, and it is compiled for every kernel
(docs/performance.md, "Compilation and start-up")."""


def jit(func: Callable | None = None, *, inline: bool = False, nogil: bool = False) -> Any:
    """Compile ``func`` with numba (nopython, no fastmath, cached when a cache can be written).

    Used as ``@jit``, or ``@jit(inline=True)`` for a helper that numba inlines at its IR
    level into the kernel that calls it (``inline="always"``): the helper is then compiled
    only as part of its caller, never as a module of its own. numba compiles every kernel
    called by another into a module of its own and links a copy of it into each caller's
    module, where LLVM optimises it and generates machine code for it again, so a helper
    with one call site in each kernel that calls it pays for a module that is never run.
    Inlined are such helpers of the algorithms' and criteria's kernels, and the LM
    iteration (:func:`moik.solver.lm.lm_start`) into its loops. Not inlined: helpers with
    several call sites in one kernel (each site would type and compile its own copy), and
    the LM iteration's own helpers (their caller's typing grows by what their modules
    save). docs/performance.md gives the measurements behind each choice. Called from
    Python, an inlined helper compiles as a kernel of its own.

    ``nogil=True`` releases the GIL while the kernel runs when it is called from Python
    (numba's ``nogil``; the machine code is the same): for the kernels that threads run
    side by side on chunks of a batch (:mod:`moik.solver.parallel`).
    """
    if func is None:
        return lambda f: jit(f, inline=inline, nogil=nogil)
    _kernels.add(func)
    options = {**JIT_OPTIONS, "inline": "always"} if inline else dict(JIT_OPTIONS)
    if nogil:
        options["nogil"] = True
    dispatcher = numba.njit(cache=False, **options)(func)
    if hasattr(dispatcher, "get_call_template"):  # not a plain function (NUMBA_DISABLE_JIT)
        dispatcher.get_call_template = _plain_call_template(dispatcher.get_call_template)
    try:
        # what cache=True does, with our key (numba's types omit the private _cache)
        dispatcher._cache = KernelCache(func)
    except RuntimeError as exc:  # numba found no writable cache location: stay uncached
        if "no locator available" not in str(exc):
            raise
    return dispatcher


def _plain_call_template(resolve: Callable) -> Callable:
    """A kernel's ``get_call_template`` (how numba types a call of it from compiled code)
    that compiles it for the argument types without their literal values.

    numba types a constant argument as a literal (``Literal[int](0)``) and compiles the
    callee once per literal value, and once for a value a caller's type inference saw only
    in passing (a variable set to ``-1`` before a loop sets it): every such version is a
    module of its own, linked and optimised again into each caller (seconds of a first
    run; no kernel of moik needs a literal argument). The results are the same: LLVM
    inlines the constant into the callee's code where it pays. Where the plain types do
    not type (a callee that needs the literal), numba's own resolution is used.
    """
    def get_call_template(args: Sequence[Any], kws: dict[str, Any]) -> Any:
        plain = tuple(nb_types.unliteral(a) for a in args)
        plain_kws = {k: nb_types.unliteral(v) for k, v in kws.items()}
        if plain != tuple(args) or plain_kws != kws:
            with contextlib.suppress(numba.core.errors.TypingError):
                return resolve(plain, plain_kws)
        return resolve(args, kws)

    return get_call_template


def is_cached(dispatcher: Any) -> bool:
    """Whether the kernel cache holds a version of ``dispatcher`` (a :func:`jit` kernel)
    compiled from the current sources, for any signature; also True when it has no cache
    (nothing another process compiles could reach it)."""
    cache = getattr(dispatcher, "_cache", None)
    return not isinstance(cache, KernelCache) or bool(_current_keys(cache))


def _current_keys(cache: KernelCache) -> list:
    """The index keys of ``cache`` compiled from the current sources (none where the index
    cannot be read)."""
    digest = sources_digest()
    with contextlib.suppress(Exception):  # an unreadable index: as if empty
        return [key for key in cache._cache_file._load_index() if key[-1] == digest]
    return []


def is_cached_for(dispatcher: Any, signature: tuple) -> bool:
    """Whether ``dispatcher`` (a :func:`jit` kernel) has a version for the argument types
    ``signature`` (``tuple(dispatcher.typeof_pyval(a) for a in args)``) compiled in this
    process, or in the kernel cache from the current sources (a call then loads it)."""
    if signature in dispatcher.overloads:
        return True
    cache = getattr(dispatcher, "_cache", None)
    return isinstance(cache, KernelCache) and any(key[0] == signature
                                                  for key in _current_keys(cache))


WAIT_LIMIT = 120.0  # seconds a kernel waits for another process compiling it (at most)
_ELSEWHERE: list[tuple[tuple[Any, ...], Callable[[float], object]]] = []


def compiled_elsewhere(kernels: Sequence[Any], wait: Callable[[float], object]) -> None:
    """Say that another process compiles ``kernels`` into the cache: ``wait(seconds)``
    returns when it has ended or the seconds have passed (:mod:`moik.warmup.background`
    registers its children so)."""
    _ELSEWHERE.append((tuple(kernels), wait))


def await_elsewhere(dispatcher: Any) -> None:
    """Before a call that would compile ``dispatcher``: where it is neither compiled here
    nor cached but another process compiles it (:func:`compiled_elsewhere`), wait until
    that process ends (at most :data:`WAIT_LIMIT` seconds), so that the call loads it
    instead of compiling it a second time side by side."""
    if not _ELSEWHERE or getattr(dispatcher, "overloads", None) or is_cached(dispatcher):
        return
    for kernels, wait in _ELSEWHERE:
        if any(k is dispatcher for k in kernels):
            wait(WAIT_LIMIT)


def kernel_array(values: Any) -> np.ndarray:
    """``values`` as a C-contiguous, writeable ``float64`` array (no copy when it is one).

    No validation (shapes and finiteness are the caller's business); this only
    guarantees that a kernel sees the one array type it was compiled for.
    """
    if (type(values) is np.ndarray and values.dtype == np.float64
            and values.flags.c_contiguous and values.flags.writeable):
        return values
    return np.array(values, dtype=np.float64, order="C", copy=True)


class StructType(nb_types.StructRef):
    """A numba StructRef type whose literal field types are widened (a field set from the
    literal ``0`` holds any integer): the base of moik's StructRef types, each registered
    with ``numba.experimental.structref.register`` and given a proxy by :func:`define_struct`."""

    def preprocess_fields(self, fields):
        return tuple((name, nb_types.unliteral(typ)) for name, typ in fields)


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
