"""The background families of a cold first collision-aware solve: its distance test
compiled by a child process (:mod:`moik.warmup.background`) while the solve compiles the
rest. Apart from :mod:`moik.warmup.beside` (the other families) so that the child imports
only the collision and chain modules, not the solver's, problems' and algorithms'.

``"collision-leaves"``: a cold first collision-aware solve compiles the start loop of a
plain solve and the collision test it calls on each exact end between compiled runs
(:mod:`moik.solver.tested_starts`; the answers' distances too, row by row), whose
distance kernels (the pairs' bounds, GJK on the hulls, the box and primitive distances:
about half of that solve's compiling) nothing else calls. :func:`beside_collision` has a
child build the solve's own checker (pickled: the same collision set, of the same numba
type) and call that test once, while the parent compiles the FK and LM kernels; the
``moik`` command starts it before a ``solve`` with ``--scene`` or ``--self-collision``.

``"collision-stand-in"``: the same distance test on a stand-in collision set of the solve's
numba type, so that the child starts before the solve's checker exists (building it reads
the arm's meshes and compiles its off-chain frames: seconds in which the child would
wait). :func:`beside_collision_early` guesses the type from the command line (a
:class:`~moik.collision.compiled.CompoundSet` for self pairs alone, a
:class:`~moik.collision.compiled.CollisionSet` with a scene: true of the catalog's arms but
iiwa14 with a scene); :func:`beside_collision` given that child keeps it where the
checker's set is of the guessed type, and otherwise stops it and starts
``"collision-leaves"`` on the checker.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from moik.collision.compiled import CollisionSet, CompoundSet, collision_set
from moik.collision.distance import BOX, CAPSULE, HULL
from moik.collision.kernels import distance_below, distance_scratch
from moik.collision.model import CollisionChecker
from moik.problems.targets import as_target
from moik.robots import Robot
from moik.solver.context import ik_context
from moik.warmup import background

COLLISION_PROBES = (distance_below,)
"""The collision test of a start's end, which both families' children write."""


def beside_collision(checker: CollisionChecker, early: StandIn | None = None
                     ) -> background.Background | None:
    """Start the ``"collision-leaves"`` child for a first collision-aware solve checked by
    ``checker`` (a :class:`~moik.collision.CollisionChecker`; module docstring), or return
    None where it cannot help (:mod:`moik.warmup.background`). ``early``: the
    ``"collision-stand-in"`` child started before the checker existed
    (:func:`beside_collision_early`), kept where it compiles the checker's set type."""
    if not isinstance(checker, CollisionChecker) or checker.n_pairs == 0:
        if early is not None:
            early.child.stop()
        return None
    if early is not None:
        if isinstance(checker.compiled, CompoundSet) == early.compound:
            return early.child
        early.child.stop()  # a set of the other type: its kernels would be of no use
    return background.start("collision-leaves", {"checker": checker}, COLLISION_PROBES)


@dataclass(frozen=True)
class StandIn:
    """A running ``"collision-stand-in"`` child and the set type it compiles."""

    child: background.Background
    compound: bool  # CompoundSet (else CollisionSet)


def beside_collision_early(robot: Robot, *, scene: bool) -> StandIn | None:
    """Start the ``"collision-stand-in"`` child for a first collision-aware solve of
    ``robot`` (``scene``: with obstacles) before its checker is built (module docstring), or
    return None where it cannot help."""
    if not isinstance(robot, Robot):
        return None
    compound = not scene
    child = background.start("collision-stand-in", {"robot": robot, "compound": compound},
                             COLLISION_PROBES)
    return None if child is None else StandIn(child, compound)


def stand_in_set(robot: Robot, compound: bool) -> CollisionSet:
    """A collision set of ``robot``'s chain of the numba type a checker's has: two shapes
    on the first two joints' frames (a capsule and a hull: a
    :class:`~moik.collision.compiled.CompoundSet`; a box and a capsule: a
    :class:`~moik.collision.compiled.CollisionSet`) and their pair."""
    tetra = 0.05 * np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    kinds = [CAPSULE, HULL] if compound else [BOX, CAPSULE]
    return collision_set(chain=robot.chain_model, body=np.array([1, min(2, robot.dof)]),
                         local=np.tile(np.eye(4), (2, 1, 1)), kinds=np.array(kinds),
                         sizes=np.array([[0.05, 0.1, 0.05], [0.05, 0.1, 0.0]]),
                         pairs=np.array([[0, 1]]), hull_points=tetra,
                         hull_ranges=np.array([[0, 4]]))


def collision_stand_in(robot: Robot, compound: bool) -> None:
    """The ``"collision-stand-in"`` child: the constructors of a solve's contexts, without
    and with the collision set (:class:`~moik.solver.session.SolveSession` builds them
    early, while the child has time to spare; any target: the types do not depend on it),
    then the distance test on :func:`stand_in_set`."""
    cs = stand_in_set(robot, compound)
    for collision in (None, cs):
        ik_context(robot, as_target(np.zeros(3)), stop=(0.0, 0.0), tol=(0.0, 0.0),
                   distinct=0.1, collision=collision, clearance=0.0)
    q = np.ascontiguousarray((robot.lower + robot.upper) / 2.0, dtype=np.float64)
    distance_below(cs, q, distance_scratch(cs), 0.0)


def collision_leaves(checker: CollisionChecker) -> None:
    """The ``"collision-leaves"`` child: the distance test of an end (every distance kernel
    it calls) on the solve's own collision set, at the middle of the joint ranges."""
    cs = checker.compiled
    q = np.ascontiguousarray((checker.robot.lower + checker.robot.upper) / 2.0, dtype=np.float64)
    distance_below(cs, q, distance_scratch(cs), 0.0)
