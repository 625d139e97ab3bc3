"""CEC2017 single-objective test functions (I-BES paper, Section 5.2).

Source: I-BES paper (Section 5.2, Table 12: F3, F8, F9, F14, F15, F18, F19,
F27, F30 at D = 30 on [-100, 100]^D), and Awad, Ali, Liang, Qu & Suganthan,
"Problem Definitions and Evaluation Criteria for the CEC 2017 Special Session
..." (2016), whose reference implementation is the C file ``cec17_func.cpp``
(N. Awad, last update 26 May 2017) with its ``input_data`` folder.

The functions come from the optional dependency ``minionpy`` (``pip install
-e '.[cec]'`` in the repository, pinned to 1.9.1, MIT licence), a C++ port of ``cec17_func.cpp``
whose wheel ships the official shift vectors, rotation matrices and shuffle
permutations (``minionpy/cec_input_data/input_data_2017``, the official
``input_data`` files byte for byte); nothing is downloaded at run time.
minionpy is imported when a CEC2017 problem is built, so moik works without it.
Numbering is the official one (F2 was removed from the suite; bias 100 i).

Checked against the official code: ``tests/problems/benchmarks/test_cec2017_oracle.py``
transcribes F3, F5, F8, F9, F14 and F27 from ``cec17_func.cpp`` in numpy, and
minionpy agrees with it to ~1e-14 relative at D = 10, 30, 50, quirks of the C
code included (F8's rounding step is overwritten, so F8 is the plain rotated
Rastrigin; F14's Schaffer F7 component reads the shuffled vector from its
start). ``F_i(o_i) = 100 i`` holds at the shift vector o_i for every function
and D in {10, 30, 50} except F9, as in the official code: its Levy component
maps z to ``w = 1 + (z - 1) / 4``, so the minimum 900 lies at z = 1, i.e. at
``x = o_9 + M_9^{-1} 1``, which is ``x_opt`` here (F9(o_9) = 903.26 at D = 30).

Before the switch this module used opfunu 1.0.4 (with the same official
data), which departs from ``cec17_func.cpp``: at D = 30 on 200 random points
of the box, opfunu and minionpy agree to 1e-8 only on F1, F4 and F10 (F12 to
6e-8, F14 and F18 within 0.5 %). The causes found:

* F3 (Zakharov): opfunu weights the linear sum by a constant 0.5 where the
  official code weights it by ``0.5 (i + 1)``;
* F5 (Rastrigin): opfunu drops the official 5.12/100 scaling of x - o;
* F8: opfunu rounds as the CEC2017 report's non-continuous Rastrigin does;
  the official code's rounding has no effect (see above);
* F9 (Levy): opfunu scales x - o by 5.12/100 (the CEC2022 scaling) and moves
  the optimum to o_9;
* hybrid functions (F11-F20): opfunu passes the shuffled ``M (x - o)`` to
  the components without each component's search-range scaling (5.12/100 for
  Rastrigin, 5/100 for HGBat, 1000/100 for Schwefel, ...);
* composition functions (F21-F30): opfunu evaluates every component at
  ``x - o_1`` instead of ``x - o_k``, and its F27 Schaffer component adds 1.

So the ``ibes-cec2017`` results measured with opfunu are not comparable with
published CEC2017 tables; with minionpy the functions are the official ones.

Cost: minionpy evaluates the whole population in one call. Measured at D = 30
with 30 rows per call on the shared 2-core reference machine: 7e-6 (F3) to
1.1e-4 (F30) s per row, 6-34x faster than opfunu's one Python call per row on
the nine I-BES functions.
"""

from __future__ import annotations

from importlib import import_module, resources
from importlib.resources.abc import Traversable
from types import ModuleType

import numpy as np

from moik._validate import finite_array, integer
from moik.exceptions import MoikError, ParameterError, UnknownNameError
from moik.problems.benchmarks._base import Benchmark

IBES_FUNCTIONS = (3, 8, 9, 14, 15, 18, 19, 27, 30)
AVAILABLE_FUNCTIONS = (1, *range(3, 31))
DIMENSIONS = (10, 30, 50, 100)
LEVY = 9
"""The function whose optimum is not at its shift vector (see the module docstring)."""


def load_minionpy() -> ModuleType:
    """Import ``minionpy`` or explain how to install it.

    Returns:
        The minionpy module.

    Raises:
        MoikError: If minionpy is not installed.
    """
    try:
        return import_module("minionpy")
    except ImportError as err:
        raise MoikError(
            "the CEC2017 functions need the optional dependency minionpy; "
            "install it with: pip install -e '.[cec]' in the moik repository"
        ) from err


