"""``moik batch ROBOT TARGETS --out RESULT``: inverse kinematics of a file of targets.

Targets: a ``.npy`` file of poses ``(n, 4, 4)`` or positions ``(n, 3)``, or a CSV file
with one target per line, ``x, y, z`` (a position) or ``x, y, z, roll, pitch, yaw`` (a
pose: ``R = Rz(yaw) Ry(pitch) Rx(roll)``, radians, degrees with ``--deg``), commas or
blanks between the numbers, an optional header line, ``#`` comments. Lengths are in
the robot's unit.

Results (:func:`~moik.solver.batch.solve_ik_batch`, ``--workers`` CPUs, default all):
``.npz`` with the arrays ``q (n, dof)``, ``status``, ``success``, ``position_error``,
``orientation_error`` (geodesic, rad), ``n_eval`` and, with ``--scene`` or
``--self-collision``, ``min_distance``; or ``.csv`` with one line per target: the joint
values (named by the joints), ``status``, the errors and ``min_distance``. A progress
bar on stderr for batches of :data:`PROGRESS_MIN` targets or more (tqdm), then one
summary line. Exit status as ``moik solve``: 0 every target solved, 1 some not, 2 bad
input (a file that cannot be read, of the wrong shape, with NaN, a non-rotation, no
target) with one line on stderr.
"""

from __future__ import annotations

import argparse
import csv
import io
import sys
from pathlib import Path

import numpy as np

from moik._paths import atomic_write_bytes
from moik._validate import integer
from moik.cli import collision
from moik.cli.common import SOLVE_OPTIONS, library_call, robot, tolerance
from moik.cli.parser import given
from moik.exceptions import NonFiniteError, ParameterError, ShapeError, TargetError
from moik.kinematics.orientation import ROTATION_ATOL, rotation_from_zyx
from moik.robots import Robot
from moik.solver import solve_ik_batch
from moik.solver.parallel import chunk_bounds, worker_count

PROGRESS_MIN = 1000  # targets from which the progress bar is shown
RESULT_FORMATS = (".npz", ".csv")
TARGET_FORMATS = (".npy", ".csv")


def read_targets(path: str, *, degrees: bool = False) -> np.ndarray:
    """The targets of ``path``: ``(n, 4, 4)`` poses or ``(n, 3)`` positions (not yet
    validated as rotations: :func:`~moik.solver.batch.solve_ik_batch` does).

    Raises:
        ParameterError: Not a ``.npy`` or ``.csv`` file, or unreadable.
        ShapeError: No target, or rows of the wrong length.
        NonFiniteError: NaN or inf.
    """
    file = Path(path)
    suffix = file.suffix.lower()
    if suffix not in TARGET_FORMATS:
        raise ParameterError(f"targets file must end in {' or '.join(TARGET_FORMATS)}, got "
                             f"{path!r}")
    if not file.is_file():
        raise ParameterError(f"targets file {path!r} does not exist or is not a file")
    arr = _read_npy(file) if suffix == ".npy" else _read_csv(file, degrees)
    if arr.size == 0:
        raise ShapeError(f"targets file {path!r} holds no target")
    if not np.all(np.isfinite(arr)):
        row = int(np.flatnonzero(~np.isfinite(arr.reshape(len(arr), -1)).all(axis=1))[0]) \
            if arr.ndim > 1 else 0
        raise NonFiniteError(f"targets file {path!r}: target {row} holds NaN or inf")
    if arr.ndim == 3:
        _check_poses(arr, path)
    return arr


def _check_poses(T: np.ndarray, path: str) -> None:
    """The first pose of ``T`` that is not rigid, named (the solver's check, per row)."""
    R, eye = T[:, :3, :3], np.eye(3)
    gram = np.einsum("nka,nkb->nab", R, R)
    bad = (np.any(np.abs(gram - eye) > ROTATION_ATOL + 1e-5 * eye, axis=(1, 2))
           | (np.abs(np.linalg.det(R) - 1.0) > ROTATION_ATOL + 1e-5))
    if bad.any():
        raise TargetError(f"targets file {path!r}: target {int(np.flatnonzero(bad)[0])} is not "
                          "a pose: its rotation is not orthonormal with det +1")
    last = np.any(np.abs(T[:, 3] - (0.0, 0.0, 0.0, 1.0)) > 1e-8, axis=1)
    if last.any():
        raise TargetError(f"targets file {path!r}: target {int(np.flatnonzero(last)[0])} is not "
                          "a pose: its last row must be [0, 0, 0, 1]")


