"""The link pairs a MoveIt SRDF leaves unchecked, as body pairs of a URDF collision model.

A robot's package often ships the allowed-collision matrix its authors computed (MoveIt
Setup Assistant's ``.srdf``): ``<disable_collisions link1= link2= reason=/>`` per link pair,
``<disable_default_collisions link=/>`` for every pair with a link, and
``<enable_collisions link1= link2=/>`` to check a pair again. Given to
:func:`moik.collision.urdf.model_from_urdf` (``srdf=``, or ``load_urdf(..., srdf=)`` for a
solve's default model, ``--srdf`` on the command line), those pairs are not checked: the
caller's explicit choice, named in the model's ``source``. Needed where the URDF's own
geometry overlaps by construction (example-robot-data's ``panda_collision.urdf``: the
spheres of links 1 and 3 overlap in every configuration; its SRDF disables the pair), which
moik's sampling never allows by itself (:mod:`moik.collision.acm`).

moik checks self pairs per body (a chain link and the links fixed to it), an SRDF per
link: a body pair is left unchecked only when the SRDF disables every pair of links with
geometry on the two bodies. Links of the URDF that are not on the chain (another arm, a
head) are ignored. Entries naming links the URDF does not have (the whole robot's SRDF
beside a URDF of one arm) are skipped with a :class:`~moik.exceptions.GeometryWarning`
naming them, as MoveIt skips them; an SRDF none of whose entries names the URDF's links
is an error (another robot's SRDF).
"""

from __future__ import annotations

import warnings
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from moik._validate.reading import read_bytes, robot_xml
from moik._validate.reading import text as decoded_text
from moik.collision.model import CollisionModel
from moik.exceptions import GeometryError, GeometryWarning

MAX_SRDF_BYTES = 16 * 2**20


def _root(source: Any) -> tuple[ET.Element, str]:
    """The ``<robot>`` element of an SRDF path or XML text, and a label for messages."""
    if isinstance(source, str) and source.lstrip().startswith("<"):
        label, text = "<SRDF string>", source
    else:
        if not isinstance(source, (str, Path)) or not str(source).strip():
            raise GeometryError(f"srdf must be an SRDF file path or XML text, got {source!r:.80}")
        label = str(source)
        text = decoded_text(read_bytes(Path(source), "SRDF", GeometryError,
                                       limit=MAX_SRDF_BYTES), f"SRDF {label!r}", GeometryError)
    return robot_xml(text, label, "an SRDF", GeometryError), label


Rules = tuple[set[frozenset[str]], set[str], set[frozenset[str]]]


def srdf_rules(source: Any, urdf_links: set[str]) -> tuple[Rules, str]:
    """``((disabled, every, enabled), label)``: the link pairs an SRDF disables, the links
    all of whose pairs it disables (``disable_default_collisions``), the pairs it checks
    again (``enable_collisions``), and a label for messages.

    Raises:
        GeometryError: Unreadable, not XML, not ``<robot>``, an element without its link
            names, or entries none of which names only links of the URDF (``urdf_links``).
    """
    root, label = _root(source)
    disabled: set[frozenset[str]] = set()
    every: set[str] = set()
    enabled: set[frozenset[str]] = set()
    skipped: set[str] = set()
    entries = 0
    for el in root:
        if el.tag == "disable_default_collisions":
            names = [el.get("link")]
        elif el.tag in ("disable_collisions", "enable_collisions"):
            names = [el.get("link1"), el.get("link2")]
        else:
            continue
        if not all(isinstance(n, str) and n for n in names):
            raise GeometryError(f"SRDF {label!r}: <{el.tag}> needs "
                                f"{'link=' if len(names) == 1 else 'link1= and link2='}")
        entries += 1
        unknown = {str(n) for n in names if n not in urdf_links}
        if unknown:
            skipped |= unknown
            continue
        if el.tag == "disable_default_collisions":
            every.add(str(names[0]))
        elif el.tag == "disable_collisions":
            disabled.add(frozenset(str(n) for n in names))
        else:
            enabled.add(frozenset(str(n) for n in names))
    if skipped:
        if not (disabled or every or enabled):
            raise GeometryError(f"SRDF {label!r}: none of its {entries} entries names only "
                                f"links of the URDF (it names {sorted(skipped)[:5]}...): is it "
                                "this robot's SRDF?")
        warnings.warn(f"SRDF {label!r}: entries naming links the URDF does not have are "
                      f"skipped: {', '.join(sorted(skipped)[:8])}"
                      f"{f' and {len(skipped) - 8} more' if len(skipped) > 8 else ''}",
                      GeometryWarning, stacklevel=4)
    return (disabled, every, enabled), label


def body_pairs(model: CollisionModel, source: Any, urdf_links: set[str]
               ) -> tuple[list[tuple[str, str]], str]:
    """The body pairs of ``model`` (checked now) whose every pair of links with geometry the
    SRDF ``source`` disables (module docstring), and the SRDF's label."""
    (disabled, every, enabled), label = srdf_rules(source, urdf_links)

    def off(a: str, b: str) -> bool:
        pair = frozenset((a, b))
        return pair not in enabled and (pair in disabled or a in every or b in every)

    names = model.links
    out = []
    for i, j in model.checked_body_pairs():
        on_i, on_j = set(model.origins[names[i]]), set(model.origins[names[j]])
        if all(off(a, b) for a in on_i for b in on_j):
            out.append((names[i], names[j]))
    return out, label
