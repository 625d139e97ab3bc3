"""Shared base of the benchmark problems: known optimum and argument checks.

Every benchmark is a vectorized single-objective pymoo ``Problem`` that states
its known optimum value ``f_opt`` (and location ``x_opt`` where one is known);
``pareto_front()`` returns ``f_opt`` and ``pareto_set()`` returns ``x_opt`` so
pymoo's indicators and tolerance terminations can use them.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike
from pymoo.core.problem import Problem

from moik._validate import integer


def check_n_var(n_var: object) -> int:
    """Return ``n_var`` as an int after checking it is a positive integer.

    Args:
        n_var: Requested number of decision variables.

    Returns:
        The number of variables.

    Raises:
        ParameterError: If ``n_var`` is not an integer >= 2.
    """
    return integer("n_var", n_var, minimum=2)


class Benchmark(Problem):
    """A single-objective box-bounded test problem with a known optimum.

    Attributes:
        f_opt: The known global minimum value.
        x_opt: One known global minimizer (1-D array), or ``None`` if unknown.
    """

    def __init__(
        self,
        *,
        n_var: int,
        xl: float | np.ndarray,
        xu: float | np.ndarray,
        f_opt: float,
        x_opt: ArrayLike | None,
        n_ieq_constr: int = 0,
    ) -> None:
        super().__init__(n_var=n_var, n_obj=1, n_ieq_constr=n_ieq_constr, xl=xl, xu=xu, vtype=float)
        self.f_opt = float(f_opt)
        self.x_opt = None if x_opt is None else np.asarray(x_opt, dtype=float)

    def _calc_pareto_front(self) -> float:
        return self.f_opt

    def _calc_pareto_set(self) -> np.ndarray | None:
        return self.x_opt
