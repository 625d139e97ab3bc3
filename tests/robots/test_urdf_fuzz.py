"""Fuzz test of the URDF loader (moik/robots/urdf.py, issue 27 item 3): the URDFs moik
ships, mutated (elements and attributes deleted, numbers made NaN, infinite, huge,
tiny or negative, parent and child swapped, joints duplicated, joint types changed).

Every case must end in a :class:`~moik.exceptions.MoikError` or in a sane robot
(finite reach, finite chain constants, finite FK at the limits and at random joint
values), never in another exception, a numpy overflow warning or nonsense accepted.
"""

import copy
import time
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import moik.robots
from moik.exceptions import MoikError, MoikWarning
from moik.robots.urdf import load_urdf

URDF_DIR = Path(moik.robots.__file__).with_name("data")
SHIPPED = {"lbr_iiwa_14_r820.urdf": "tool0", "panda.urdf": "panda_hand_tcp",
           "ur5_robot.urdf": "tool0", "puma560_robot.urdf": None}
N_CASES = 600
NUMERIC = ("xyz", "rpy", "lower", "upper")
BAD_NUMBERS = ("nan", "inf", "-inf", "1e300", "-1e300", "1e200", "1e160", "1e308", "-1.7e308",
               "-5", "-1e-320", "1e-300", "0", "abc", "", "1e400")
TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar", "spherical")


def _mutate(root: ET.Element, rng: np.random.Generator) -> str:
    """One random mutation of ``root`` in place; returns what it did."""
    everything = [(parent, el) for parent in root.iter() for el in parent]
    joints = root.findall("joint")
    kind = rng.integers(7)
    if kind == 0:  # delete an element (a joint's origin, axis, limit, parent, child; a link...)
        inner = [(p, el) for p, el in everything if p.tag == "joint" or el.tag in ("joint", "link")]
        parent, el = inner[rng.integers(len(inner))]
        parent.remove(el)
        return f"deleted <{el.tag}> of <{parent.tag} {parent.get('name')}>"
    if kind == 1:  # delete an attribute
        attributed = [el for _, el in everything if el.attrib]
        el = attributed[rng.integers(len(attributed))]
        key = sorted(el.attrib)[rng.integers(len(el.attrib))]
        del el.attrib[key]
        return f"deleted {key}= of <{el.tag}>"
    if kind in (2, 3):  # a bad number in one component of a numeric attribute of a joint
        numeric = [(el, key) for j in joints for el in j.iter()
                   for key in NUMERIC if key in el.attrib]
        el, key = numeric[rng.integers(len(numeric))]
        parts = el.get(key, "").split() or ["0"]
        parts[rng.integers(len(parts))] = BAD_NUMBERS[rng.integers(len(BAD_NUMBERS))]
        if rng.random() < 0.1:
            parts = parts[:-1]  # a component missing
        el.set(key, " ".join(parts))
        return f"<{el.tag}> {key}={el.get(key)!r}"
    joint = joints[rng.integers(len(joints))]
    if kind == 4:  # swap parent and child
        parent, child = joint.find("parent"), joint.find("child")
        if parent is None or child is None:
            return "nothing (a joint without parent or child)"
        a, b = parent.get("link"), child.get("link")
        parent.set("link", b or "")
        child.set("link", a or "")
        return f"swapped parent and child of joint {joint.get('name')}"
    if kind == 5:  # duplicate a joint, under its own name or another
        dup = copy.deepcopy(joint)
        if rng.random() < 0.5:
            dup.set("name", f"{joint.get('name')}_dup")
        root.append(dup)
        return f"duplicated joint {joint.get('name')} as {dup.get('name')}"
    joint.set("type", TYPES[rng.integers(len(TYPES))])
    return f"joint {joint.get('name')} made {joint.get('type')}"


def _check_sane(robot: moik.robots.Robot, rng: np.random.Generator) -> None:
    assert np.isfinite(robot.reach) and robot.reach > 0
    chain = robot.kinematic_chain
    assert all(np.all(np.isfinite(np.asarray(a, dtype=float)))
               for a in (chain.origins, robot.lower, robot.upper))
    Q = np.vstack([robot.lower, robot.upper, (robot.lower + robot.upper) / 2,
                   robot.random_q(5, rng=rng)])
    T = robot.fk(Q)
    assert np.all(np.isfinite(T))
    assert np.all(np.linalg.norm(T[:, :3, 3], axis=1) <= robot.reach * (1 + 1e-9) + 1e-12)


def test_mutated_shipped_urdfs_end_in_an_error_or_a_sane_robot():
    rng = np.random.default_rng(20261201)
    texts = {name: (URDF_DIR / name).read_text() for name in SHIPPED}
    outcomes = {"error": 0, "robot": 0}
    start = time.perf_counter()
    for case in range(N_CASES):
        name = list(SHIPPED)[rng.integers(len(SHIPPED))]
        root = ET.fromstring(texts[name])
        done = [_mutate(root, rng) for _ in range(1 + rng.integers(3))]
        tip = SHIPPED[name] if rng.random() < 0.8 else None
        text = ET.tostring(root, encoding="unicode")
        where = f"case {case}: {name}, tip {tip}: {'; '.join(done)}"
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", MoikWarning)  # degrees-looking limits are legal
            warnings.simplefilter("error", RuntimeWarning)  # an overflow nobody checked
            try:
                robot = load_urdf(text, tip_link=tip)
            except MoikError:
                outcomes["error"] += 1
                continue
            except Exception as exc:  # noqa: BLE001 - the failure this test looks for
                pytest.fail(f"{where}: raw {type(exc).__name__}: {exc}")
            try:
                _check_sane(robot, rng)
            except (AssertionError, RuntimeWarning) as exc:
                pytest.fail(f"{where}: accepted a robot that is not sane: {exc!r}")
            outcomes["robot"] += 1
    elapsed = time.perf_counter() - start
    print(f"{N_CASES} URDF fuzz cases in {elapsed:.2f} s: {outcomes}")
    # both outcomes really happen (a loader that refused everything would pass otherwise)
    assert outcomes["robot"] >= N_CASES // 10 and outcomes["error"] >= N_CASES // 10, outcomes