def _read_npy(file: Path) -> np.ndarray:
    try:
        arr = np.load(file, allow_pickle=False)
    except (ValueError, OSError, EOFError):
        raise ParameterError(f"cannot read targets file {str(file)!r}: not a numpy .npy file "
                             "of numbers") from None
    except MemoryError:  # a header declaring more than memory holds (damaged, or too large)
        raise ParameterError(f"cannot read targets file {str(file)!r}: the array its header "
                             "declares does not fit in memory (a damaged file, or split the "
                             "targets into several files)") from None
    if not isinstance(arr, np.ndarray) or arr.dtype.kind not in "iuf":
        raise ParameterError(f"targets file {str(file)!r} must hold a real array, got "
                             f"{getattr(arr, 'dtype', type(arr).__name__)}")
    try:
        arr = arr.astype(np.float64)
    except MemoryError:
        raise ParameterError(f"targets file {str(file)!r} is too large to convert to float64 "
                             "in memory: split the targets into several files") from None
    if arr.size and not ((arr.ndim == 3 and arr.shape[1:] == (4, 4))
                         or (arr.ndim == 2 and arr.shape[1] == 3)):
        raise ShapeError(f"targets file {str(file)!r} must hold poses (n, 4, 4) or positions "
                         f"(n, 3), got shape {arr.shape}")
    return arr


