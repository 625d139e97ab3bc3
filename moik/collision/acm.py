"""The allowed-collision matrix by sampling, as MoveIt's setup assistant computes it.

MoveIt Setup Assistant ("Self-Collisions" step, ``compute_default_collisions``) disables
the collision check of link pairs that are adjacent in the chain, in collision at the
default configuration, in collision in (nearly) every random configuration ("always"),
or in none of them ("never"), sampling 10,000 random configurations by default. This
module does the same on a :class:`~moik.collision.model.CollisionModel` with the
compiled distances: ``samples`` configurations uniform within the joint limits (10,000
by default, MoveIt's "sampling density" default), a pair is *always* in collision when
it penetrates in at least ``always`` (95 %, MoveIt's threshold) of them and *never* when
it penetrates in none. MoveIt also disables pairs in collision at the robot's default
pose; moik has no default pose (the middle of the limits need not be a valid one), so
that rule is not applied.

On bounding shapes (capsules fitted around meshes) the "always" rule is unsound: bounds
that overlap in every sample say nothing of the meshes inside them, which may touch only
sometimes; pass ``always=None`` to allow no pair for being always in collision.

"Never" pairs are a speed-up with a risk (a collision rarer than 1 in ``samples`` is
missed): pass ``never=False`` to keep them checked.
"""

from __future__ import annotations

import numpy as np

from moik._validate import flag, integer, interval
from moik.collision.model import CollisionChecker, CollisionModel
from moik.exceptions import ParameterError

DEFAULT_SAMPLES = 10_000


def body_pair_contacts(model: CollisionModel, Q: np.ndarray) -> dict[tuple[int, int], np.ndarray]:
    """For each checked body pair, whether it penetrates at each row of ``Q``."""
    checker = CollisionChecker(model=model, self_collision=True)
    D = checker.distances(Q)
    out: dict[tuple[int, int], np.ndarray] = {}
    for k, key in enumerate(checker.pair_bodies):
        hit = D[:, k] < 0.0
        out[key] = out[key] | hit if key in out else hit
    return out


def sample_allowed(model: CollisionModel, *, rng: np.random.Generator,
                   samples: int = DEFAULT_SAMPLES, always: float | None = 0.95,
                   never: bool = True) -> CollisionModel:
    """``model`` with the pairs that are in collision always or never allowed.

    Args:
        model: The model (its ``allowed`` pairs stay allowed).
        rng: The random configurations' generator.
        samples: Number of random configurations (MoveIt's default 10,000).
        always: Fraction of samples from which a pair counts as always in collision
            (``None``: no pair is allowed for that).
        never: Whether pairs never in collision are allowed too.
    """
    if not isinstance(rng, np.random.Generator):
        raise ParameterError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    samples = integer("samples", samples, minimum=1)
    limit = np.inf if always is None else interval("always", always, 0.0, 1.0, lo_open=True)
    never = flag("never", never)
    robot = model.robot
    Q = robot.random_q(samples, rng=rng)
    allowed = []
    for (i, j), hit in body_pair_contacts(model, Q).items():
        rate = hit.mean()
        if rate >= limit or (never and not hit.any()):
            allowed.append((model.links[i], model.links[j]))
    return model.with_allowed(allowed)
