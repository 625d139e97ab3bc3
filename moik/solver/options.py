"""The search options of :func:`moik.solver.solve_ik`, validated together and up front.

Every option is checked before any stage runs, so a bad value raises whichever
stage would have ended the solve (the batched first attempt often solves a pose
before the search, whose options would otherwise never be looked at).
:func:`moik.solver.solve_path` validates the options it passes on the same way.
"""

from __future__ import annotations

import importlib
import operator
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from moik._validate import choice, flag, integer, keywords, optional_integer, positive
from moik._validate import seed as check_seed
from moik.exceptions import ParameterError
from moik.kinematics.orientation import available_metrics
from moik.solver.start_streams import seed_state

DEFAULT_POP_SIZES = (20, 40)  # search population: one solution wanted, several

MAX_SOLUTIONS = 100_000
"""Most distinct solutions one solve may ask for (each costs memory up front)."""
MAX_POP_SIZE = 10**6
"""Largest search population."""


def at_most(name: str, value: int, high: int) -> int:
    """``value`` if it is at most ``high``.

    Raises:
        ParameterError: Naming ``name`` and the bound (what is allocated up front grows
            with it: ``n_solutions=1000000000`` would ask for 67 GiB).
    """
    if value > high:
        raise ParameterError(f"{name} must be at most {high}, got {value}")
    return value

# (name, smallest value, largest value) of the integer options: the largest keep what
# is allocated up front bounded (a typo such as 1000000000 must not ask for 67 GiB)
_COUNTS = (("n_solutions", 1, MAX_SOLUTIONS), ("max_evals", 1, 10**12), ("starts", 0, 10**6),
           ("generations", 1, 10**7), ("candidates_per_round", 1, 10**4),
           ("patience", 1, 10**7), ("front_evals", 1, 10**12))


@dataclass(frozen=True, kw_only=True)
class SearchOptions:
    """Validated options of one :func:`~moik.solver.solve_ik` call (see its arguments).

    The field defaults are solve_ik's defaults, and the only place they are written:
    ``solve_ik``'s signature, ``solve_ik_batch`` and the CLI read them from
    :data:`SEARCH_DEFAULTS` (``{field: default}``). Integers refuse bools and floats
    (``2.0``); ``orientation`` is an orientation-metric name (case-insensitive, stored
    lower-case); ``pop_size`` ``None`` becomes 20, or 40 when several solutions are
    wanted, and must suit ``method`` (EOSMA needs at least 3).

    Raises:
        ParameterError: A value out of its range or of the wrong kind, or an
            algorithm of the wrong kind for ``method`` / ``front_method``.
        UnknownNameError: An unknown algorithm or orientation-metric name,
            listing the valid ones.
    """

    method: str = "eosma"
    orientation: str = "geodesic"
    polish: bool = True
    n_solutions: int = 1
    max_evals: int = 50_000
    starts: int = 500
    pop_size: int | None = None
    generations: int = 15
    candidates_per_round: int = 3
    distinct: float = 0.1
    patience: int = 30
    front_method: str = "moeosma"
    front_evals: int = 10_000

    def __post_init__(self) -> None:
        for name, low, high in _COUNTS:
            value = integer(name, getattr(self, name), minimum=low)
            object.__setattr__(self, name, at_most(name, value, high))
        pop_size = optional_integer("pop_size", self.pop_size, minimum=2)
        if pop_size is not None:
            at_most("pop_size", pop_size, MAX_POP_SIZE)
        if pop_size is None:
            pop_size = DEFAULT_POP_SIZES[0] if self.n_solutions == 1 else DEFAULT_POP_SIZES[1]
        object.__setattr__(self, "pop_size", pop_size)
        object.__setattr__(self, "distinct", positive("distinct", self.distinct))
        object.__setattr__(self, "polish", flag("polish", self.polish))
        object.__setattr__(self, "orientation",
                           choice("orientation metric", self.orientation, available_metrics()))
        _check_algorithms(self.method, self.front_method, pop_size)

    @classmethod
    def of(cls, **values) -> SearchOptions:
        """``SearchOptions(**values)``; when every value is its field's default object
        (``solve_ik``'s signature passes them through: an identity test, so ``True`` for
        ``1`` is still validated), the one validated :data:`DEFAULT_OPTIONS` instead
        (solve_ik's hot path: validating costs about a third of a first-stage solve)."""
        if all(map(operator.is_, values.values(), map(SEARCH_DEFAULTS.__getitem__, values))):
            return DEFAULT_OPTIONS
        return cls(**values)


SEARCH_DEFAULTS: dict[str, Any] = {f.name: f.default for f in fields(SearchOptions)}
"""solve_ik's search options and their defaults, read from :class:`SearchOptions`."""


def algorithm_registry() -> Any:
    """:mod:`moik.algorithms.registry`, loaded when a search or a non-default method needs it.

    Importing every algorithm (and pymoo's) is most of a process's first solve, while the
    first stage solves nearly every pose without one: deferred for start-up time, not for
    an import cycle.
    """
    return importlib.import_module("moik.algorithms.registry")