def _read_csv(file: Path, degrees: bool) -> np.ndarray:
    try:
        text = file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise ParameterError(f"cannot read targets file {str(file)!r}: {exc}") from None
    rows: list[list[float]] = []
    for number, line in enumerate(text.removeprefix("\ufeff").splitlines(), start=1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        fields = _fields(line)
        if "" in fields:
            raise ShapeError(f"targets file {str(file)!r} line {number}: an empty field in "
                             f"{line!r}")
        try:
            if any("_" in f for f in fields):  # float() reads '1_0' as 10
                raise ValueError
            values = [float(f) for f in fields]
        except ValueError:
            if not rows and all(f.strip("\"'").replace("_", "").isalpha() for f in fields):
                continue  # a header line
            raise ParameterError(f"targets file {str(file)!r} line {number}: expected numbers "
                                 f"(x y z [roll pitch yaw]), got {line!r}") from None
        if len(values) not in (3, 6) or (rows and len(values) != len(rows[0])):
            want = f"{len(rows[0])}" if rows else "3 (x y z) or 6 (x y z roll pitch yaw)"
            raise ShapeError(f"targets file {str(file)!r} line {number}: expected {want} "
                             f"numbers, got {len(values)}")
        rows.append(values)
    if not rows:
        return np.zeros((0, 3))  # refused by read_targets: no target
    arr = np.array(rows, dtype=np.float64)
    if arr.shape[1] == 3:
        return arr
    finite = np.isfinite(arr).all(axis=1)
    if not finite.all():
        raise NonFiniteError(f"targets file {str(file)!r}: target "
                             f"{int(np.flatnonzero(~finite)[0])} holds NaN or inf")
    if not degrees and (np.abs(arr[:, 3:]) > 2 * np.pi + 1e-9).any():
        row = int(np.flatnonzero((np.abs(arr[:, 3:]) > 2 * np.pi + 1e-9).any(axis=1))[0])
        raise TargetError(f"targets file {str(file)!r}: target {row} has angles "
                          f"{arr[row, 3:].tolist()} beyond 2 pi in magnitude; they are "
                          "radians: add --deg to give degrees")
    angles = np.radians(arr[:, 3:]) if degrees else arr[:, 3:]
    poses = np.tile(np.eye(4), (len(arr), 1, 1))
    poses[:, :3, 3] = arr[:, :3]
    poses[:, :3, :3] = [rotation_from_zyx(y, p, r) for r, p, y in angles]
    return poses


def _fields(line: str) -> list[str]:
    """A CSV line's fields: comma-separated (one trailing comma allowed), else blank-separated."""
    if "," not in line:
        return line.split()
    fields = [f.strip() for f in line.split(",")]
    return fields[:-1] if fields[-1] == "" and len(fields) > 1 else fields


def result_file(spec: str, targets: str | None = None) -> Path:
    """``--out``, checked before solving: ``.npz`` or ``.csv`` in an existing folder, a new
    name or a regular file (not a link, a folder, a FIFO or a device), not the targets
    file itself."""
    path = Path(spec)
    if path.suffix.lower() not in RESULT_FORMATS:
        raise ParameterError(f"--out must end in {' or '.join(RESULT_FORMATS)}, got {spec!r}")
    if not path.parent.is_dir():
        raise ParameterError(f"--out folder {str(path.parent)!r} does not exist (create it "
                             "first)")
    if path.is_symlink():
        raise ParameterError(f"--out {spec!r} is a symbolic link; moik does not write "
                             "through links: remove it or name another file")
    if path.exists() and not path.is_file():
        raise ParameterError(f"--out {spec!r} exists and is not a regular file (a folder, "
                             "FIFO or device): name a new file")
    if targets is not None and path.exists() and Path(targets).exists() \
            and path.samefile(targets):
        raise ParameterError(f"--out {spec!r} is the targets file: name another file")
    return path


def write_results(path: Path, arm: Robot, res) -> None:
    """The batch's answers into ``path`` (``.npz`` arrays or ``.csv`` lines)."""
    columns = {"status": res.status, "success": res.success,
               "position_error": res.position_error,
               "orientation_error": res.orientation_error, "n_eval": res.n_eval}
    if res.min_distance is not None:
        columns["min_distance"] = res.min_distance
    buffer = io.BytesIO()
    if path.suffix.lower() == ".npz":
        np.savez(buffer, q=res.q, **columns)
    else:
        names = list(arm.joint_names) or [f"q{j + 1}" for j in range(arm.dof)]
        text = io.StringIO(newline="")
        out = csv.writer(text)
        out.writerow(names + list(columns))
        for i in range(len(res.q)):
            out.writerow([repr(float(v)) for v in res.q[i]]
                         + [_cell(columns[c][i]) for c in columns])
        buffer.write(text.getvalue().encode("utf-8"))
    # a new file beside it, then renamed: never through a link planted since the check,
    # and a file interrupted mid-write never takes the result's name
    atomic_write_bytes(path, buffer.getvalue())


def _cell(value) -> str:
    if isinstance(value, np.floating | float):
        return repr(float(value))
    if isinstance(value, np.bool_ | bool):
        return str(bool(value)).lower()
    return str(value)


class _Bar:
    """Targets answered so far: a tqdm bar on stderr (tqdm is a dependency; without it,
    nothing)."""

    def __init__(self, total: int, enabled: bool) -> None:
        self._bar = None
        if enabled:
            try:
                from tqdm import tqdm
            except ImportError:  # optional, as for `moik experiment run`
                return
            self._bar = tqdm(total=total, unit="target", file=sys.stderr, desc="moik batch")

    def __call__(self, k: int) -> None:
        if self._bar is not None:
            self._bar.update(min(k, int(self._bar.total or 0) - self._bar.n))

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()


def summary(res, n_workers: int, unit: str, path: Path) -> str:
    """One line: how many solved, the other statuses, time and rate with the workers that
    ran (one for a batch of one chunk), the largest errors, the links left unchecked."""
    n = len(res.status)
    statuses, counts = np.unique(res.status, return_counts=True)
    others = ", ".join(f"{c} {s}" for s, c in zip(statuses, counts, strict=True)
                       if s != "solved")
    solved = int(res.success.sum())
    line = (f"{solved}/{n} solved{f' ({others})' if others else ''} in {res.time:.2f} s "
            f"({solved / res.time:.0f} solutions/s, {n_workers} "
            f"{'worker' if n_workers == 1 else 'workers'})")
    if solved:
        pos = res.position_error[res.success].max()
        ori = res.orientation_error[res.success].max()
        line += f"; largest errors of the solved: position {pos:.3g} {unit}, orientation " \
                f"{ori:.3g} rad"
    if getattr(res, "unchecked_links", ()):
        line += f"; not checked (no collision geometry): {', '.join(res.unchecked_links)}"
    return f"{line}; written to {path}"


def cmd_batch(args: argparse.Namespace) -> int:
    """Solve every target of the file, write the results, print the summary; 0 when every
    target is solved, 1 otherwise."""
    search = given(args, "seed", "tol")
    if "seed" in search:
        integer("--seed", search["seed"], minimum=0)
    if "tol" in search:
        search["tol"] = tolerance(search["tol"])
    out = result_file(args.out, args.targets)
    arm = robot(args)
    targets = read_targets(args.targets, degrees=args.deg)
    if args.deg and (targets.ndim == 2 or args.targets.lower().endswith(".npy")):
        raise ParameterError("--deg applies to the angles of a CSV of poses (x y z roll pitch "
                             "yaw); these targets have none")
    check = collision.checker(args, arm)
    bar = _Bar(len(targets), not args.no_progress and len(targets) >= PROGRESS_MIN)
    try:
        with library_call({**SOLVE_OPTIONS, "workers": "--workers"}):
            res = solve_ik_batch(arm, targets, workers=args.workers, progress=bar, **search,
                                 **collision.solver_options(check))
    finally:
        bar.close()
    write_results(out, arm, res)
    workers = worker_count(args.workers)
    print(summary(res, min(workers, len(chunk_bounds(len(targets), workers))), arm.unit, out))
    return 0 if bool(res.success.all()) else 1
