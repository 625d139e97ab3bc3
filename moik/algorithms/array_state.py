"""The helpers of the one array-state base (:mod:`moik.algorithms.array_base`).

Keyword and size validation (a misspelled option must not pass silently), finite
bounds, the schedule rule (:func:`planned_iterations`, the length T of the papers' t/T
schedules from the current termination), the initial population (uniform, optionally
seeded with ``X0``) and the evaluation budget.
"""

from __future__ import annotations

import functools
import inspect
import math
from collections.abc import Generator

import numpy as np
from pymoo.core.algorithm import Algorithm
from pymoo.core.population import Population
from pymoo.core.sampling import Sampling
from pymoo.core.termination import TerminateIfAll, TerminateIfAny
from pymoo.termination.default import DefaultTermination
from pymoo.termination.delta import DeltaToleranceTermination

from moik._validate import integer, is_integer, keywords
from moik.algorithms.mechanics import clip_to_bounds, uniform_population
from moik.exceptions import NonFiniteError, ParameterError, ShapeError

DEFAULT_SCHEDULE_LENGTH = 1000
"""T when neither ``max_iter`` nor any termination criterion bounds the run."""

Step = Generator[np.ndarray, tuple, None]
"""One generation: yields candidate arrays ``X``, receives ``(F, CV)`` for each."""

PYMOO_OPTIONS: frozenset[str] = frozenset(
    p.name for p in inspect.signature(Algorithm.__init__).parameters.values()
    if p.name != "self" and p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY))
"""The options of pymoo's ``Algorithm.__init__`` (termination, output, display, callback,
archive, return_least_infeasible, save_history, verbose, seed, evaluator): accepted by
every algorithm besides its own hyperparameters."""


@functools.cache
def constructor_keywords(cls: type) -> frozenset[str]:
    """Every keyword ``cls(...)`` accepts: the named parameters of each ``__init__`` along
    its MRO (subclasses forward the rest through ``**kwargs``) and :data:`PYMOO_OPTIONS`."""
    names = set(PYMOO_OPTIONS)
    for klass in cls.__mro__:
        init = klass.__dict__.get("__init__")
        if init is not None and klass not in (Algorithm, object):
            names.update(p.name for p in inspect.signature(init).parameters.values()
                         if p.name != "self"
                         and p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY))
    return frozenset(names)


def refuse_unknown_keywords(cls: type, given: dict) -> None:
    """Refuse keywords that reached a base's ``**kwargs`` and that ``cls`` does not accept
    (pymoo's ``Algorithm`` would swallow them silently).

    Raises:
        ParameterError: Naming the unknown keywords and listing every keyword ``cls``
            accepts (:func:`constructor_keywords`).
    """
    if given and not PYMOO_OPTIONS.issuperset(given):
        keywords(cls.__name__, given, constructor_keywords(cls))


def find_limit(termination, attr: str) -> float:
    """Smallest ``attr`` (n_max_gen / n_max_evals) among any-of termination criteria."""
    limit = getattr(termination, attr, None)
    limit = np.inf if limit is None else float(limit)
    if isinstance(termination, (TerminateIfAny, DefaultTermination)):
        for sub in termination.criteria:
            limit = min(limit, find_limit(sub, attr))
    return limit


def check_termination(termination) -> None:
    """Refuse an ``n_gen`` or ``n_eval`` criterion below 1, anywhere in ``termination``
    (pymoo itself fails on them with ``ZeroDivisionError`` or ``AssertionError``).

    Raises:
        ParameterError: Naming the criterion and the value given.
    """
    for attr, name in (("n_max_gen", "n_gen"), ("n_max_evals", "n_eval")):
        value = getattr(termination, attr, None)
        if value is not None and not value >= 1:
            raise ParameterError(f"an {name!r} termination needs a limit >= 1 (the initial "
                                 f"population is generation 1); got {value!r}")
    for sub in getattr(termination, "criteria", ()):
        check_termination(sub)
    inner = getattr(termination, "termination", None)
    if inner is not None:
        check_termination(inner)


def tolerance_criteria(termination) -> list[str]:
    """The names of the tolerance criteria (pymoo's ``DeltaToleranceTermination``: ``ftol``,
    ``xtol``, ``cv``) anywhere in ``termination``."""
    if isinstance(termination, DeltaToleranceTermination):
        return [type(termination).__name__]
    inner = getattr(termination, "termination", None)
    found = [] if inner is None else tolerance_criteria(inner)
    for sub in getattr(termination, "criteria", ()):
        found += tolerance_criteria(sub)
    return found


def has_time_criterion(termination) -> bool:
    """Whether a ``time`` criterion is anywhere in ``termination`` (its plan then changes)."""
    if getattr(termination, "max_time", None) is not None:
        return True
    inner = getattr(termination, "termination", None)
    return any(has_time_criterion(c) for c in getattr(termination, "criteria", ())) or (
        inner is not None and has_time_criterion(inner))


