"""Results as data: the trials of a results folder as records or a pandas DataFrame.

>>> from moik.experiments import load_results
>>> trials = load_results("results/eosma-table5-quick")            # doctest: +SKIP
>>> trials[0]["algorithm"], trials[0]["best_f"], trials[0]["convergence"].shape  # doctest: +SKIP
>>> frame = load_results("results/eosma-table5-quick", as_frame=True)  # doctest: +SKIP
>>> frame.groupby("algorithm")["best_f"].median()                  # doctest: +SKIP

pandas is optional (not a dependency of moik): it is imported only for
``as_frame=True``.
"""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

import numpy as np

from moik._validate import flag
from moik.exceptions import ParameterError
from moik.experiments.store import ResultStore


def load_results(folder: str | Path, *, as_frame: bool = False, arrays: bool = True):
    """The stored trials of a results folder, one record per trial.

    Each record is a dict of what the trial stored in ``results.jsonl`` (its id,
    ``algorithm``, ``target`` index, ``run``, ``seed``, ``status``, ``time``,
    ``best_f``, errors, ...; lists such as ``best_x`` become numpy arrays), plus
    ``experiment`` and ``target_name``, plus (with ``arrays``) every array of its
    ``.npz`` by name (``convergence``, ``best_x``, ``front_F``, ``front_X`` ...).
    Failed trials are included (``status="error"``, no arrays). Trials whose
    arrays are damaged or missing are left out with a warning (``moik
    experiment run ... --resume`` runs them again).

    Args:
        folder: A results folder (``moik experiment run ... --out folder``).
        as_frame: Return a ``pandas.DataFrame`` (one row per trial; array cells
            hold numpy arrays) instead of the list.
        arrays: Load each trial's arrays (False: the scalars alone, faster).

    Returns:
        ``list[dict]`` in the file's order, or a ``pandas.DataFrame``.

    Raises:
        ResultsError: If ``folder`` is not a results folder.
        ParameterError: If ``as_frame=True`` and pandas is not installed.
    """
    as_frame, arrays = flag("as_frame", as_frame), flag("arrays", arrays)
    pandas = _pandas() if as_frame else None
    store = ResultStore.open(folder, verify=arrays)
    if store.damaged:
        warnings.warn(f"{store.folder}: {len(store.damaged)} trial(s) left out, their arrays "
                      "are damaged or missing: " + "; ".join(store.damaged.values()),
                      stacklevel=2)
    names = [t.get("name") for t in store.meta.get("targets", [])]
    rows = []
    for rec in store.records():
        row: dict[str, Any] = {"experiment": store.meta.get("experiment")}
        row.update({k: _as_array(v) for k, v in rec.items()})
        index = rec.get("target")
        row["target_name"] = names[index] if isinstance(index, int) and 0 <= index < len(
            names) else None
        if arrays and rec.get("has_arrays"):
            row.update(store.load_arrays(rec["trial"]))
        rows.append(row)
    return pandas.DataFrame(rows) if pandas is not None else rows


def _as_array(value):
    """A stored list of numbers (None: non-finite) as a numpy array; anything else as it is."""
    if not isinstance(value, list) or not value:
        return value
    try:
        arr = np.asarray(value)
        if arr.dtype.kind == "O" and any(v is None for v in arr.ravel()):
            arr = np.asarray(value, dtype=float)  # None is how a non-finite float is stored
    except (ValueError, TypeError, OverflowError):
        return value
    return arr if arr.dtype.kind in "iuf" else value


def _pandas():
    """The pandas module, or a clear error that it is missing."""
    try:
        import pandas
    except ImportError:
        raise ParameterError("load_results(..., as_frame=True) needs pandas, which is not "
                             "installed: pip install pandas (or use the list of records)"
                             ) from None
    return pandas
