"""The search options of :func:`moik.solver.solve_ik`, validated together and up front.

Every option is checked before any stage runs, so a bad value raises whichever
stage would have ended the solve (the batched first attempt often solves a pose
before the search, whose options would otherwise never be looked at).
:func:`moik.solver.solve_path` validates the options it passes on the same way.
"""

from __future__ import annotations

import functools
import importlib
import threading
from dataclasses import dataclass
from typing import Any

import numpy as np

from moik._validate import choice, flag, integer, keywords, optional_integer, positive
from moik._validate import seed as check_seed
from moik.exceptions import ParameterError
from moik.kinematics.orientation import available_metrics

# solve_ik's search options and their defaults (solve_ik's signature repeats them; a test
# keeps the two equal)
SEARCH_DEFAULTS = {"method": "eosma", "orientation": "geodesic", "polish": True,
                   "n_solutions": 1, "max_evals": 50_000, "starts": 500, "pop_size": None,
                   "generations": 15, "candidates_per_round": 3, "distinct": 0.1,
                   "patience": 30, "front_method": "moeosma", "front_evals": 10_000}

DEFAULT_POP_SIZES = (20, 40)  # search population: one solution wanted, several

# (name, smallest value) of the integer options
_COUNTS = (("n_solutions", 1), ("max_evals", 1), ("starts", 0), ("generations", 1),
           ("candidates_per_round", 1), ("patience", 1), ("front_evals", 1))


@dataclass(frozen=True, kw_only=True)
class SearchOptions:
    """Validated options of one :func:`~moik.solver.solve_ik` call (see its arguments).

    Integers refuse bools and floats (``2.0``); ``orientation`` is an
    orientation-metric name (case-insensitive, stored lower-case); ``pop_size``
    ``None`` becomes 20, or 40 when several solutions are wanted, and must suit
    ``method`` (EOSMA needs at least 3).

    Raises:
        ParameterError: A value out of its range or of the wrong kind, or an
            algorithm of the wrong kind for ``method`` / ``front_method``.
        UnknownNameError: An unknown algorithm or orientation-metric name,
            listing the valid ones.
    """

    method: str
    orientation: str
    polish: bool
    n_solutions: int
    max_evals: int
    starts: int
    pop_size: int | None
    generations: int
    candidates_per_round: int
    distinct: float
    patience: int
    front_method: str
    front_evals: int

    def __post_init__(self) -> None:
        for name, low in _COUNTS:
            object.__setattr__(self, name, integer(name, getattr(self, name), minimum=low))
        pop_size = optional_integer("pop_size", self.pop_size, minimum=2)
        if pop_size is None:
            pop_size = DEFAULT_POP_SIZES[0] if self.n_solutions == 1 else DEFAULT_POP_SIZES[1]
        object.__setattr__(self, "pop_size", pop_size)
        object.__setattr__(self, "distinct", positive("distinct", self.distinct))
        object.__setattr__(self, "polish", flag("polish", self.polish))
        object.__setattr__(self, "orientation",
                           choice("orientation metric", self.orientation, available_metrics()))
        if isinstance(self.method, str) and isinstance(self.front_method, str):
            _check_algorithms(self.method, self.front_method, pop_size)  # cached: a hot path
        else:
            _check_algorithms.__wrapped__(self.method, self.front_method, pop_size)


def algorithm_registry() -> Any:
    """:mod:`moik.algorithms.registry`, loaded when a search or a non-default method needs it.

    Importing every algorithm (and pymoo's) takes about 0.2 s, most of a process's first
    solve, while the first stage solves nearly every pose without one: deferred for
    start-up time, not for an import cycle.
    """
    return importlib.import_module("moik.algorithms.registry")


@functools.lru_cache(maxsize=64)
def _check_algorithms(method: str, front_method: str, pop_size: int) -> None:
    """The kinds of ``method`` / ``front_method`` and ``method``'s own limits on ``pop_size``.

    The defaults (``"eosma"``, ``"moeosma"`` with the default population sizes) are
    known to pass (a test checks them against the registry) and are not looked up.
    """
    if (method, front_method) == (SEARCH_DEFAULTS["method"], SEARCH_DEFAULTS["front_method"]) \
            and pop_size in DEFAULT_POP_SIZES:
        return
    registry = algorithm_registry()
    is_multi_objective = registry.is_multi_objective
    if is_multi_objective(method):  # also raises UnknownNameError for an unknown name
        raise ParameterError(f"method must be a single-objective algorithm, got {method!r}")
    if not is_multi_objective(front_method):
        raise ParameterError(f"front_method must be a multi-objective algorithm, got "
                             f"{front_method!r}")
    registry.get_algorithm(method, pop_size=pop_size)


def validated_options(**values) -> SearchOptions:
    """:class:`SearchOptions` of ``values``, cached (solve_ik's hot path validates the same
    options over and over). The key holds each value's type: ``True`` and ``1`` (or ``2.0``
    and ``2``) are equal and hash alike, but must not share a validation."""
    given = tuple(values.values())
    try:
        return _OPTIONS[(tuple(values), given, tuple(map(type, given)))]
    except KeyError:
        options = SearchOptions(**values)
        if len(_OPTIONS) >= 256:
            _OPTIONS.clear()
        _OPTIONS[(tuple(values), given, tuple(map(type, given)))] = options
        return options
    except TypeError:  # an unhashable value: validate uncached (it raises)
        return SearchOptions(**values)


_OPTIONS: dict[tuple, SearchOptions] = {}  # validated options by (names, values, types)


def search_options(owner: str, options: dict) -> SearchOptions:
    """:class:`SearchOptions` from keyword ``options`` over :data:`SEARCH_DEFAULTS`.

    Raises:
        ParameterError: An unknown keyword (listing the accepted ones) or a bad value.
    """
    keywords(owner, options, SEARCH_DEFAULTS)
    return validated_options(**{**SEARCH_DEFAULTS, **options})


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


_PCG64_STATES: dict[int, Any] = {}  # PCG64(SeedSequence(seed)).state of integer seeds seen
_MAX_STATES = 4096
_LOCAL = threading.local()


def start_generator(seed: int) -> np.random.Generator:
    """``Generator(PCG64(starts_sequence(seed)))`` for an integer ``seed`` >= 0, bit for bit.

    Seeding a PCG64 through a SeedSequence costs more than a whole first-stage solve
    takes, so the initial state of each seed is kept (up to ``_MAX_STATES`` seeds) and
    loaded into one generator per thread. The generator is reset by the next call on
    the same thread: use it within one solve only.
    """
    state = _PCG64_STATES.get(seed)
    if state is None:
        if len(_PCG64_STATES) >= _MAX_STATES:
            _PCG64_STATES.clear()
        state = _PCG64_STATES[seed] = np.random.PCG64(starts_sequence(seed)).state
    generator = getattr(_LOCAL, "generator", None)
    if generator is None:
        generator = _LOCAL.generator = np.random.Generator(np.random.PCG64(0))
    generator.bit_generator.state = state
    return generator
