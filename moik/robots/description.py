"""Where a robot loaded from a URDF came from: the file (or text) and its package folders.

:func:`moik.robots.urdf.load_urdf` attaches one to the :class:`~moik.robots.chain.Robot` it
returns (``robot.description``), so that the URDF's collision geometry can be read when a
solve first checks collisions (:func:`moik.collision.urdf.model_from_urdf`) without the
caller naming the file again.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any


@dataclass(frozen=True, eq=False)
class URDFDescription:
    """A URDF a robot was loaded from.

    Attributes:
        source: The file path (absolute) or the XML text.
        package_dirs: The ``package_dirs`` given to ``load_urdf`` (``None``: only
            ``ROS_PACKAGE_PATH`` and the URDF's own folder are searched).
        srdf: The MoveIt SRDF given to ``load_urdf`` (path, absolute, or XML text): its
            disabled pairs are not checked (:mod:`moik.collision.srdf`); ``None``: none.
    """

    source: Path | str
    package_dirs: Any = None
    srdf: Path | str | None = None
