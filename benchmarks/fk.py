"""Forward kinematics speed: moik's compiled kernels vs a straightforward numpy chain.

Prints, side by side in one process, nanoseconds per FK (the full 4x4 pose,
``robot.fk``, validation included) at batch 1, 100 and 10,000 for the EOSMA 7-DOF
arm, the Puma 560, an iiwa-like 7-DOF arm and a UR5-like URDF chain, against the
straightforward batched numpy DH / 4x4 chain (``moik.robots.fk_reference``), with
their ratio (goal: at least 5x at batch 100) and the largest difference; then the
fused ``PoseIK`` objective (FK + orientation metric in one compiled call) per
population of 100 against the numpy path (``fk_reference`` + the metric's numpy
function). Each cell is the median of interleaved repeats (moik, numpy, moik, ...),
so load on the machine hits both sides alike.

Run: python benchmarks/fk.py [--out FILE] (``--out`` also writes the printed table to
FILE, e.g. docs/results/fk.txt, which docs/performance.md links to).
"""

from __future__ import annotations

import argparse
import os
import tempfile
import timeit
from pathlib import Path

import numba
import numpy as np
from _output import OUT_HELP, table_output

import moik
from moik.kinematics.orientation import orientation_metric
from moik.problems import PoseIK, random_reachable_targets
from moik.robots import Robot, fk_kernels, fk_reference, get_robot
from moik.robots.urdf import load_urdf

REPEATS = 7
CELL_SECONDS = 0.02  # time of one measurement (several calls)

_UR5_LIKE = """<robot name="ur5-like">
  <link name="base"/><link name="shoulder"/><link name="upper_arm"/><link name="forearm"/>
  <link name="wrist_1"/><link name="wrist_2"/><link name="wrist_3"/><link name="tool0"/>
  {joints}
</robot>"""
_UR5_JOINTS = [  # (parent, child, xyz, rpy, axis), UR5 link lengths in metres
    ("base", "shoulder", "0 0 0.089159", "0 0 0", "0 0 1"),
    ("shoulder", "upper_arm", "0 0.13585 0", "0 1.570796325 0", "0 1 0"),
    ("upper_arm", "forearm", "0 -0.1197 0.425", "0 0 0", "0 1 0"),
    ("forearm", "wrist_1", "0 0 0.39225", "0 1.570796325 0", "0 1 0"),
    ("wrist_1", "wrist_2", "0 0.093 0", "0 0 0", "0 0 1"),
    ("wrist_2", "wrist_3", "0 0 0.09465", "0 0 0", "0 1 0"),
]


def ur5_like() -> Robot:
    """A UR5-like chain loaded from URDF text (rpy origins, y axes, a fixed tool joint)."""
    joints = [f'<joint name="{c}_joint" type="revolute"><parent link="{p}"/><child link="{c}"/>'
              f'<origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="{axis}"/>'
              '<limit lower="-6.28" upper="6.28" effort="1" velocity="1"/></joint>'
              for p, c, xyz, rpy, axis in _UR5_JOINTS]
    joints.append('<joint name="tool" type="fixed"><parent link="wrist_3"/><child link="tool0"/>'
                  '<origin xyz="0 0.0823 0" rpy="0 0 1.570796325"/></joint>')
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "ur5_like.urdf"
        path.write_text(_UR5_LIKE.format(joints="\n  ".join(joints)))
        return load_urdf(path)


def iiwa_like() -> Robot:
    """A 7-DOF arm with the KUKA LBR iiwa 14 R820 geometry as standard DH rows."""
    half = np.pi / 2
    return Robot(name="iiwa-like", a=np.zeros(7), alpha=[-half, half, half, -half, -half, half, 0],
                 d=[0.36, 0, 0.42, 0, 0.4, 0, 0.126], theta=np.zeros(7),
                 lower=-np.radians([170, 120, 170, 120, 170, 120, 175]),
                 upper=np.radians([170, 120, 170, 120, 170, 120, 175]))


def _calls_per_cell(fn) -> int:
    once = timeit.timeit(fn, number=1)
    return max(1, int(CELL_SECONDS / max(once, 1e-7)))


