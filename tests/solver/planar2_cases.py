"""Hand-solved cases on ``planar2``, shared by the solver's tests (not a test module).

``planar2`` (I-BES Table 2) is ``T(q) = Rz(q1) Tx(a1) Rz(q2) Tx(a2)`` with ``a1 = 0.35``,
``a2 = 0.30`` (reach 0.65, limits ``[-pi, pi]``): the elbow (frame 1) is at
``a1 u(q1)``, the tool at ``a1 u(q1) + a2 u(q1 + q2)`` with heading ``q1 + q2``
(``u(a) = (cos a, sin a, 0)``). A position target ``(x, y, 0)`` with
``a1 - a2 < r = |(x, y)| < a1 + a2`` has exactly two solutions modulo 2 pi (law of
cosines): ``q2 = +-acos((r^2 - a1^2 - a2^2) / (2 a1 a2))``,
``q1 = atan2(y, x) - atan2(a2 sin q2, a1 + a2 cos q2)``.

:func:`elbow_guard`: a sphere of radius 0.05 on the elbow and an obstacle sphere of radius
0.05 centred where one branch puts its elbow: that branch is 0.1 deep in contact
(signed distance -0.1), the other ``|e_1 - e_0| - 0.1`` away.
"""

import numpy as np

from moik.collision import CollisionChecker, CollisionModel, Scene, Sphere
from moik.robots import get_robot
from moik.solver.collision import CollisionGuard

ARM = get_robot("planar2")
A1, A2, REACH = 0.35, 0.30, 0.65


def rz(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def tool(q) -> tuple[np.ndarray, np.ndarray]:
    """Tool position and rotation at ``q`` (module doc)."""
    q1, q2 = q
    return (np.array([A1 * np.cos(q1) + A2 * np.cos(q1 + q2),
                      A1 * np.sin(q1) + A2 * np.sin(q1 + q2), 0.0]), rz(q1 + q2))


def elbow(q) -> np.ndarray:
    return np.array([A1 * np.cos(q[0]), A1 * np.sin(q[0]), 0.0])


def branches(x: float, y: float) -> np.ndarray:
    """The two solutions ``(2, 2)`` of the position target ``(x, y, 0)`` (module doc)."""
    c2 = (x * x + y * y - A1 * A1 - A2 * A2) / (2 * A1 * A2)
    q2 = np.array([np.arccos(c2), -np.arccos(c2)])
    q1 = np.arctan2(y, x) - np.arctan2(A2 * np.sin(q2), A1 + A2 * np.cos(q2))
    return np.column_stack([q1, q2])


def wrapped(a, b) -> np.ndarray:
    """``|a - b|`` with angles taken modulo 2 pi."""
    return np.abs((np.asarray(a) - b + np.pi) % (2 * np.pi) - np.pi)


def elbow_guard(blocked: np.ndarray, clearance: float = 0.0) -> CollisionGuard:
    """The guard of the module doc, its obstacle on the elbow of ``blocked``."""
    pose = np.eye(4)
    pose[:3, 3] = elbow(blocked)
    model = CollisionModel(robot=ARM, shapes={"link1": Sphere(radius=0.05)})
    scene = Scene({"ball": Sphere(radius=0.05, pose=pose)})
    return CollisionGuard(CollisionChecker(model=model, scene=scene), clearance)


def elbow_distance(q, blocked) -> float:
    """The guard's distance at ``q``, by hand."""
    return float(np.linalg.norm(elbow(q) - elbow(blocked)) - 0.1)
