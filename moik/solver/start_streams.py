"""The random starts of a batch, drawn in compiled code, bit for bit as ``solve_ik`` draws them.

``solve_ik(robot, target, seed=s)`` draws its random starts from
``Generator(PCG64(starts_sequence(s)))`` (:func:`moik.solver.options.starts_sequence`):
``lower + (upper - lower) * rng.random((k, dof))``. A batch of ``n`` targets needs ``n``
such generators; seeding each through numpy's ``SeedSequence`` and ``PCG64`` costs about
30 us of Python (as much as solving an easy target), so :func:`batch_streams` computes the
``n`` PCG64 states in one compiled call and :func:`draw_starts` draws from them.

The algorithms are numpy's, written again here in unsigned integer arithmetic (numpy
keeps them in C/Cython): ``SeedSequence`` (O'Neill's ``seed_seq`` alternative: the
``hashmix``/``mix`` pool of ``numpy/random/bit_generator.pyx`` and its
``generate_state``), PCG64 seeding (``pcg64_set_seed``: ``srandom`` of the 128-bit
LCG with the state and increment from ``generate_state(4, uint64)``), its XSL-RR output
and ``next_double`` (``(x >> 11) * 2**-53``). Equality with numpy's generators is
tested on many seeds, spawn keys and pool sizes, and each batch checks its first target
against numpy before using the compiled streams (:func:`start_streams`).
"""

from __future__ import annotations

import contextlib
from typing import Any

import numba
import numpy as np

from moik._jit import jit

M32 = np.uint64(0xFFFFFFFF)
INIT_A, MULT_A = np.uint64(0x43B0D7E5), np.uint64(0x931E8875)
INIT_B, MULT_B = np.uint64(0x8B51F9DD), np.uint64(0x58F38DED)
MIX_MULT_L, MIX_MULT_R = np.uint64(0xCA01F9DD), np.uint64(0x4973F715)
XSHIFT = np.uint64(16)
PCG_MULT_HI, PCG_MULT_LO = np.uint64(0x2360ED051FC65DA4), np.uint64(0x4385DF649FCCF645)
TO_DOUBLE = 1.0 / 9007199254740992.0  # 2**-53
POOL_SIZE = 4  # numpy's DEFAULT_POOL_SIZE (a SeedSequence made without pool_size)


def uint32_words(x) -> list[int]:
    """numpy's ``_coerce_to_uint32_array`` of an entropy or spawn key: a non-negative
    integer as 32-bit words, lowest first (``[0]`` for 0); a sequence, each element so."""
    if isinstance(x, int | np.integer):
        n = int(x)
        if n < 0:
            raise ValueError("expected a non-negative integer")
        words = [n & 0xFFFFFFFF] if n == 0 else []
        while n > 0:
            words.append(n & 0xFFFFFFFF)
            n >>= 32
        return words
    return [w for v in x for w in uint32_words(v)]


@jit
def _hashmix(value, hash_const):
    """``hashmix`` (value and the running constant, both 32-bit): the new (value, const)."""
    value = (value ^ hash_const) & M32
    hash_const = (hash_const * MULT_A) & M32
    value = (value * hash_const) & M32
    return value ^ (value >> XSHIFT), hash_const


@jit
def _mix(x, y):
    result = ((MIX_MULT_L * x) - (MIX_MULT_R * y)) & M32
    return result ^ (result >> XSHIFT)


@jit
def _pool(entropy, pool_size):
    """``SeedSequence.mix_entropy`` of the assembled entropy words (uint64 holding 32 bits)."""
    mixer = np.zeros(pool_size, dtype=np.uint64)
    h = INIT_A
    for i in range(pool_size):
        mixer[i], h = _hashmix(entropy[i] if i < entropy.size else np.uint64(0), h)
    for i_src in range(pool_size):
        for i_dst in range(pool_size):
            if i_src != i_dst:
                v, h = _hashmix(mixer[i_src], h)
                mixer[i_dst] = _mix(mixer[i_dst], v)
    for i_src in range(pool_size, entropy.size):
        for i_dst in range(pool_size):
            v, h = _hashmix(entropy[i_src], h)
            mixer[i_dst] = _mix(mixer[i_dst], v)
    return mixer


@jit
def _state_words(pool):
    """``generate_state(4, uint64)``: 8 words of 32 bits, paired little-endian."""
    h = INIT_B
    out = np.empty(4, dtype=np.uint64)
    for k in range(4):
        pair = np.zeros(2, dtype=np.uint64)
        for half in range(2):
            v = (pool[(2 * k + half) % pool.size] ^ h) & M32
            h = (h * MULT_B) & M32
            v = (v * h) & M32
            pair[half] = v ^ (v >> XSHIFT)
        out[k] = pair[0] | (pair[1] << np.uint64(32))
    return out