def official_data_dir() -> Traversable:
    """The folder of the official CEC2017 data files that minionpy ships.

    Returns:
        ``minionpy/cec_input_data/input_data_2017`` (``M_i_DD.txt``,
        ``shift_data_i.txt``, ``shuffle_data_i_DD.txt``).

    Raises:
        MoikError: If minionpy is not installed.
    """
    load_minionpy()
    return resources.files("minionpy") / "cec_input_data" / "input_data_2017"


def shift_vector(number: int, n_var: int) -> np.ndarray:
    """The official shift vector o_i (o_1 of the components for F21-F30).

    Args:
        number: Official CEC2017 function number.
        n_var: Dimension D.

    Returns:
        The first ``n_var`` values of the first line of ``shift_data_<number>.txt``,
        as ``cec17_func.cpp`` reads them.
    """
    with (official_data_dir() / f"shift_data_{number}.txt").open() as fh:
        return np.array(fh.readline().split()[:n_var], dtype=float)


def optimum_location(number: int, n_var: int) -> np.ndarray:
    """Where official function ``number`` attains ``100 * number``.

    Args:
        number: Official CEC2017 function number.
        n_var: Dimension D.

    Returns:
        o_i, except for F9: ``o_9 + M_9^{-1} 1`` (Levy's minimum is at z = 1).
    """
    o = shift_vector(number, n_var)
    if number != LEVY:
        return o
    with (official_data_dir() / f"M_{LEVY}_D{n_var}.txt").open() as fh:
        rotation = np.loadtxt(fh)
    return o + np.linalg.solve(rotation, np.ones(n_var))


def make_minion_function(number: int, n_var: int):
    """Build minionpy's evaluator of official CEC2017 function ``number``.

    Args:
        number: Official CEC2017 function number (1 or 3-30).
        n_var: Dimension, one of 10, 30, 50, 100.

    Returns:
        A callable mapping an ``(n, n_var)`` array to a list of ``n`` values.

    Raises:
        UnknownNameError: If ``number`` is not an available CEC2017 function.
        ParameterError: If ``n_var`` is not a dimension with official data.
    """
    if number not in AVAILABLE_FUNCTIONS:
        raise UnknownNameError("CEC2017 function", number, [str(i) for i in AVAILABLE_FUNCTIONS])
    if n_var not in DIMENSIONS:
        raise ParameterError(
            f"CEC2017 n_var must be one of {DIMENSIONS} (official data), got {n_var!r}"
        )
    return load_minionpy().CEC2017Functions(number, n_var)


class CEC2017(Benchmark):
    """Official CEC2017 function F_i as a vectorised pymoo Problem on [-100, 100]^D.

    Args:
        number: Official function number (1 or 3-30; I-BES uses
            3, 8, 9, 14, 15, 18, 19, 27, 30).
        n_var: Dimension D (10, 30, 50 or 100; I-BES uses 30).

    Attributes:
        f_opt: ``100 * number``, attained at ``x_opt`` (the shift vector o_i,
            or ``o_9 + M_9^{-1} 1`` for F9).

    Raises:
        UnknownNameError: If ``number`` is not 1 or 3-30.
        ParameterError: If ``number`` is not an integer or ``n_var`` has no official data.
        MoikError: If minionpy is not installed.
    """

    def __init__(self, number: int, n_var: int = 30) -> None:
        self.number = integer("CEC2017 function number", number)
        n_var = integer("n_var", n_var)
        self.function = make_minion_function(self.number, n_var)
        super().__init__(
            n_var=n_var,
            xl=-100.0,
            xu=100.0,
            f_opt=100.0 * self.number,
            x_opt=optimum_location(self.number, n_var),
        )

    def __getstate__(self) -> dict:
        # minionpy's evaluator does not pickle: rebuild it on unpickling (process pools, deepcopy)
        state = self.__dict__.copy()
        del state["function"]
        return state

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self.function = make_minion_function(self.number, self.n_var)

    def _evaluate(self, x, out, *args, **kwargs):
        # minionpy reads n_var values per row whatever the row length: check the shape first
        x = finite_array("x", x, shape=(None, self.n_var))
        out["F"] = np.asarray(self.function(x), dtype=float)

    def name(self) -> str:
        return f"CEC2017-F{self.number}"
