"""Batched forward kinematics speed: moik's kernel vs the straightforward version.

Prints ns per FK for the EOSMA 7-DOF arm at batch 100 and 10,000, side by side
with a straightforward per-joint 4x4 matmul implementation of the same robot
(``moik.robots.fk_reference``), their ratio, and the largest difference.
Goal (issue 2): at most 350 ns per FK at batch 100 (the straightforward
version measures about 700 ns on the 2-core development machine).

Run: python benchmarks/fk.py
"""

from __future__ import annotations

import timeit

import numpy as np

from moik.robots import fk_reference, get_robot


def ns_per_fk(fn, Q: np.ndarray, budget_s: float = 0.5) -> float:
    """Best-of-7 time per FK in nanoseconds."""
    number = max(1, int(budget_s / 7 / max(timeit.timeit(lambda: fn(Q), number=1), 1e-7)))
    best = min(timeit.repeat(lambda: fn(Q), number=number, repeat=7)) / number
    return best / Q.shape[0] * 1e9


def main() -> None:
    robot = get_robot("eosma7")
    rng = np.random.default_rng(0)
    print(f"robot {robot.name}: {robot.dof} DOF; ns per FK (best of 7)")
    print(f"{'batch':>7} {'moik fk':>10} {'fk_position':>12} {'reference':>10} {'ratio':>7} "
          f"{'max |diff|':>11}")
    for n in (100, 10_000):
        Q = robot.random_q(n, rng=rng)
        fast = ns_per_fk(robot.fk, Q)
        pos = ns_per_fk(robot.fk_position, Q)
        ref = ns_per_fk(lambda Q: fk_reference(robot, Q), Q)
        diff = np.abs(robot.fk(Q) - fk_reference(robot, Q)).max()
        print(f"{n:>7} {fast:>10.0f} {pos:>12.0f} {ref:>10.0f} {ref / fast:>6.2f}x {diff:>11.1e}")


if __name__ == "__main__":
    main()