@jit
def _mul_hi(a, b):
    """High 64 bits of the 128-bit product of two 64-bit words."""
    a_lo, a_hi, b_lo, b_hi = a & M32, a >> np.uint64(32), b & M32, b >> np.uint64(32)
    lo_lo, hi_lo, lo_hi, hi_hi = a_lo * b_lo, a_hi * b_lo, a_lo * b_hi, a_hi * b_hi
    cross = (lo_lo >> np.uint64(32)) + (hi_lo & M32) + lo_hi
    return hi_hi + (hi_lo >> np.uint64(32)) + (cross >> np.uint64(32))


@jit
def _step(s_hi, s_lo, i_hi, i_lo):
    """One LCG step of the 128-bit state: ``state * MULT + inc`` (mod 2**128)."""
    hi = _mul_hi(s_lo, PCG_MULT_LO) + s_lo * PCG_MULT_HI + s_hi * PCG_MULT_LO
    lo = s_lo * PCG_MULT_LO
    new_lo = lo + i_lo
    carry = np.uint64(1) if new_lo < lo else np.uint64(0)
    return hi + i_hi + carry, new_lo


@jit
def _seed_state(words, pool_size, state):
    """PCG64 seeded from the SeedSequence of ``words``: ``state = (hi, lo, inc_hi, inc_lo)``."""
    v = _state_words(_pool(words, pool_size))
    inc_hi = (v[2] << np.uint64(1)) | (v[3] >> np.uint64(63))
    inc_lo = (v[3] << np.uint64(1)) | np.uint64(1)
    s_hi, s_lo = _step(np.uint64(0), np.uint64(0), inc_hi, inc_lo)
    lo = s_lo + v[1]
    s_hi, s_lo = s_hi + v[0] + (np.uint64(1) if lo < s_lo else np.uint64(0)), lo
    s_hi, s_lo = _step(s_hi, s_lo, inc_hi, inc_lo)
    state[0], state[1], state[2], state[3] = s_hi, s_lo, inc_hi, inc_lo


@jit(nogil=True)
def batch_streams(base, spawn, rows, states):
    """PCG64 states ``(n, 4)`` of ``SeedSequence(entropy, spawn_key=(*spawn_key, i, key),
    pool_size)`` for ``first <= i < first + n`` (row ``i - first``), ``rows = (pool_size,
    key, first, n)``; ``base``: the entropy's words (uint64 holding 32 bits), ``spawn``: the
    spawn key's words (as :func:`uint32_words`)."""
    pool_size, key, first, n = rows
    n_run = max(base.size, pool_size)  # numpy pads the entropy to the pool with a spawn key
    for r in range(n):
        i = first + r
        n_i = 1 if i < 2**32 else 2
        words = np.zeros(n_run + spawn.size + n_i + 1, dtype=np.uint64)
        words[:base.size] = base
        words[n_run:n_run + spawn.size] = spawn
        words[n_run + spawn.size] = np.uint64(i) & M32
        if n_i == 2:
            words[n_run + spawn.size + 1] = np.uint64(i) >> np.uint64(32)
        words[words.size - 1] = key
        _seed_state(words, pool_size, states[r])


@jit(nogil=True)
def draw_starts(states, lower, upper, out):
    """``out[i] = lower + (upper - lower) * U`` with ``U`` the next ``k * dof`` doubles of
    stream ``i`` (C order, as ``Generator.random((k, dof))``); the states advance."""
    n, k, dof = out.shape
    for i in range(n):
        s_hi, s_lo, i_hi, i_lo = states[i, 0], states[i, 1], states[i, 2], states[i, 3]
        for a in range(k):
            for j in range(dof):
                s_hi, s_lo = _step(s_hi, s_lo, i_hi, i_lo)
                x = s_hi ^ s_lo
                rot = s_hi >> np.uint64(58)
                x = (x >> rot) | (x << ((np.uint64(64) - rot) & np.uint64(63)))
                u = np.float64(x >> np.uint64(11)) * TO_DOUBLE
                out[i, a, j] = lower[j] + (upper[j] - lower[j]) * u
        states[i, 0], states[i, 1] = s_hi, s_lo


