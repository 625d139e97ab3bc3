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

A URDF model's matrix (:func:`cached_allowed`, for :mod:`moik.collision.urdf`) allows the
"never" pairs only, judged on the compounds' parts (hulls of mesh pieces, prisms of
cylinders: the geometry the solves measure) and cached on disk. A pair in collision in
every sample stays checked, so every answer is rejected for it; it is named in a
:class:`~moik.exceptions.GeometryWarning` and in the model's ``source`` (measured once
on the ABB IRB 140 of rtb-data, whose flange turns 6-9 mm from its forearm's fork, with
a decomposition that measured no concavity on compact links: the convex pieces of the
two overlapped in every configuration, while the meshes touch in one in ten).

"Never" pairs are a speed-up with a risk (a collision rarer than 1 in ``samples`` is
missed): pass ``never=False`` to keep them checked.
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from moik._validate import flag, integer, interval
from moik.collision.kernels import pair_signs
from moik.collision.mesh_fit import digest, load_cached, store_cached
from moik.collision.model import CollisionChecker, CollisionModel
from moik.collision.shapes import Compound
from moik.exceptions import GeometryWarning, ParameterError

DEFAULT_SAMPLES = 10_000
ACM_SEED = 0  # the random configurations of a URDF model's matrix
Pairs = list[tuple[str, str]]


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


def sample_pairs(model: CollisionModel, samples: int) -> tuple[Pairs, Pairs]:
    """``(never, always)``: the body pairs in collision in none of ``samples`` random
    configurations (seed :data:`ACM_SEED`), and those with a shape pair in collision in
    all of them, judged on the compounds' parts (the geometry the solves measure)."""
    checker = CollisionChecker(model=model, self_collision=True)
    if checker.n_pairs == 0:
        return [], []
    Q = model.robot.random_q(samples, rng=np.random.default_rng(ACM_SEED))
    touching = np.zeros(checker.n_pairs, dtype=np.bool_)
    free = np.zeros(checker.n_pairs, dtype=np.bool_)
    pair_signs(checker.compiled, np.ascontiguousarray(Q), touching, free)
    hit: dict[tuple[int, int], bool] = {}
    stuck: dict[tuple[int, int], bool] = {}
    for k, pair in enumerate(checker.pair_bodies):
        hit[pair] = hit.get(pair, False) or bool(touching[k])
        stuck[pair] = stuck.get(pair, False) or not free[k]
    names = model.links
    return ([(names[i], names[j]) for (i, j), h in hit.items() if not h],
            [(names[i], names[j]) for (i, j), s in stuck.items() if s])


def _pair_list(value: Any, links: tuple[str, ...]) -> bool:
    return isinstance(value, list) and all(
        isinstance(p, list) and len(p) == 2 and all(n in links for n in p) for p in value)


def cached_allowed(model: CollisionModel, samples: int, use_cache: bool,
                   placement: dict[str, float]) -> CollisionModel:
    """``model`` with :func:`sample_pairs`'s "never" pairs allowed (read from the disk cache
    when there, keyed by the chain, the off-chain joints' values, the shapes, their parts
    and the settings); its "always" pairs named in a
    :class:`~moik.exceptions.GeometryWarning` and in the model's ``source``."""
    robot = model.robot
    chain = robot.kinematic_chain
    parts: list[Any] = [{"samples": samples, "seed": ACM_SEED, "links": list(model.links),
                         "rule": "never and always, on the parts"}, placement,
                        chain.origins, chain.joint_types.astype(float), robot.lower, robot.upper]
    for body, shape in model.items:
        parts += [body, type(shape).__name__, shape.pose, np.array(shape.sizes),
                  *([p.points for p in shape.parts] if isinstance(shape, Compound) else [])]
    if model.allowed:  # pairs allowed before (an SRDF's) are not sampled
        parts.append(sorted(sorted(p) for p in model.allowed))
    key = digest(parts)
    cached = load_cached("acm", key) if use_cache else None
    if (isinstance(cached, dict) and _pair_list(cached.get("never"), model.links)
            and _pair_list(cached.get("always"), model.links)):
        never, always = cached["never"], cached["always"]
    else:
        never, always = sample_pairs(model, samples)
        if use_cache:
            store_cached("acm", key, {"never": sorted(sorted(p) for p in never),
                                      "always": sorted(sorted(p) for p in always)})
    out = model.with_allowed(never)
    if not always:
        return out
    named = ", ".join(f"{a} - {b}" for a, b in sorted(sorted(p) for p in always))
    warnings.warn(
        f"{robot.name}: links {named} are in collision in every one of {samples} random "
        "configurations as the model measures them (the convex pieces that hold their "
        "collision geometry), so every answer will be rejected; the meshes themselves may "
        "be apart. If they never touch, give the robot's MoveIt SRDF that disables the pair "
        "(load_urdf(..., srdf=), --srdf) or pass collision=model.with_allowed([(a, b)])",
        GeometryWarning, stacklevel=3)
    return CollisionModel(robot=robot, shapes=out.shapes, links=out.links, allowed=out.allowed,
                          source=f"{out.source}; in collision in every sampled configuration "
                                 f"(every answer rejected): {named}",
                          aliases=out.aliases, origins=out.origins)
