"""Scalable classical test functions F1-F13 (MChOA paper, Table 2).

Source: the MChOA IK paper (the team's copy ``mchoa-industrial-robot``,
Table 2, dimensions 30/500/1000), which takes the functions from the ChOA
MATLAB code (Khishe & Mosavi 2020), itself the set of Yao, Liu & Lin (1999,
IEEE TEC 3(2)) as coded by Mirjalili for GWO (2014). Every function here is
vectorized over the population (no loop over individuals).

Notes against the extracted table text:

* F2 reads ``sum(x_i + prod x_j)``; the bars were lost in extraction. The
  standard (Yao; ChOA code) Schwefel 2.22 ``sum|x_i| + prod|x_i|`` is used. For
  n >= ~300 the product can overflow to ``inf`` far from the optimum, exactly as
  in the reference MATLAB code.
* F4 is ``max_i |x_i|`` (Schwefel 2.21).
* F6 reads ``sum x_i + 0.5 ^2``: the ChOA/GWO code uses ``sum(|x_i + 0.5|^2)``
  (default); Yao's step function ``sum(floor(x_i + 0.5)^2)`` is ``step=True``.
* F7 reads ``i^2 x_i^4``; Yao and the ChOA code use ``i * x_i^4`` (used here).
  The noise ``U[0, 1)`` comes from a generator owned by the instance (``seed``);
  ``noise=False`` gives the noise-free quartic.
* F8 has its optimum ``-418.9829 n`` at ``x_i = 420.9687`` (the table rounds to
  ``-419 n``); pymoo's ``Schwefel`` adds ``418.9829 n`` so it is not reused.
* F9, F10, F11 reuse pymoo's ``Rastrigin``, ``Ackley`` and ``Griewank`` (same
  formulas) with the table's bounds; pymoo's ``Sphere`` (shifted to 0.5) and
  ``Rosenbrock`` (bounds +-2.048, loop over variables) are not reused.
"""

from __future__ import annotations

import numpy as np
from pymoo.problems.single import Ackley, Griewank, Rastrigin

from moik.problems.benchmarks._base import Benchmark, check_n_var

SCHWEFEL_X_OPT = 420.968746
SCHWEFEL_F_PER_VAR = -418.9828872724338


def ufun(x: np.ndarray, a: float, k: float, m: float) -> np.ndarray:
    """Penalty term of F12/F13 (MChOA Eq. 22), elementwise.

    Args:
        x: Array of any shape.
        a: Half-width of the penalty-free interval.
        k: Penalty factor.
        m: Penalty exponent.

    Returns:
        ``k (x - a)^m`` where ``x > a``, ``k (-x - a)^m`` where ``x < -a``, else 0.
    """
    return k * (x - a) ** m * (x > a) + k * (-x - a) ** m * (x < -a)


class _Scalable(Benchmark):
    """Common constructor of the scalable functions."""

    bound: float = 100.0
    opt_value: float = 0.0

    def __init__(self, n_var: int = 30) -> None:
        n_var = check_n_var(n_var)
        super().__init__(
            n_var=n_var,
            xl=-self.bound,
            xu=self.bound,
            f_opt=self.opt_value,
            x_opt=np.full(n_var, self._x_opt_value()),
        )

    def _x_opt_value(self) -> float:
        return 0.0


class F1(_Scalable):
    """Sphere: ``sum x_i^2`` on [-100, 100]^n; 0 at 0."""

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = np.sum(x**2, axis=1)


class F2(_Scalable):
    """Schwefel 2.22: ``sum|x_i| + prod|x_i|`` on [-10, 10]^n; 0 at 0."""

    bound = 10.0

    def _evaluate(self, x, out, *args, **kwargs):
        ax = np.abs(x)
        with np.errstate(over="ignore"):
            out["F"] = np.sum(ax, axis=1) + np.prod(ax, axis=1)


class F3(_Scalable):
    """Schwefel 1.2: ``sum_i (sum_{j<=i} x_j)^2`` on [-100, 100]^n; 0 at 0."""

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = np.sum(np.cumsum(x, axis=1) ** 2, axis=1)


class F4(_Scalable):
    """Schwefel 2.21: ``max_i |x_i|`` on [-100, 100]^n; 0 at 0."""

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = np.max(np.abs(x), axis=1)


class F5(_Scalable):
    """Rosenbrock: ``sum 100 (x_{i+1} - x_i^2)^2 + (x_i - 1)^2`` on [-30, 30]^n; 0 at 1."""

    bound = 30.0

    def _x_opt_value(self) -> float:
        return 1.0

    def _evaluate(self, x, out, *args, **kwargs):
        head, tail = x[:, :-1], x[:, 1:]
        out["F"] = np.sum(100.0 * (tail - head**2) ** 2 + (head - 1.0) ** 2, axis=1)