def _modulo_2_64() -> contextlib.AbstractContextManager:
    """Overflow warnings off where the kernels run as plain Python (``NUMBA_DISABLE_JIT``:
    numpy's uint64 arithmetic wraps modulo 2**64, as compiled code does, but warns); a
    no-op where they are compiled (``np.errstate`` is Python under the GIL, per chunk)."""
    if getattr(numba.config, "DISABLE_JIT", False):
        return np.errstate(over="ignore")
    return contextlib.nullcontext()


def streams(root: np.random.SeedSequence, key: int, n: int, first: int = 0) -> np.ndarray:
    """The PCG64 states ``(n, 4)`` of the children ``(i, key)`` of ``root``,
    ``first <= i < first + n`` (:func:`batch_streams`)."""
    base = np.array(uint32_words(root.entropy), dtype=np.uint64)
    spawn = np.array(uint32_words(root.spawn_key), dtype=np.uint64)
    states = np.empty((n, 4), dtype=np.uint64)
    with _modulo_2_64():
        batch_streams(base, spawn, (int(root.pool_size), np.uint64(key), int(first), n), states)
    return states


def seed_state(seed: int, key: int) -> dict[str, Any]:
    """``PCG64(SeedSequence(seed, spawn_key=(key,))).state`` of an integer ``seed`` >= 0,
    computed by :func:`_seed_state` (a third of the time numpy's SeedSequence and PCG64
    objects take). :func:`moik.solver.options.start_generator` checks its first against
    numpy's."""
    words, spawn = uint32_words(seed), uint32_words(key)
    n_run = max(len(words), POOL_SIZE)  # numpy pads the entropy to the pool (a spawn key)
    entropy = np.zeros(n_run + len(spawn), dtype=np.uint64)
    entropy[:len(words)] = words
    entropy[n_run:] = spawn
    state = np.empty(4, dtype=np.uint64)
    if getattr(numba.config, "DISABLE_JIT", False):  # plain Python: modulo 2**64, no warning
        with np.errstate(over="ignore"):
            _seed_state(entropy, POOL_SIZE, state)
    else:
        _seed_state(entropy, POOL_SIZE, state)
    hi, lo, inc_hi, inc_lo = state.tolist()
    return {"bit_generator": "PCG64",
            "state": {"state": hi << 64 | lo, "inc": inc_hi << 64 | inc_lo},
            "has_uint32": 0, "uinteger": 0}


def numpy_state(root: np.random.SeedSequence, key: int, i: int) -> np.ndarray:
    """Stream ``i``'s state ``(4,)`` as numpy seeds it (the reference of :func:`streams`)."""
    seq = np.random.SeedSequence(root.entropy, spawn_key=(*root.spawn_key, i, key),
                                 pool_size=root.pool_size)
    st = np.random.PCG64(seq).state["state"]
    m = (1 << 64) - 1
    return np.array([st["state"] >> 64, st["state"] & m, st["inc"] >> 64, st["inc"] & m],
                    dtype=np.uint64)


def streams_match(root: np.random.SeedSequence, key: int, i: int) -> bool:
    """Whether :func:`streams` gives stream ``i`` as numpy seeds it (:func:`numpy_state`)."""
    return bool(np.array_equal(streams(root, key, 1, i)[0], numpy_state(root, key, i)))


def start_streams(root: np.random.SeedSequence, key: int, n: int, first: int = 0, *,
                  checked: bool | None = None) -> np.ndarray:
    """:func:`streams` (of the children ``first .. first + n - 1``), checked on the first
    against numpy's seeding (should numpy ever seed otherwise, every stream is taken from
    numpy's, slowly but equal). ``checked``: the check's answer where the caller has it
    already (:func:`streams_match` once for a batch cut in chunks: its Python would
    otherwise hold the GIL once per chunk)."""
    states = streams(root, key, n, first)
    if checked is None:
        checked = bool(np.array_equal(states[0], numpy_state(root, key, first)))
    if not checked:
        states = np.array([numpy_state(root, key, first + i) for i in range(n)],
                          dtype=np.uint64)
    return states


def draw_rows(states: np.ndarray, rows: np.ndarray, k: int, lower: np.ndarray,
              upper: np.ndarray) -> np.ndarray:
    """``(len(rows), k, dof)`` starts from the streams ``rows`` (:func:`draw_starts`; their
    states advance in ``states``)."""
    out = np.empty((len(rows), k, lower.size))
    sub = np.ascontiguousarray(states[rows])
    with _modulo_2_64():
        draw_starts(sub, lower, upper, out)
    states[rows] = sub
    return out
