"""Robot models: DH chains, the paper catalog and URDF loading."""

from moik.robots.catalog import as_robot, available_robots, get_robot
from moik.robots.chain import Robot, fk_reference

__all__ = ["Robot", "as_robot", "available_robots", "fk_reference", "get_robot"]