def _check_algorithms(method: str, front_method: str, pop_size: int) -> None:
    """The kinds of ``method`` / ``front_method`` and ``method``'s own limits on ``pop_size``.

    The defaults (``"eosma"``, ``"moeosma"`` with the default population sizes) are
    known to pass (a test checks them against the registry) and are not looked up:
    loading the registry is most of a first solve, and the first stage solves most poses
    without it.
    """
    if (method, front_method) == ("eosma", "moeosma") and pop_size in DEFAULT_POP_SIZES:
        return
    registry = algorithm_registry()
    is_multi_objective = registry.is_multi_objective
    if is_multi_objective(method):  # also raises UnknownNameError for an unknown name
        raise ParameterError(f"method must be a single-objective algorithm, got {method!r}")
    if not is_multi_objective(front_method):
        raise ParameterError(f"front_method must be a multi-objective algorithm, got "
                             f"{front_method!r}")
    registry.get_algorithm(method, pop_size=pop_size)


def search_options(owner: str, options: dict) -> SearchOptions:
    """:class:`SearchOptions` from keyword ``options`` over :data:`SEARCH_DEFAULTS`.

    Raises:
        ParameterError: An unknown keyword (listing the accepted ones) or a bad value.
    """
    keywords(owner, options, SEARCH_DEFAULTS)
    return SearchOptions.of(**{**SEARCH_DEFAULTS, **options})


def seed_sequence(seed) -> np.random.SeedSequence:
    """``seed`` validated (``None``, an integer >= 0 or a SeedSequence) as a ``SeedSequence``."""
    seed = check_seed("seed", seed)
    return seed if isinstance(seed, np.random.SeedSequence) else np.random.SeedSequence(seed)


STARTS_KEY = 0x6D6F696B
"""The spawn key of the random starts' stream: ``SeedSequence(seed, spawn_key=(STARTS_KEY,))``.

Not the seed's own stream, which :func:`moik.problems.random_reachable_targets` (and
``numpy.random.default_rng(seed)``) draws from: with one stream the first start of
``solve_ik(..., seed=s)`` was the configuration a target of ``seed=s`` came from."""


def starts_sequence(seed: int | np.random.SeedSequence) -> np.random.SeedSequence:
    """The SeedSequence of the random starts of ``seed`` (:data:`STARTS_KEY`)."""
    if isinstance(seed, np.random.SeedSequence):
        return np.random.SeedSequence(seed.entropy, spawn_key=(*seed.spawn_key, STARTS_KEY),
                                      pool_size=seed.pool_size)
    return np.random.SeedSequence(seed, spawn_key=(STARTS_KEY,))


_PCG64_STATES: dict[int, Any] = {}  # PCG64(starts_sequence(seed)).state of seeds seen
_MAX_STATES = 4096
_FREE: list[np.random.Generator] = []  # generators no solve holds


class start_generator:  # noqa: N801 (used as a function: ``with start_generator(seed)``)
    """``Generator(PCG64(starts_sequence(seed)))`` for an integer ``seed`` >= 0, bit for
    bit, held for the ``with`` block.

    Seeding a PCG64 through numpy's SeedSequence costs a sixth of a first-stage solve,
    the compiled seeding (:func:`_seeded`) a third of that, loading a kept state into an
    existing generator less. So the initial
    state of each seed is kept (up to ``_MAX_STATES`` seeds), and generators are lent from
    a free list: a solve that re-enters ``solve_ik`` (or another thread) gets a generator
    of its own, never one another block still holds.
    """

    def __init__(self, seed: int):
        state = _PCG64_STATES.get(seed)
        if state is None:
            if len(_PCG64_STATES) >= _MAX_STATES:
                _PCG64_STATES.clear()
            state = _PCG64_STATES[seed] = _seeded(seed)
        self._state = state

    def __enter__(self) -> np.random.Generator:
        try:
            self._generator = _FREE.pop()
        except IndexError:
            self._generator = np.random.Generator(np.random.PCG64(0))
        self._generator.bit_generator.state = self._state
        return self._generator

    def __exit__(self, *exc) -> None:
        _FREE.append(self._generator)


DEFAULT_OPTIONS = SearchOptions()
"""The options of a call that changes none (validated once)."""


_SEEDING: dict[str, bool] = {}  # "first": a seed was given; "compiled": equals numpy's


def _seeded(seed: int) -> Any:
    """``PCG64(starts_sequence(seed)).state``: numpy's for the first seed of the process (a
    process that solves once never compiles the seeding), then compiled
    (:func:`~moik.solver.start_streams.seed_state`), checked against numpy's on the second
    seed (should numpy ever seed otherwise, numpy's is used)."""
    if "compiled" not in _SEEDING:
        state = np.random.PCG64(starts_sequence(seed)).state
        if "first" in _SEEDING:
            _SEEDING["compiled"] = seed_state(seed, STARTS_KEY) == state
        _SEEDING["first"] = True
        return state
    if _SEEDING["compiled"]:
        return seed_state(seed, STARTS_KEY)
    return np.random.PCG64(starts_sequence(seed)).state
