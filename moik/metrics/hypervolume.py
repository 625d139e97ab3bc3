"""Hypervolume of Pareto fronts, and the reference-point policy of the EOSMA paper.

The hypervolume (Zitzler & Thiele 1999, https://doi.org/10.1109/4235.797969) of
a front F (minimized) with reference point r is the Lebesgue measure of the
region dominated by F and bounded by r. It is computed by pymoo's
``pymoo.indicators.hv.HV``, which delegates to moocore; moik only validates the
input and fixes the policy:

- No normalization: objectives are used as they are, as in the EOSMA paper
  (Yin et al. 2022, Sci. Rep. 12, 9421,
  https://doi.org/10.1038/s41598-022-13516-3, Table 8); its HV values are
  areas in the raw (position error, orientation error) plane.
- Points beyond the reference point (``F_k >= r_k`` in some objective) add
  nothing: moocore only counts points that strictly dominate ``r``. The
  authors' HV.m (Shihong-Yin/MOEOSMA, MOEOSMA_for_CMOP) removes such points
  first, which gives the same value. Dominated points inside the box add
  nothing either, so a front need not be filtered first.
- An empty front has hypervolume 0.

Reference point (EOSMA paper, text before Table 8): "1.1 times the maximum
objective function value found in all algorithms and all optimization runs";
:func:`reference_point` implements it. The paper's own points for the two
desired poses are in :data:`EOSMA_TABLE8_REF_POINTS`.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from moik.exceptions import NonFiniteError, ParameterError, ShapeError

EOSMA_TABLE8_REF_POINTS: dict[str, tuple[float, float]] = {
    "P1": (2.088567, 2.466816),
    "P2": (1.695669, 2.524178),
}
"""Reference points of the EOSMA paper's Table 8 (P1 unreachable, P2 reachable pose)."""


def _finite(name: str, arr: np.ndarray) -> np.ndarray:
    if not np.all(np.isfinite(arr)):
        raise NonFiniteError(f"{name} must hold finite values only; got {arr[~np.isfinite(arr)]}")
    return arr


def _front(name: str, F: object) -> np.ndarray:
    arr = np.asarray(F, dtype=float)
    if arr.ndim != 2 or arr.shape[1] == 0:
        raise ShapeError(
            f"{name} must be a 2-D array (n_points, n_obj) with n_obj >= 1; got shape {arr.shape}"
        )
    return _finite(name, arr)


def hypervolume(F: object, ref_point: object) -> float:
    """Hypervolume of the front ``F`` (minimized) with respect to ``ref_point``.

    Args:
        F: Objective values, shape (n_points, n_obj); may have 0 rows.
        ref_point: Reference point, shape (n_obj,).

    Returns:
        The hypervolume; points with any objective >= the reference value add
        nothing, and an empty front gives 0.0.

    Raises:
        ShapeError: If ``F`` is not 2-D or ``ref_point`` does not have n_obj
            entries.
        NonFiniteError: If either holds NaN or infinite values.

    Example:
        >>> hypervolume([[1.0, 1.0], [0.5, 1.5]], [2.0, 2.0])
        1.25
    """
    F = _front("F", F)
    ref = np.asarray(ref_point, dtype=float)
    if ref.shape != (F.shape[1],):
        raise ShapeError(
            f"ref_point must have shape ({F.shape[1]},) to match F {F.shape}; got {ref.shape}"
        )
    _finite("ref_point", ref)
    if F.shape[0] == 0:
        return 0.0
    from pymoo.indicators.hv import HV  # at the first use: the solver imports this package

    return float(HV(ref_point=ref)(F))


def reference_point(fronts: Iterable[object], *, factor: float = 1.1) -> np.ndarray:
    """Reference point ``factor`` x the per-objective maximum over all fronts.

    This is the EOSMA paper's policy (Table 8): pool the fronts of every
    algorithm and run of one experiment and take 1.1 times the largest value of
    each objective. It suits non-negative objectives such as IK errors.

    Args:
        fronts: Arrays of shape (n_points_i, n_obj); empty ones are skipped.
        factor: Multiplier of the maxima, >= 1 (the paper: 1.1).

    Returns:
        Array of shape (n_obj,).

    Raises:
        ParameterError: If ``factor`` < 1, no front has a point, or a maximum
            is <= 0 (then ``factor * max`` would not lie beyond the front; pass
            an explicit reference point instead).
        ShapeError: If the fronts are not 2-D or disagree in n_obj.
        NonFiniteError: If a front holds NaN or infinite values.
    """
    real = isinstance(factor, (int, float, np.integer, np.floating))
    if isinstance(factor, bool) or not real or not np.isfinite(factor) or factor < 1:
        raise ParameterError(f"factor must be a finite number >= 1; got {factor!r}")
    arrays = [_front(f"fronts[{i}]", F) for i, F in enumerate(fronts)]
    widths = {a.shape[1] for a in arrays}
    if len(widths) > 1:
        raise ShapeError(f"all fronts must have the same n_obj; got {sorted(widths)}")
    points = [a for a in arrays if a.shape[0] > 0]
    if not points:
        raise ParameterError("reference_point needs at least one front with at least one point")
    fmax = np.max(np.concatenate(points), axis=0)
    if np.any(fmax <= 0):
        raise ParameterError(
            f"the maximum of every objective must be > 0 for the factor policy; got {fmax}; "
            "pass an explicit ref_point to hypervolume() instead"
        )
    return factor * fmax