def interleaved_medians(fns) -> list[float]:
    """Median seconds per call of each function, measured in interleaved repeats."""
    for fn in fns:
        fn()  # compile / warm up
    numbers = [_calls_per_cell(fn) for fn in fns]
    times: list[list[float]] = [[] for _ in fns]
    for _ in range(REPEATS):
        for k, fn in enumerate(fns):
            times[k].append(timeit.timeit(fn, number=numbers[k]) / numbers[k])
    return [float(np.median(t)) for t in times]


def _kernel_call(robot: Robot, Q: np.ndarray):
    """The compiled FK kernel alone (no validation, output allocated once): the floor."""
    chain, out = robot.kinematic_chain, np.empty((len(Q), 4, 4))
    return lambda: fk_kernels.fk_poses(chain.origins, chain.joint_types, Q, out)


def fk_table(robots: list[Robot]) -> None:
    print("moik: robot.fk (validation included); kernel: the compiled kernel alone; fk/kernel: "
          "their ratio; ratio: numpy / moik")
    print(f"{'robot':<12} {'batch':>7} {'moik ns/FK':>11} {'kernel ns/FK':>13} "
          f"{'fk/kernel':>10} {'numpy ns/FK':>12} {'ratio':>7} {'max |diff| / reach':>19}")
    for robot in robots:
        for n in (1, 100, 10_000):
            Q = robot.random_q(n, rng=np.random.default_rng(n))
            fast, kernel, ref = interleaved_medians([lambda Q=Q, r=robot: r.fk(Q),
                                                     _kernel_call(robot, Q),
                                                     lambda Q=Q, r=robot: fk_reference(r, Q)])
            diff = np.abs(robot.fk(Q) - fk_reference(robot, Q)).max() / max(1.0, robot.reach)
            print(f"{robot.name:<12} {n:>7} {fast / n * 1e9:>11.1f} {kernel / n * 1e9:>13.1f} "
                  f"{fast / kernel:>9.2f}x {ref / n * 1e9:>12.1f} {ref / fast:>6.1f}x "
                  f"{diff:>19.1e}")


def numpy_pose_objective(problem: PoseIK, X: np.ndarray) -> np.ndarray:
    """The same objective the plain-numpy way: fk_reference, then the metric's numpy function."""
    T = fk_reference(problem.robot, X)
    target_repr, error = orientation_metric(problem.orientation)
    pos = np.linalg.norm(T[:, :3, 3] - problem.target.position, axis=1)
    ori = error(T[:, :3, :3], target_repr(problem.target.rotation))
    return (problem.weights[0] * pos + problem.weights[1] * ori)[:, None]


def objective_table() -> None:
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=0)[0]
    X = robot.random_q(100, rng=np.random.default_rng(0))
    print(f"\nfused PoseIK objective, {robot.name}, population of 100 (us per population)")
    print(f"{'metric':<22} {'moik us':>8} {'numpy us':>9} {'ratio':>7} {'max |diff|':>11}")
    for metric in ("geodesic", "eosma-euler", "frobenius", "zyx-euler"):
        problem = PoseIK(robot, target, orientation=metric)
        fast, ref = interleaved_medians([lambda p=problem: p.evaluate(X),
                                         lambda p=problem: numpy_pose_objective(p, X)])
        diff = np.abs(problem.evaluate(X) - numpy_pose_objective(problem, X)).max()
        print(f"{metric:<22} {fast * 1e6:>8.1f} {ref * 1e6:>9.1f} {ref / fast:>6.1f}x "
              f"{diff:>11.1e}")


def _where(package: Path) -> str:
    """The moik measured: this repository's (no path of the machine in a stored table)
    or an installed one."""
    here = Path(__file__).resolve().parents[1]
    return "this repository" if package.resolve().parent == here else "an installed copy"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", help=OUT_HELP)
    args = parser.parse_args()
    with table_output(args.out):
        load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
        print(f"numpy {np.__version__}, numba {numba.__version__}, {os.cpu_count()} CPUs, "
              f"load average {load:.2f}; medians of {REPEATS} interleaved repeats; "
              f"moik from {_where(Path(moik.__file__).parent)}\n")
        fk_table([get_robot("eosma7"), get_robot("puma560"), iiwa_like(), ur5_like()])
        objective_table()


if __name__ == "__main__":
    main()
