"""Where a URDF's movable joints outside the IK chain are placed, for its collision geometry.

A robot loaded from a URDF (:func:`moik.robots.urdf.load_urdf`) moves only its chain's
joints; the URDF may hang more links behind other movable joints (*off-chain joints*:
a gripper's fingers, e.g. panda's ``panda_finger_joint1``/``2``, or a second branch).
Their links belong to the body of the chain link they hang from
(:func:`moik.robots.urdf_geometry.link_placements`), placed at one stated value of each
off-chain joint:

* the value the caller gives (``joint_values={"panda_finger_joint1": 0.04}``), a finite
  number within the joint's limits (a ``continuous`` joint's are ``[-pi, pi]``, one turn,
  as :func:`~moik.robots.urdf.load_urdf` gives a chain's);
* else the joint's zero clipped into its limits (panda's fingers: 0, closed);
* a ``<mimic joint= multiplier= offset=>`` joint follows its leader:
  ``value = multiplier * leader + offset`` (multiplier 1 and offset 0 by default), and
  must land within its own limits; it cannot be given a value of its own.

A mimic joint that follows a joint of the chain, or a ``floating``/``planar`` joint with
links behind it, cannot be placed on a body at one value: an error, never a silent skip.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from moik._validate import named_numbers
from moik.exceptions import ParameterError, URDFError
from moik.robots.urdf import _limits

MOVABLE = ("revolute", "continuous", "prismatic")


@dataclass(frozen=True)
class JointPlacement:
    """The value an off-chain joint is placed at, and why.

    Attributes:
        value: The joint's value (rad or m).
        how: ``"given"``, ``"default"`` (its zero clipped into its limits) or
            ``"mimic"`` (follows ``leader``).
        leader: The joint it mimics (``how == "mimic"``), else ``""``.
    """

    value: float
    how: str
    leader: str = ""

    def describe(self, name: str) -> str:
        """``"NAME = VALUE (why)"``, for a model's ``source``."""
        why = {"given": "given", "default": "default: its zero clipped into its limits",
               "mimic": f"mimics {self.leader}"}[self.how]
        return f"{name} = {self.value:g} ({why})"


def _mimic(el: ET.Element, name: str) -> tuple[str, float, float] | None:
    m = el.find("mimic")
    if m is None:
        return None
    leader = m.get("joint")
    if not leader:
        raise URDFError(f"joint {name!r}: <mimic> needs a joint=")
    try:
        mult, off = float(m.get("multiplier", "1")), float(m.get("offset", "0"))
    except ValueError:
        raise URDFError(f"joint {name!r}: <mimic> multiplier and offset must be numbers, "
                        f"got {dict(m.attrib)}") from None
    if not (np.isfinite(mult) and np.isfinite(off)):
        raise URDFError(f"joint {name!r}: <mimic> multiplier and offset must be finite, "
                        f"got {dict(m.attrib)}")
    return leader, mult, off


def place_joints(joints: dict[str, ET.Element], chain: tuple[str, ...], given: Any
                 ) -> dict[str, JointPlacement]:
    """The placement of every movable joint of a parsed URDF that is not in ``chain``.

    Args:
        joints: ``{name: <joint> element}`` of the URDF.
        chain: The IK chain's joint names (``robot.joint_names``).
        given: ``None`` or ``{joint name: value}`` for off-chain joints that do not mimic.

    Raises:
        ParameterError: ``given`` names a joint that is not an off-chain joint, a chain or
            a mimic joint, or a value that is not finite or outside the joint's limits; a
            mimic joint pushed outside its limits by its leader.
        URDFError: A mimic joint whose leader is missing, fixed, a chain joint, or a cycle.
    """
    off = {n: el for n, el in joints.items() if el.get("type") in MOVABLE and n not in chain}
    limits = {n: _limits(el, n, str(el.get("type"))) for n, el in off.items()}
    mimics = {n: m for n, el in off.items() if (m := _mimic(el, n)) is not None}
    free = {n: limits[n] for n in off if n not in mimics}
    if given is None:
        given = {}
    if isinstance(given, Mapping):
        for name in given:
            if name in chain:
                raise ParameterError(f"joint_values: {name!r} is a joint of the IK chain (its "
                                     "value is the solution's); give only off-chain joints: "
                                     f"{sorted(free)}")
            if name in mimics:
                raise ParameterError(f"joint_values: {name!r} mimics {mimics[name][0]!r} and "
                                     f"follows it; give {mimics[name][0]!r} instead")
    values = named_numbers("joint_values", given, free)
    out = {n: JointPlacement(values[n], "given") if n in values
           else JointPlacement(float(np.clip(0.0, *free[n])), "default") for n in free}

    def resolve(name: str, seen: tuple[str, ...]) -> float:
        if name in out:
            return out[name].value
        leader, mult, offset = mimics[name]
        if leader in seen:
            raise URDFError(f"the <mimic> joints {list(seen)} form a cycle")
        if leader in chain:
            raise URDFError(f"joint {name!r} mimics {leader!r}, a joint of the IK chain: the "
                            "links behind it move with the solution and cannot be placed on one "
                            "body; choose a chain without it or drop the <mimic>")
        if leader not in off:
            raise URDFError(f"joint {name!r} mimics {leader!r}, which is not a movable joint "
                            "of the URDF")
        value = mult * resolve(leader, (*seen, name)) + offset
        lo, hi = limits[name]
        if not lo <= value <= hi:
            raise ParameterError(f"joint {name!r} mimics {leader!r} ({name} = {mult:g} * "
                                 f"{leader} + {offset:g}) = {value:g}, outside its limits "
                                 f"[{lo:g}, {hi:g}]; give {leader!r} a value in joint_values")
        out[name] = JointPlacement(value, "mimic", leader)
        return value

    for name in mimics:
        resolve(name, (name,))
    return out
