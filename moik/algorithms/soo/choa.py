"""Chimp optimization algorithm (ChOA) and the MChOA improvements as switches.

ChOA: Khishe & Mosavi, "Chimp optimization algorithm", Expert Systems with
Applications 149, 113338 (2020), DOI 10.1016/j.eswa.2020.113338. MChOA: Hou,
Luo, Wu, Sun & Zhang, "Solution of Inverse Kinematics for Industry Robot Based
on Multi-Strategy Improved Chimpanzee Optimization Algorithm" (the MChOA
paper). Equation numbers are the MChOA paper's:

- Eqs. 7-11: the four best chimps so far lead (Attacker, Barrier, Chaser,
  Driver); for leader k, ``x_k = x_leader_k - a_k |c_k x_leader_k - m_k x|`` with
  ``a = 2 f rand_1 - f`` (Eq. 8), ``rand_1 = Cg_k rand`` (the group coefficient
  of leader k, as in the authors' code), ``c = 2 rand_2`` (Eq. 9), ``m`` a
  chaotic map value (Eq. 10); the new position is the mean of x_1..x_4
  (Eq. 11); f decreases linearly from 2.5 to 0.
- CChOA, Eqs. 13-14: the initial population comes from the Iteration map
  ``x_{n+1} = sin(b pi / x_n)`` (b = 0.7), one sequence of length N per
  dimension from a random start, mapped to ``lb + (x + 1)/2 (ub - lb)`` (the
  ``(x + 1)/2`` rescaling of [-1, 1] is the one of the authors' chaos.m).
- OIChOA, Eq. 18: ``a = 2 Cg rand f - Cg f`` (symmetric about 0).
- OChOA (Section 3.2.3): the random number of ``a`` is shared by the four
  leaders (one draw per chimp and coordinate instead of four).
- WChOA, Eqs. 19-21: ``x = sum(w_k x_k) / sum(w_k)`` with
  ``w_k = S / (P_k + P_2 + P_3 + P_4) = S / (S - P_1 + P_k)``, ``S = sum P``,
  ``P_k = |F_k - f_opt|`` the leaders' distances to the known optimum value
  (Eq. 21 is f_opt = 0). Taken as printed: the best leader gets weight 1 and
  worse leaders less; all four equal when S = 0.
- MChOA: all four switches.

Group coefficients (``Cg_k``, the ChOA1 set of the authors' public code, with
s = t/T): ``1.95 - 2 s^(1/3)`` for the Attacker and Barrier, ``2.5 - 2 s^3`` for
the Chaser and Driver. Defaults (MChOA paper Section 4.1): N = 50, f 2.5 -> 0,
Gauss/mouse map for m (the map the authors' code calls). Evaluations: N per
iteration. Coordinates are clipped to the bounds (authors' code). Constrained
problems: the leaders are the four feasibility-first best (Deb's rules, see
base.py), and WChOA uses the feasibility-first ranking values.

Two bugs of the widely copied public ChOA code are not reproduced:
- Its third and fourth terms both use the Chaser as the leader
  (``X3 = Chaser - A3 |C3 Chaser - m x|`` and ``X4 = Chaser - A4 |C4 Driver -
  m x|``), so the Driver never leads; here each term uses its own leader.
- Its ``m = chaos(3, 1, 1)`` returns the map's start value 0.7 on every call,
  a constant; here each leader term has its own chaotic state per chimp and
  coordinate, advanced one map step per iteration.
Other deviations: the leaders are the four best positions evaluated so far (the
code's cascade of ``if`` tests does not shift leaders down and can skip the
Driver); the code's second group coefficient on ``rand_2`` is not used, Eq. 9
has none; Eq. 12's switch to a raw chaotic value as a position (mu >= 0.5) is
not applied, as in the authors' code. In floating point the Gauss map reaches
0 (the continued fraction of a double ends); states at 0 are redrawn.
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.array_state import given_rows
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, ranking_fitness
from moik.algorithms.soo.eo import update_pool
from moik.exceptions import ParameterError

SWITCHES = ("chaotic_init", "oi_coefficient", "shared_random", "weighted")
TINY = 1e-12


def gauss_map(x: np.ndarray) -> np.ndarray:
    """Gauss/mouse map ``frac(1/x)`` (0 stays 0); values in [0, 1)."""
    safe = np.where(x == 0.0, 1.0, x)
    return np.where(x == 0.0, 0.0, np.mod(1.0 / safe, 1.0))


def iterative_map(x: np.ndarray, b: float = 0.7) -> np.ndarray:
    """Eq. 13: the Iteration map ``sin(b pi / x)``; values in [-1, 1]."""
    safe = np.where(x == 0.0, 1.0, x)
    return np.where(x == 0.0, 0.0, np.sin(b * np.pi / safe))


def logistic_map(x: np.ndarray) -> np.ndarray:
    """Logistic map ``4 x (1 - x)``; values in [0, 1]."""
    return 4.0 * x * (1.0 - x)


CHAOTIC_MAPS = {  # map, value in [0, 1] from the state
    "gauss": (gauss_map, lambda x: x),
    "iterative": (iterative_map, lambda x: (x + 1.0) / 2.0),
    "logistic": (logistic_map, lambda x: x),
}


def chaotic_step(state: np.ndarray, name: str, *, rng: np.random.Generator) -> np.ndarray:
    """Advance the chaotic states one step; states stuck near 0 are redrawn in (0, 1)."""
    new = CHAOTIC_MAPS[name][0](state)
    stuck = np.abs(new) < TINY
    return np.where(stuck, rng.uniform(TINY, 1.0, state.shape), new) if stuck.any() else new


def chaotic_population(n: int, xl: np.ndarray, xu: np.ndarray, *, b: float = 0.7,
                       rng: np.random.Generator) -> np.ndarray:
    """Eqs. 13-14: n Iteration-map iterates per dimension from a random start, in the box."""
    x = rng.uniform(TINY, 1.0, xl.size)
    rows = []
    for _ in range(n):
        x = iterative_map(x, b)
        x = np.where(np.abs(x) < TINY, rng.uniform(TINY, 1.0, xl.size), x)
        rows.append(x)
    return xl + (np.asarray(rows) + 1.0) / 2.0 * (xu - xl)


def group_coefficients(t: int, T: int) -> np.ndarray:
    """Cg of the Attacker, Barrier, Chaser and Driver (authors' code, ChOA1 set)."""
    s = min(t / T, 1.0)
    return np.array([1.95 - 2.0 * s ** (1 / 3), 1.95 - 2.0 * s ** (1 / 3),
                     2.5 - 2.0 * s**3, 2.5 - 2.0 * s**3])


def adaptive_weights(P: np.ndarray) -> np.ndarray:
    """Eqs. 20-21: ``w_k = S / (S - P_1 + P_k)`` for leaders sorted best first."""
    P = np.abs(np.asarray(P, dtype=float))
    S = P.sum()
    if not np.isfinite(S) or S <= 0.0:
        return np.ones(len(P))
    return S / (S - P[0] + P)


def chimp_update(X, leaders, m, f: float, Cg, *, opposition: bool, shared: bool,
                 weights: np.ndarray | None, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 8-11 (Eq. 18 with ``opposition``, Eq. 19 with ``weights``).

    Args:
        X: Chimp positions (n, d).
        leaders: Attacker, Barrier, Chaser, Driver positions (4, d).
        m: Chaotic values (4, n, d), one per leader term.
        f: The decreasing factor f. Cg: group coefficients (4,).
        opposition: Use Eq. 18 for a. shared: one rand_1 for all four leaders.
        weights: Leader weights (4,) of Eq. 19, or None for the mean of Eq. 11.
        rng: Random generator.
    """
    n, d = X.shape
    r1 = rng.random((1 if shared else 4, n, d))
    r2 = rng.random((4, n, d))
    cg = Cg[:, None, None]
    a = cg * f * (2.0 * r1 - 1.0) if opposition else 2.0 * f * cg * r1 - f  # Eq. 18 / Eq. 8
    c = 2.0 * r2  # Eq. 9
    L = leaders[:, None, :]
    Xk = L - a * np.abs(c * L - m * X)  # Eq. 11, one term per leader
    if weights is None:
        return Xk.sum(axis=0) / 4.0  # Eq. 11
    w = np.asarray(weights, dtype=float)[:, None, None]
    return (w * Xk).sum(axis=0) / w.sum()  # Eq. 19


class ChOA(ArrayAlgorithm):
    """Chimp optimization with MChOA's four improvements as switches.

    Every switch is off by default (plain ChOA); the classmethods ``cchoa``,
    ``oichoa``, ``ochoa``, ``wchoa`` and ``mchoa`` build the paper's variants.
    Extra public arrays: ``leaders_X``/``leaders_F`` (the four best so far).

    Args:
        pop_size: Number of chimps N (paper: 50).
        f_max: Start value of f, decreasing linearly to 0, in (0, 5] (paper: 2.5).
        chaotic_map: Map for m: ``"gauss"`` (authors' code), ``"iterative"``,
            ``"logistic"``.
        b: Iteration-map parameter of Eq. 13, in (0, 1] (0.7).
        chaotic_init: CChOA, Eqs. 13-14. oi_coefficient: OIChOA, Eq. 18.
        shared_random: OChOA. weighted: WChOA, Eqs. 19-21.
        f_opt: Known optimal objective value of Eq. 20 (Eq. 21: 0).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 4

    def __init__(self, *, pop_size: int = 50, f_max: float = 2.5, chaotic_map: str = "gauss",
                 b: float = 0.7, chaotic_init: bool = False,
                 oi_coefficient: bool = False, shared_random: bool = False,
                 weighted: bool = False, f_opt: float = 0.0,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.f_max = interval("f_max", f_max, 0.0, 5.0, lo_open=True)
        self.b = interval("b", b, 0.0, 1.0, lo_open=True)
        self.f_opt = interval("f_opt", f_opt, -np.inf, np.inf, lo_open=True, hi_open=True)
        if chaotic_map not in CHAOTIC_MAPS:
            raise ParameterError(f"chaotic_map must be one of {', '.join(CHAOTIC_MAPS)}, "
                                 f"got {chaotic_map!r}")
        self.chaotic_map = chaotic_map
        given = dict(zip(SWITCHES, (chaotic_init, oi_coefficient, shared_random, weighted),
                         strict=True))
        for name, value in given.items():
            if not isinstance(value, (bool, np.bool_)):
                raise ParameterError(f"{name} must be True or False, got {value!r}")
            setattr(self, name, bool(value))

    @classmethod
    def cchoa(cls, **kwargs) -> ChOA:
        """CChOA: the chaotic (Iteration map) initialization, Eqs. 13-14."""
        return cls(**{"chaotic_init": True, **kwargs})

    @classmethod
    def oichoa(cls, **kwargs) -> ChOA:
        """OIChOA: the opposition-inspired coefficient a, Eq. 18."""
        return cls(**{"oi_coefficient": True, **kwargs})

    @classmethod
    def ochoa(cls, **kwargs) -> ChOA:
        """OChOA: one shared random number of a for the four leaders."""
        return cls(**{"shared_random": True, **kwargs})

    @classmethod
    def wchoa(cls, **kwargs) -> ChOA:
        """WChOA: the adaptive leader weights, Eqs. 19-21."""
        return cls(**{"weighted": True, **kwargs})

    @classmethod
    def mchoa(cls, **kwargs) -> ChOA:
        """MChOA (Hou et al.): all four improvements; a keyword turns one off."""
        return cls(**{**dict.fromkeys(SWITCHES, True), **kwargs})

    def _initialize_infill(self):
        pop = super()._initialize_infill()
        k = given_rows(self.X0, self.sampling, self.pop_size)
        if self.chaotic_init and k < self.pop_size:
            X = pop.get("X")
            X[k:] = chaotic_population(self.pop_size - k, self.xl, self.xu, b=self.b,
                                       rng=self.random_state)
            pop.set("X", X)
        return pop

    def _initialize_state(self) -> None:
        n, d = self.X.shape
        empty = np.empty((0, d))
        cv0 = None if self.CV is None else np.empty(0)
        self.leaders_X, self.leaders_F, self.leaders_CV = update_pool(
            empty, np.empty(0), cv0, self.X, self.F, self.CV)
        self.chaos = self.random_state.uniform(TINY, 1.0, (4, n, d))

    def _weights(self) -> np.ndarray | None:
        if not self.weighted:
            return None
        return adaptive_weights(ranking_fitness(self.leaders_F, self.leaders_CV) - self.f_opt)

    def _generation(self) -> Step:
        rng = self.random_state
        leaders = self.leaders_X
        if len(leaders) < 4:  # fewer than 4 distinct evaluations so far: repeat the best
            leaders = np.concatenate([leaders, np.repeat(leaders[:1], 4 - len(leaders), 0)])
        self.chaos = chaotic_step(self.chaos, self.chaotic_map, rng=rng)
        m = CHAOTIC_MAPS[self.chaotic_map][1](self.chaos)
        f = self.f_max * (1.0 - min(self.t / self.max_iter, 1.0))
        X = chimp_update(self.X, leaders, m, f, group_coefficients(self.t, self.max_iter),
                         opposition=self.oi_coefficient, shared=self.shared_random,
                         weights=self._weights(), rng=rng)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
        self.leaders_X, self.leaders_F, self.leaders_CV = update_pool(
            self.leaders_X, self.leaders_F, self.leaders_CV, X, F, CV)