def check_sizes(pop_size: object, min_pop_size: int, max_iter: object) -> tuple[int, int | None]:
    """``(pop_size, max_iter)`` validated: an integer >= ``min_pop_size``; a positive
    integer or None.

    Raises:
        ParameterError: For a value that is not an integer (bools and floats refused)
            or is out of range.
    """
    pop_size = integer("pop_size", pop_size, minimum=min_pop_size)
    if max_iter is None:
        return pop_size, None
    if not (is_integer(max_iter) and max_iter >= 1):
        raise ParameterError(f"max_iter must be a positive integer or None, got {max_iter!r}")
    return pop_size, int(max_iter)


def finite_bounds(problem, name: str) -> tuple[np.ndarray, np.ndarray]:
    """The problem's ``(xl, xu)`` as float arrays; both must be finite."""
    if getattr(problem, "vars", None) is not None:
        raise ParameterError(f"{name} works on real-valued vectors; the problem has mixed "
                             f"variables ({', '.join(sorted(map(str, problem.vars)))}); use "
                             f"pymoo's MixedVariableGA")
    xl, xu = problem.bounds()
    try:
        xl, xu = np.asarray(xl, float), np.asarray(xu, float)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} needs real-valued bounds xl, xu; got {xl!r}, {xu!r}") \
            from None
    if xl is None or xu is None or not (np.all(np.isfinite(xl)) and np.all(np.isfinite(xu))):
        raise ParameterError(f"{name} needs finite bounds xl, xu")
    return np.asarray(xl, float), np.asarray(xu, float)


def planned_iterations(termination, *, t: int, n_eval: int, elapsed: float,
                       per_iteration: float, plans: dict) -> float:
    """The schedule length T the termination's budget allows, seen from iteration ``t``.

    T counts update iterations after initialization (the papers' Max_t): the
    iterations ``t = 1 .. T`` fit the budget and ``t / T`` reaches 1 on the last one:

    - ``n_gen``: ``n_max_gen - 1`` (pymoo counts the initial population as
      generation 1);
    - ``n_eval``: ``t - 1`` plus the iterations the evaluations left allow at
      ``per_iteration`` each (the last one possibly cut short), planned once, when
      the criterion is first seen (its T is kept in ``plans``, keyed by the criterion
      object, so an algorithm whose rate varies within a run keeps one plan; a new
      criterion, e.g. a checkpoint resumed with a new termination, is planned from
      where the run stands);
    - ``time``: ``t / p`` with ``p`` the share of the time used, re-estimated every call
      (an estimate: the run stops when the time is up);
    - any-of criteria (tuples, pymoo's default and robust terminations): the smallest T;
      all-of: the largest; a ``RobustTermination``: its inner criterion's; other
      criteria (tolerances): none (inf).

    Every finite T is at least ``t``.

    Args:
        termination: A pymoo termination (the algorithm's current one).
        t: The iteration about to run (1 = the first after initialization).
        n_eval: Evaluations done so far.
        elapsed: Seconds since the run started.
        per_iteration: Expected evaluations per iteration.
        plans: The ``n_eval`` plans made so far (updated in place).

    Returns:
        T as an integer-valued float, or inf when no criterion bounds the run.
    """
    def plan(criterion) -> float:
        return planned_iterations(criterion, t=t, n_eval=n_eval, elapsed=elapsed,
                                  per_iteration=per_iteration, plans=plans)

    if isinstance(termination, TerminateIfAll):
        return max((plan(c) for c in termination.criteria), default=math.inf)
    if isinstance(termination, (TerminateIfAny, DefaultTermination)):
        return min((plan(c) for c in termination.criteria), default=math.inf)
    if hasattr(termination, "termination"):  # RobustTermination wraps one criterion
        return plan(termination.termination)
    T = math.inf
    if getattr(termination, "n_max_gen", None) is not None:
        T = float(termination.n_max_gen) - 1.0
    elif getattr(termination, "n_max_evals", None) is not None:
        if termination not in plans:
            left = float(termination.n_max_evals) - n_eval
            plans[termination] = (t - 1 + max(math.ceil(left / per_iteration), 1)
                                  if math.isfinite(left) else math.inf)
        T = plans[termination]
    elif getattr(termination, "max_time", None) is not None and elapsed > 0:
        T = math.ceil(t * float(termination.max_time) / elapsed)
    return max(T, float(t))


