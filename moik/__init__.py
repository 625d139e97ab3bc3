"""moik: multi-objective inverse kinematics of robot arms with metaheuristics, on pymoo."""

from moik.exceptions import MoikError

__version__ = "0.1.0"

__all__ = ["MoikError", "__version__"]
