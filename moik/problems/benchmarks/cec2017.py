"""CEC2017 single-objective test functions (I-BES paper, Section 5.2).

Source: I-BES paper (the team's copy ``ibes-manipulators-2024``, Section
5.2, Table 12: F3, F8, F9, F14, F15, F18, F19, F27, F30 at D = 30 on
[-100, 100]^D), and Awad, Ali, Liang, Qu & Suganthan, "Problem Definitions and
Evaluation Criteria for the CEC 2017 Special Session ..." (2016).

The functions and the official shift vectors, rotation matrices and shuffle
permutations come from the optional dependency ``opfunu`` (``pip install
moik[cec]``), whose wheel ships the official ``data_2017`` text files; nothing
is downloaded at run time. opfunu is imported lazily, so moik works without it.

Numbering: this module uses the official numbers (F_i, bias 100 i). opfunu 1.0.4
drops the removed F2 and numbers the rest one lower (its ``F22017`` is the
official F3, Zakharov, with bias 200 and the data of F2). Here official F_i is
opfunu's class ``F{i-1}2017`` built with the official data files of F_i
(``shift_data_i``, ``M_i_D``, ``shuffle_data_i_D``) and bias 100 i, so
``F_i(o_i) = 100 i`` holds with the official pairing.

Known deviations of opfunu 1.0.4 from the official C code (cec17_func.cpp),
kept as is, not patched here:

* hybrid functions (F11-F20) pass the shuffled ``M (x - o)`` to their
  components without each component's search-range scaling (e.g. 5.12/100 for
  Rastrigin, 5/100 for HGBat, 1000/100 for Schwefel);
* composition functions (F21-F30) evaluate every component at ``x - o_1``
  instead of ``x - o_k`` (only the weights use ``o_k``); F27's expanded
  Schaffer component adds 1 to its argument;
* F9 (Levy) scales ``x - o`` by 5.12/100 before the rotation, where
  ``cec17_func.cpp``'s ``levy_func`` calls ``sr_func`` with 1.0 (5.12/100 is
  the CEC2022 code's scaling): a 20x narrower landscape, much easier from
  [-100, 100] (every algorithm of ``ibes-cec2017`` ends near 900-950 here,
  the I-BES paper reports 5500-21500).

Values at ``o_1`` (the global optimum) are unaffected; the landscapes elsewhere
differ from the official code, so results are comparable between algorithms
run here but not digit-for-digit with published CEC2017 tables.

Cost: opfunu evaluates one solution at a time, so ``_evaluate`` loops over the
rows; measured on the 2-core reference machine at D = 30 about 3e-5 s per row
for F14 and 2e-4 s per row for F30 (a 30 x 500 run of F30: about 3 s).
"""

from __future__ import annotations

import importlib
import warnings

import numpy as np

from moik.exceptions import MoikError, ParameterError, UnknownNameError
from moik.problems.benchmarks._base import Benchmark

IBES_FUNCTIONS = (3, 8, 9, 14, 15, 18, 19, 27, 30)
AVAILABLE_FUNCTIONS = (1, *range(3, 31))
HYBRID = range(11, 21)
SHUFFLED_COMPOSITION = (29, 30)
DIMENSIONS = (10, 30, 50, 100)


def load_opfunu_cec2017():
    """Import ``opfunu.cec_based.cec2017`` or explain how to install it.

    Returns:
        The opfunu CEC2017 module.

    Raises:
        MoikError: If opfunu is not installed.
    """
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            return importlib.import_module("opfunu.cec_based.cec2017")
    except ImportError as err:
        raise MoikError(
            "the CEC2017 functions need the optional dependency opfunu; "
            "install it with: pip install moik[cec]"
        ) from err


def make_opfunu_function(number: int, n_var: int):
    """Build opfunu's object for official CEC2017 function ``number``.

    Args:
        number: Official CEC2017 function number (1 or 3-30).
        n_var: Dimension, one of 10, 30, 50, 100.

    Returns:
        An opfunu benchmark object with ``evaluate(x)`` for one 1-D solution.

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
    module = load_opfunu_cec2017()
    cls = getattr(module, f"F{max(number - 1, 1)}2017")
    kwargs = {
        "ndim": n_var,
        "f_shift": f"shift_data_{number}",
        "f_matrix": f"M_{number}_D",
        "f_bias": 100.0 * number,
    }
    if number in HYBRID or number in SHUFFLED_COMPOSITION:
        kwargs["f_shuffle"] = f"shuffle_data_{number}_D"
    return cls(**kwargs)


class CEC2017(Benchmark):
    """Official CEC2017 function F_i as a pymoo Problem on [-100, 100]^D.

    Args:
        number: Official function number (1 or 3-30; I-BES uses
            3, 8, 9, 14, 15, 18, 19, 27, 30).
        n_var: Dimension D (10, 30, 50 or 100; I-BES uses 30).

    Attributes:
        f_opt: ``100 * number``, attained at ``x_opt`` (the shift vector o_i).
    """

    def __init__(self, number: int, n_var: int = 30) -> None:
        self.number = int(number)
        self.function = make_opfunu_function(self.number, n_var)
        super().__init__(
            n_var=n_var,
            xl=-100.0,
            xu=100.0,
            f_opt=100.0 * self.number,
            x_opt=np.asarray(self.function.x_global, dtype=float)[:n_var],
        )

    def _evaluate(self, x, out, *args, **kwargs):
        evaluate = self.function.evaluate
        out["F"] = np.fromiter((evaluate(row) for row in x), dtype=float, count=len(x))

    def name(self) -> str:
        return f"CEC2017-F{self.number}"