def check_points(name: str, X0, xl: np.ndarray, xu: np.ndarray) -> np.ndarray:
    """``X0`` as a float array of at least one finite row within ``[xl, xu]`` (any number:
    a sample larger than the population is evaluated in full and ranked,
    :mod:`moik.algorithms.initial_survival`).

    Raises:
        ShapeError: For a wrong shape or no row. NonFiniteError: For NaN/inf.
        ParameterError: For points outside the bounds.
    """
    X0 = np.asarray(X0, dtype=float)
    n_var = len(xl)
    if X0.ndim != 2 or X0.shape[1] != n_var or len(X0) < 1:
        raise ShapeError(f"{name} must have shape (k, {n_var}) with k >= 1, got {X0.shape}")
    if not np.all(np.isfinite(X0)):
        raise NonFiniteError(f"{name} holds NaN or infinite values")
    if np.any(clip_to_bounds(X0, xl, xu) != X0):
        raise ParameterError(f"{name} has points outside the problem bounds [xl, xu]")
    return X0


def initial_population(n: int, xl: np.ndarray, xu: np.ndarray, X0, *,
                       rng: np.random.Generator, name: str = "X0") -> Population:
    """Uniform initial points; the first rows replaced by ``X0`` if given (validated);
    ``X0`` alone when it has ``n`` rows or more."""
    if X0 is not None:
        X0 = check_points(name, X0, xl, xu)
        if len(X0) > n:
            return Population.new("X", X0.copy())
    X = uniform_population(n, xl, xu, rng=rng)
    if X0 is not None:
        X[: len(X0)] = X0
    return Population.new("X", X)


def initial_infill(problem, n: int, xl: np.ndarray, xu: np.ndarray, *, X0, sampling,
                   rng: np.random.Generator) -> Population:
    """The initial population from ``X0`` or pymoo's ``sampling=`` forms (as pymoo's
    algorithms take them), the rows not given drawn uniformly.

    ``sampling`` is a pymoo ``Sampling`` (asked for ``n`` points with the run's random
    state), an array (as ``X0``: any number of rows) or a ``Population`` (any number of
    individuals, copied; those already evaluated are not evaluated again, as pymoo's
    ``Evaluator`` skips them). More rows than ``n`` are all returned (the algorithm keeps
    ``n`` of them after their evaluation, :mod:`moik.algorithms.initial_survival`).

    Raises:
        ParameterError: If both ``X0`` and ``sampling`` are given, or for a sampling of
            another type; the errors of :func:`check_points` for its points.
    """
    if sampling is None:
        return initial_population(n, xl, xu, X0, rng=rng)
    if X0 is not None:
        raise ParameterError("give the initial points as X0 or as sampling, not both")
    if isinstance(sampling, Population):
        check_points("sampling", sampling.get("X"), xl, xu)
        given = [ind.copy() for ind in sampling]
        X = uniform_population(max(n - len(given), 0), xl, xu, rng=rng)
        return Population.merge(Population.create(*given), Population.new("X", X))
    if isinstance(sampling, Sampling):
        X = sampling.do(problem, n, random_state=rng).get("X")
        return Population.new("X", check_points("sampling", X, xl, xu))
    if isinstance(sampling, (np.ndarray, list, tuple)):
        return initial_population(n, xl, xu, sampling, rng=rng, name="sampling")
    raise ParameterError(f"sampling must be a pymoo Sampling, an array of points or a "
                         f"Population, got {type(sampling).__name__}")


class GivenPoints(Sampling):
    """A pymoo ``Sampling`` of given points (an array or a ``Population``, any number of
    rows), the rows not given drawn uniformly: pymoo's array and Population forms of
    ``sampling=`` for a pymoo algorithm that takes only a ``Sampling`` (MOPSO-CD)."""

    def __init__(self, points) -> None:
        super().__init__()
        self.points = points

    def do(self, problem, n_samples, *args, random_state=None, **kwargs) -> Population:
        """The points as a ``Population`` (evaluated individuals stay evaluated)."""
        xl, xu = (np.asarray(b, dtype=float) for b in problem.bounds())
        return initial_infill(problem, n_samples, xl, xu, X0=None, sampling=self.points,
                              rng=random_state)

    def _do(self, problem, n_samples, *args, random_state=None, **kwargs):
        xl, xu = (np.asarray(b, dtype=float) for b in problem.bounds())
        return initial_infill(problem, n_samples, xl, xu, X0=None, sampling=self.points,
                              rng=random_state).get("X")


def given_rows(X0, sampling, n: int) -> int:
    """How many rows of the initial population of size ``n`` the user gave (``X0`` or
    ``sampling=``: all of them for a pymoo ``Sampling``; possibly more than ``n``); an
    algorithm with its own initialisation (chaotic maps) draws only the others."""
    if X0 is not None:
        return len(np.atleast_2d(X0))
    if sampling is None:
        return 0
    if isinstance(sampling, Sampling):
        return n
    return len(sampling) if isinstance(sampling, Population) else len(np.atleast_2d(sampling))


def budget_left(max_evals: float, n_eval: int, n: int) -> int:
    """How many of ``n`` candidates the evaluation budget still allows."""
    left = max_evals - n_eval
    return n if left >= n else int(max(left, 0))