class F6(_Scalable):
    """Shifted sphere ``sum |x_i + 0.5|^2`` (or Yao's step) on [-100, 100]^n; 0 at -0.5."""

    def __init__(self, n_var: int = 30, *, step: bool = False) -> None:
        self.step = bool(step)
        super().__init__(n_var)

    def _x_opt_value(self) -> float:
        return -0.5

    def _evaluate(self, x, out, *args, **kwargs):
        y = np.floor(x + 0.5) if self.step else x + 0.5
        out["F"] = np.sum(y**2, axis=1)


class F7(_Scalable):
    """Noisy quartic ``sum i x_i^4 + U[0, 1)`` on [-1.28, 1.28]^n; 0 at 0 (noise-free)."""

    bound = 1.28

    def __init__(self, n_var: int = 30, *, noise: bool = True, seed: int = 0) -> None:
        self.noise = bool(noise)
        self.seed = seed
        self.rng = np.random.default_rng(seed)
        super().__init__(n_var)

    def _evaluate(self, x, out, *args, **kwargs):
        f = np.sum(np.arange(1, x.shape[1] + 1) * x**4, axis=1)
        if self.noise:
            f = f + self.rng.random(x.shape[0])
        out["F"] = f


class F8(_Scalable):
    """Schwefel 2.26: ``sum -x_i sin(sqrt|x_i|)`` on [-500, 500]^n; -418.9829 n at 420.9687."""

    bound = 500.0

    def __init__(self, n_var: int = 30) -> None:
        self.opt_value = SCHWEFEL_F_PER_VAR * check_n_var(n_var)
        super().__init__(n_var)

    def _x_opt_value(self) -> float:
        return SCHWEFEL_X_OPT

    def _evaluate(self, x, out, *args, **kwargs):
        out["F"] = np.sum(-x * np.sin(np.sqrt(np.abs(x))), axis=1)


def _reuse(cls: type, bound: float, n_var: int):
    """Instantiate a pymoo problem with the table's bounds and known optimum."""
    n_var = check_n_var(n_var)
    problem = cls(n_var=n_var)
    problem.xl = np.full(n_var, -bound)
    problem.xu = np.full(n_var, bound)
    problem.f_opt = 0.0
    problem.x_opt = np.zeros(n_var)
    return problem


def F9(n_var: int = 30) -> Rastrigin:
    """Rastrigin on [-5.12, 5.12]^n (pymoo's ``Rastrigin``); 0 at 0."""
    return _reuse(Rastrigin, 5.12, n_var)


def F10(n_var: int = 30) -> Ackley:
    """Ackley on [-32, 32]^n (pymoo's ``Ackley``, a=20, b=0.2, c=2 pi); 0 at 0."""
    return _reuse(Ackley, 32.0, n_var)


def F11(n_var: int = 30) -> Griewank:
    """Griewank on [-600, 600]^n (pymoo's ``Griewank``); 0 at 0."""
    return _reuse(Griewank, 600.0, n_var)


class F12(_Scalable):
    """Generalized penalized function 1 on [-50, 50]^n; 0 at -1."""

    bound = 50.0

    def _x_opt_value(self) -> float:
        return -1.0

    def _evaluate(self, x, out, *args, **kwargs):
        n = x.shape[1]
        y = 1.0 + (x + 1.0) / 4.0
        body = 10.0 * np.sin(np.pi * y[:, 0]) ** 2 + (y[:, -1] - 1.0) ** 2
        body = body + np.sum(
            (y[:, :-1] - 1.0) ** 2 * (1.0 + 10.0 * np.sin(np.pi * y[:, 1:]) ** 2), axis=1
        )
        out["F"] = np.pi / n * body + np.sum(ufun(x, 10.0, 100.0, 4.0), axis=1)


class F13(_Scalable):
    """Generalized penalized function 2 on [-50, 50]^n; 0 at 1."""

    bound = 50.0

    def _x_opt_value(self) -> float:
        return 1.0

    def _evaluate(self, x, out, *args, **kwargs):
        last = x[:, -1]
        body = np.sin(3.0 * np.pi * x[:, 0]) ** 2
        body = body + np.sum(
            (x[:, :-1] - 1.0) ** 2 * (1.0 + np.sin(3.0 * np.pi * x[:, 1:]) ** 2), axis=1
        )
        body = body + (last - 1.0) ** 2 * (1.0 + np.sin(2.0 * np.pi * last) ** 2)
        out["F"] = 0.1 * body + np.sum(ufun(x, 5.0, 100.0, 4.0), axis=1)
