"""Errors raised by moik.

Every error is a :class:`MoikError`; the subclasses say which kind of input was
wrong. Messages name the bad value, what was expected and, for unknown names,
the valid names. Suspicious input that is still accepted (angles that look
like degrees) gets a :class:`MoikWarning` instead.
"""

from __future__ import annotations

from collections.abc import Iterable


class MoikError(Exception):
    """Base class of every error raised by moik for bad input or state."""


class ShapeError(MoikError, ValueError):
    """An array has the wrong shape."""


class NonFiniteError(MoikError, ValueError):
    """An array holds NaN or infinite values where finite ones are required."""


class LimitsError(MoikError, ValueError):
    """Joint or variable limits are inconsistent (lower > upper, wrong length)."""


class UnknownNameError(MoikError, LookupError):
    """A robot, algorithm, metric or convention name is not known."""

    def __init__(self, kind: str, name: object, valid: Iterable[str]):
        self.kind = kind
        self.name = name
        self.valid = sorted(valid)
        super().__init__(
            f"unknown {kind} {name!r}; expected one of: {', '.join(self.valid)}"
        )

    def __str__(self) -> str:  # LookupError would otherwise quote the message
        return self.args[0]


class ParameterError(MoikError, ValueError):
    """A hyperparameter or option is outside its valid range."""


class TargetError(MoikError, ValueError):
    """A target pose or position is malformed or in the wrong unit range."""


class URDFError(MoikError, ValueError):
    """A URDF file is malformed or does not describe the requested chain."""


class GeometryError(MoikError, ValueError):
    """Collision geometry or a scene is malformed (a negative radius, a model for another robot)."""


class ConfigError(MoikError, ValueError):
    """An experiment configuration is malformed (names the file, the key and the problem)."""


class ResultsError(MoikError, OSError):
    """A results folder cannot be used as asked (exists without --resume, other config...)."""


class MoikWarning(UserWarning):
    """Base class of the warnings moik issues about suspicious but accepted input."""


class CacheWarning(MoikWarning):
    """moik's compiled-kernel cache was damaged (discarded and recompiled) or cannot be written."""


class GeometryWarning(MoikWarning):
    """A collision model can be used but will reject every answer: two of its links are in
    collision in every sampled configuration (named, with what to do about it)."""


class DegreesWarning(MoikWarning):
    """Angles given to moik (joint limits, DH twists or offsets) look like degrees.

    moik takes angles in radians; a value beyond a full turn (two turns for joint
    limits, which multi-turn joints exceed legitimately) is most likely in degrees.
    """


class NonFiniteValuesWarning(MoikWarning, RuntimeWarning):
    """A problem returned NaN or infinite objective or constraint values at some points.

    moik's algorithms treat such a point as infeasible and worst (``F = CV = inf``) and
    never report it; the warning is issued once per run.
    """


class ToleranceTerminationWarning(MoikWarning):
    """A moik algorithm runs under a tolerance termination (pymoo's ``ftol``/``xtol``/``cv``
    criteria, as in ``DefaultSingleObjectiveTermination``).

    moik's algorithms plan their run as a budget (``n_gen``, ``n_eval``, ``time``): many
    follow a schedule in t/T and explore first, with a best so far that stays flat for
    tens of generations, which a tolerance window reads as convergence and stops.
    """
